//! Every stage of the build, rendered small and pinned by a PNG snapshot. The
//! snapshot files are shared by all feature levels, so a stage renders byte for
//! byte the same in every later session's build.

use std::num::NonZeroU32;

use indicatif::ProgressBar;
use raycourse::{Overrides, Real, Render, Stage, encode_png, render, stages};

const SIZE: NonZeroU32 = NonZeroU32::new(128).unwrap();

/// At most this many samples per pixel: enough to see what a stage does.
const SAMPLES: u32 = 4;

fn render_small(stage: &Stage, threads: usize) -> (Render, Real) {
    let course = stage.scene(&Overrides::default()).unwrap().settings.samples;
    let overrides = Overrides {
        width: Some(SIZE),
        height: Some(SIZE),
        samples: NonZeroU32::new(course.min(SAMPLES)),
        ..Overrides::default()
    };
    let scene = stage
        .scene(&overrides)
        .expect("built-in scene files are valid");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let result = pool.install(|| render(&scene, &ProgressBar::hidden()));
    (result, scene.settings.gamma)
}

fn render_png(stage: &Stage, threads: usize) -> Vec<u8> {
    let (result, gamma) = render_small(stage, threads);
    encode_png(&result.film, gamma)
}

#[test]
fn no_stage_lets_a_non_finite_value_reach_the_film() {
    for stage in stages() {
        let (result, _) = render_small(stage, 2);
        assert!(
            result.film.pixels.iter().all(|c| c.is_finite()),
            "{}",
            stage.name
        );
        assert_eq!(result.dropped, 0, "{}", stage.name);
    }
}

#[test]
fn every_stage_matches_its_snapshot() {
    for stage in stages() {
        insta::assert_binary_snapshot!(&format!("{}.png", stage.name), render_png(stage, 2));
    }
}

#[test]
fn thread_count_does_not_change_the_bytes() {
    for stage in stages() {
        assert_eq!(
            render_png(stage, 1),
            render_png(stage, 2),
            "stage {}",
            stage.name
        );
    }
}

#[test]
fn every_built_in_scene_loads_at_course_settings() {
    for stage in stages() {
        let scene = stage.scene(&Overrides::default()).unwrap();
        assert_eq!(
            (scene.camera.width, scene.camera.height),
            (512, 512),
            "{}",
            stage.name
        );
        assert!(
            stage
                .path
                .ends_with(&format!("s{}/{}.toml", stage.session, stage.name))
        );
    }
}
