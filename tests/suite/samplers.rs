//! The samplers beyond the course (stratified numbers, Sobol points) and adaptive
//! sampling: each number is uniform over many pixels, the images they give have the
//! same mean as the course's independent numbers with less noise, they do not
//! depend on the thread count, and an adaptive pixel stops where it should.

use raycourse::integrator::Tracer;
use raycourse::maths::{Real, uniform, uniform_pair};
use raycourse::samplers::adaptive::Estimate;
use raycourse::samplers::pixel::{pixel_samples, sampler_rng, start_sample};
use raycourse::scene::beyond::{Beyond, Sampler};
use raycourse::scene_file::beyond::{BeyondOverrides, parse_with_beyond};
use raycourse::{Disk, Overrides, Render, Scene, find_stage};
use statrs::distribution::{ChiSquared, ContinuousCDF};

/// The chi-square p-value of `points` of the unit square against the uniform
/// density, on a grid of `cells x cells`.
fn uniform_p_value(points: &[(Real, Real)], cells: usize) -> f64 {
    let mut counts = vec![0.0; cells * cells];
    for &(x, y) in points {
        counts[(y * cells as Real) as usize * cells + (x * cells as Real) as usize] += 1.0;
    }
    let expected = points.len() as f64 / counts.len() as f64;
    let statistic: f64 = counts
        .iter()
        .map(|o| (o - expected).powi(2) / expected)
        .sum();
    ChiSquared::new((counts.len() - 1) as f64)
        .unwrap()
        .sf(statistic)
}

/// Pair number `dimension` of every sample of 4096 pixels, 16 samples each.
fn pairs_of_many_pixels(
    sampler: Sampler,
    dimension: u32,
    warp: fn(Real) -> Real,
) -> Vec<(Real, Real)> {
    let mut points = vec![];
    for pixel in 0..4096 {
        let mut rng = sampler_rng(sampler, 9, pixel, 16);
        for sample in 0..16 {
            start_sample(&mut rng, sample);
            for _ in 0..dimension {
                uniform(&mut rng);
            }
            let (x, y) = uniform_pair(&mut rng);
            points.push((warp(x), y));
        }
    }
    points
}

#[test]
fn every_sampler_is_uniform_over_many_pixels() {
    for sampler in [Sampler::Independent, Sampler::Stratified, Sampler::Sobol] {
        for dimension in [0, 1, 5] {
            let p = uniform_p_value(&pairs_of_many_pixels(sampler, dimension, |x| x), 32);
            assert!(p >= 0.01, "{sampler:?}, dimension {dimension}: p = {p:.3e}");
        }
        // A test that cannot fail proves nothing: squaring x must be caught.
        let p = uniform_p_value(&pairs_of_many_pixels(sampler, 0, |x| x * x), 32);
        assert!(
            p < 1e-6,
            "{sampler:?}: the squared numbers pass, p = {p:.3e}"
        );
    }
}

/// A stage of session 4 at 48 x 48 with `edits` to its `[render]` table.
fn stage(name: &str, samples: u32, seed: u64, render_keys: &str) -> (Scene, Beyond) {
    let stage = find_stage(4, name).unwrap();
    let source = stage
        .source
        .replace("[render]", &format!("[render]\n{render_keys}"));
    let overrides = Overrides {
        seed: Some(seed),
        ..Overrides::sized(48, 48, samples)
    };
    let beyond = BeyondOverrides::default();
    parse_with_beyond(&source, &stage.file(), &overrides, &beyond, &Disk).unwrap()
}

/// `job`'s scene rendered with its settings beyond the course.
fn render(job: &(Scene, Beyond)) -> Render {
    raycourse::engines::render(&job.0, &job.1)
}

/// The mean of each colour channel's sum over the image, and the image's squared
/// error against `reference`, both per pixel.
fn mean_and_error(image: &Render, reference: &Render) -> (Real, Real) {
    let pixels = image.film.pixels.iter().zip(&reference.film.pixels);
    let n = image.film.pixels.len() as Real;
    let mean = image
        .film
        .pixels
        .iter()
        .map(|c| c.element_sum())
        .sum::<Real>()
        / n;
    let squared = pixels
        .map(|(a, b)| (*a - *b).length_squared())
        .sum::<Real>()
        / n;
    (mean, squared)
}

#[test]
fn sobol_and_stratified_images_keep_the_mean_and_lose_noise() {
    let reference = render(&stage("light-sampling", 1024, 99, ""));
    let (truth, _) = mean_and_error(&reference, &reference);
    let mut errors = vec![];
    for sampler in ["independent", "stratified", "sobol"] {
        let image = render(&stage(
            "light-sampling",
            16,
            1,
            &format!("sampler = \"{sampler}\""),
        ));
        let (mean, squared) = mean_and_error(&image, &reference);
        eprintln!("{sampler}: mean {mean:.4e} (reference {truth:.4e}), MSE {squared:.4e}");
        assert!(
            (mean - truth).abs() < 0.02 * truth,
            "{sampler}: {mean} against {truth}"
        );
        errors.push(squared);
    }
    assert!(
        errors[1] < errors[0],
        "stratified {} >= independent {}",
        errors[1],
        errors[0]
    );
    assert!(
        errors[2] < 0.8 * errors[0],
        "sobol {} against independent {}",
        errors[2],
        errors[0]
    );
}

#[test]
fn sobol_images_do_not_depend_on_the_thread_count() {
    let scene = stage("depth-of-field", 8, 3, "sampler = \"sobol\"\nnoise = 0.05");
    let on = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| render(&scene))
    };
    let (one, three) = (on(1), on(3));
    assert_eq!(one.film, three.film);
    assert_eq!(one.samples, three.samples);
}

#[test]
fn an_adaptive_pixel_stops_when_its_mean_is_precise_and_not_before() {
    let scene = stage("light-sampling", 16, 2, "noise = 0.05");
    let taken = render(&scene).samples;
    // Batches of 4 samples, at most 4 x 16.
    assert!(
        taken.iter().all(|&n| n % 4 == 0 && (4..=64).contains(&n)),
        "{taken:?}"
    );
    assert!(taken.iter().any(|&n| n < 64) && taken.contains(&64));
    // Replay one pixel that stopped early: before its stop, no batch was precise
    // enough; at the stop, the batch was.
    let pixel = taken
        .iter()
        .position(|&n| n > 4 && n < 64)
        .expect("a pixel stopped early");
    let (row, column) = (pixel as u32 / 48, pixel as u32 % 48);
    let mut tracer = Tracer::new(&scene.0);
    let values: Vec<_> = pixel_samples(&mut tracer, &scene.1, row, column).collect();
    let mut estimate = Estimate::default();
    for (i, value) in values.iter().enumerate().take(taken[pixel] as usize) {
        estimate.add(*value);
        if (i + 1) % 4 == 0 {
            let stops = estimate.relative_error() <= 0.05;
            assert_eq!(
                stops,
                i + 1 == taken[pixel] as usize,
                "pixel {pixel} after {} samples",
                i + 1
            );
        }
    }
}
