//! Four paths at a time against the course's recursion: every stage the renderer
//! follows four paths at a time gives the same radiance, to the last bit, as with
//! `[render] recursive = true`, with the same counts of rays and samples.
#![cfg(feature = "s3")]

use std::num::NonZeroU32;

use raycourse::fast::paths_at_once;
use raycourse::maths::random::Sampler;
use raycourse::{Overrides, Render, Stage, render, stages};

/// Renders `stage` at 30 x 9 pixels (30 is not a multiple of four, so rows end
/// with fewer than four paths), at most `samples` samples per pixel, with the
/// stage's sampler or `sampler`.
fn small(
    stage: &Stage,
    samples: u32,
    extra: Overrides,
    sampler: Option<Sampler>,
) -> (Render, bool) {
    let overrides = Overrides {
        width: NonZeroU32::new(30),
        height: NonZeroU32::new(9),
        samples: NonZeroU32::new(samples),
        ..extra
    };
    let mut scene = stage.scene(&overrides).unwrap();
    if let Some(sampler) = sampler {
        scene.settings.sampling.sampler = sampler;
    }
    (render(&scene), paths_at_once::applies(&scene))
}

fn same(stage: &Stage, samples: u32, extra: Overrides, sampler: Option<Sampler>) -> bool {
    let (at_once, applies) = small(stage, samples, extra, sampler);
    let recursive = Overrides {
        recursive: true,
        ..extra
    };
    let (one_by_one, recursion_applies) = small(stage, samples, recursive, sampler);
    assert!(
        !recursion_applies,
        "{}: recursive = true is obeyed",
        stage.name
    );
    let bits = |r: &Render| -> Vec<_> {
        r.film
            .pixels
            .iter()
            .map(|c| c.to_array().map(|x| x.to_bits()))
            .collect()
    };
    let (a, b) = (bits(&at_once), bits(&one_by_one));
    let first = a.iter().zip(&b).position(|(a, b)| a != b);
    assert_eq!(first, None, "{}: first pixel that differs", stage.name);
    assert_eq!(at_once.rays, one_by_one.rays, "{}: rays", stage.name);
    assert_eq!(
        at_once.samples, one_by_one.samples,
        "{}: samples",
        stage.name
    );
    assert_eq!(
        at_once.dropped, one_by_one.dropped,
        "{}: dropped",
        stage.name
    );
    applies
}

/// The stages whose objects are all diffuse spheres, in the course's order.
const DIFFUSE_SPHERE_STAGES: [&str; 11] = [
    "white-disk",
    "shading",
    "spheres",
    "gamma",
    "shadows",
    "indirect",
    "antialiasing",
    "soft-shadows",
    "light-sampling",
    "depth-of-field",
    "russian-roulette",
];

#[test]
fn every_sphere_stage_gives_the_recursions_radiance_to_the_last_bit() {
    let compared: Vec<&str> = stages()
        .filter(|stage| same(stage, 8, Overrides::default(), None))
        .map(|stage| stage.name)
        .collect();
    // The mirror, glass and mesh stages take the recursion; the stages of later
    // sessions are absent from an earlier session's build.
    let expected: Vec<&str> = DIFFUSE_SPHERE_STAGES
        .into_iter()
        .filter(|name| stages().any(|stage| stage.name == *name))
        .collect();
    assert_eq!(compared, expected);
    assert!(compared.contains(&"indirect"));
}

#[test]
fn adaptive_sampling_stops_each_pixel_at_the_same_sample() {
    let adaptive = Overrides {
        noise: Some(0.05),
        ..Overrides::default()
    };
    let stage = stages().find(|s| s.name == "antialiasing").unwrap();
    assert!(same(stage, 16, adaptive, None));
    let (render, _) = small(stage, 16, adaptive, None);
    let fewest = render.samples.iter().min().unwrap();
    let most = render.samples.iter().max().unwrap();
    assert!(
        fewest < most,
        "pixels stop at different counts: {fewest} to {most}"
    );
}

#[test]
fn stratified_and_sobol_numbers_are_drawn_in_the_recursions_order() {
    for name in ["antialiasing", "light-sampling", "depth-of-field"] {
        let Some(stage) = stages().find(|s| s.name == name) else {
            continue;
        };
        for sampler in [Sampler::Stratified, Sampler::Sobol] {
            assert!(
                same(stage, 8, Overrides::default(), Some(sampler)),
                "{name}"
            );
        }
    }
}
