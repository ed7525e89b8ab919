//! Every stage of the build, rendered small and pinned by a PNG snapshot. The
//! snapshot files are shared by all feature levels, so a stage renders byte for
//! byte the same in every later session's build.

use raycourse::maths::Real;
use raycourse::{Overrides, Render, Stage, encode_png, render, stages};

const SIZE: u32 = 96;

/// At most this many samples per pixel: enough to see what a stage does.
const SAMPLES: u32 = 2;

fn render_small(stage: &Stage, threads: usize) -> (Render, Real) {
    let course = stage.scene(&Overrides::default()).unwrap().settings.samples;
    let overrides = Overrides::sized(SIZE, SIZE, course.min(SAMPLES));
    let scene = stage
        .scene(&overrides)
        .expect("built-in scene files are valid");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let result = pool.install(|| render(&scene));
    (result, scene.settings.gamma)
}

/// Each stage: its PNG matches the snapshot, no sample was NaN or infinite, and three
/// threads give the same bytes as two (in a single-precision build, all but the
/// snapshot).
#[test]
fn every_stage_matches_its_snapshot_whatever_the_thread_count() {
    for stage in stages() {
        let (result, gamma) = render_small(stage, 2);
        assert!(
            result.film.pixels.iter().all(|c| c.is_finite()),
            "{}",
            stage.name
        );
        assert_eq!(result.dropped, 0, "{}", stage.name);
        let png = encode_png(&result.film, gamma);
        // The snapshots hold the double-precision images; a single-precision build
        // checks everything else.
        #[cfg(not(feature = "f32"))]
        insta::assert_binary_snapshot!(&format!("{}.png", stage.name), png.clone());
        let (other, _) = render_small(stage, 3);
        assert_eq!(
            encode_png(&other.film, gamma),
            png,
            "{} on three threads",
            stage.name
        );
    }
}

#[test]
fn every_built_in_scene_loads_at_course_settings() {
    for stage in stages() {
        let scene = stage.scene(&Overrides::default()).unwrap();
        let size = (scene.camera.width, scene.camera.height);
        let expected = if stage.name.starts_with("mesh") {
            (128, 128)
        } else {
            (512, 512)
        };
        assert_eq!(size, expected, "{}", stage.name);
        assert!(
            stage
                .path
                .ends_with(&format!("s{}/{}.toml", stage.session, stage.name))
        );
    }
}
