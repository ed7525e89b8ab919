//! Light sampling and the naive soft shadows estimate the same light with very
//! different noise. With one bounce, the naive stage sees the sphere light only
//! when an indirect ray hits it; with no bounce, the light-sampling stage aims at
//! it directly. Both estimate the direct light on the floor: they must agree in mean,
//! and light sampling must be several times more accurate at equal samples.

use raycourse::integrator::Tracer;
use raycourse::maths::Real;
use raycourse::{Overrides, Scene, find_stage};

use raycourse::render::samples::pixel_samples;

const SIZE: u32 = 64;
/// A 6 x 6 patch of the floor, right of the sphere, lit by the light.
const ROWS: std::ops::Range<u32> = 46..52;
const COLUMNS: std::ops::Range<u32> = 38..44;

fn scene(name: &str, bounces: u32, samples: u32) -> Scene {
    find_stage(4, name)
        .unwrap()
        .scene(&Overrides {
            bounces: Some(bounces),
            seed: Some(5),
            ..Overrides::sized(SIZE, SIZE, samples)
        })
        .unwrap()
}

/// The samples of each pixel of the patch (sum of the three channels).
fn patch(scene: &Scene) -> Vec<Vec<Real>> {
    let mut tracer = Tracer::new(scene);
    let mut pixels = Vec::new();
    for row in ROWS {
        for column in COLUMNS {
            let samples = pixel_samples(&mut tracer, row, column);
            pixels.push(samples.map(|c| c.element_sum()).collect());
        }
    }
    pixels
}

fn mean(values: &[Real]) -> Real {
    values.iter().sum::<Real>() / values.len() as Real
}

/// Mean of all the samples and its standard error.
fn mean_and_error(pixels: &[Vec<Real>]) -> (Real, Real) {
    let all: Vec<Real> = pixels.iter().flatten().copied().collect();
    let m = mean(&all);
    let variance = all.iter().map(|v| (v - m).powi(2)).sum::<Real>() / (all.len() - 1) as Real;
    (m, (variance / all.len() as Real).sqrt())
}

/// Root mean square error of the pixel means against the reference's.
fn rmse(pixels: &[Vec<Real>], reference: &[Vec<Real>]) -> Real {
    let squares: Vec<Real> = pixels
        .iter()
        .zip(reference)
        .map(|(p, r)| (mean(p) - mean(r)).powi(2))
        .collect();
    mean(&squares).sqrt()
}

#[test]
fn same_mean_far_less_noise() {
    let naive = patch(&scene("soft-shadows", 1, 256));
    let sampled = patch(&scene("light-sampling", 0, 256));
    let (naive_mean, naive_error) = mean_and_error(&naive);
    let (sampled_mean, sampled_error) = mean_and_error(&sampled);
    let both = naive_error.hypot(sampled_error);
    assert!(
        (naive_mean - sampled_mean).abs() <= 3.0 * both,
        "naive {naive_mean} +- {naive_error}, sampled {sampled_mean} +- {sampled_error}"
    );
    assert!(sampled_mean > 0.0, "the patch is lit");

    let reference = patch(&scene("light-sampling", 0, 4096));
    let (naive_rmse, sampled_rmse) = (rmse(&naive, &reference), rmse(&sampled, &reference));
    eprintln!("RMSE at 256 samples: naive {naive_rmse:.4e}, light sampling {sampled_rmse:.4e}");
    assert!(
        naive_rmse > 4.0 * sampled_rmse,
        "naive {naive_rmse}, light sampling {sampled_rmse}"
    );
}
