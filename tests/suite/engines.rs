//! The course's code against the fast engine: every stage of the build gives the same
//! 8-bit image, its radiance the same to within a few roundings, with the same counts
//! of rays and samples, whether it renders by default (the course's functions) or with
//! `[render] fast = true`; and
//! the fast engine does take over where it can (four paths at a time in the rooms of
//! diffuse spheres, its own hierarchy for the meshes).

use raycourse::check::compare::displayed;
use raycourse::engines::render;
use raycourse::fast::paths::paths_at_once;
use raycourse::maths::Real;
use raycourse::scene::beyond::{Beyond, Sampler};
use raycourse::scene_file::beyond::{BeyondOverrides, parse_with_beyond, stage_with_beyond};
use raycourse::{Disk, Overrides, Render, Scene, Stage, stages};

/// A scene and its settings beyond the course.
type Job = (Scene, Beyond);

/// The scene of `stage` at 30 x 9 pixels (30 is not a multiple of four, so rows end
/// with fewer than four paths), at most `samples` samples per pixel, with `extra`
/// and the stage's sampler or `sampler`.
fn small(stage: &Stage, samples: u32, extra: BeyondOverrides, sampler: Option<Sampler>) -> Job {
    let overrides = Overrides::sized(30, 9, samples);
    let (scene, mut beyond) = stage_with_beyond(stage, &overrides, &extra).unwrap();
    if let Some(sampler) = sampler {
        beyond.sampler = sampler;
    }
    (scene, beyond)
}

/// Renders `stage` both ways and asserts that the two renders agree; returns the
/// fast engine's scene and render.
fn same(
    stage: &Stage,
    samples: u32,
    extra: BeyondOverrides,
    sampler: Option<Sampler>,
) -> (Scene, Render) {
    let course = small(stage, samples, extra, sampler);
    assert!(
        !course.1.fast,
        "{}: the default is the course's code",
        stage.name
    );
    let fast = small(
        stage,
        samples,
        BeyondOverrides {
            fast: true,
            ..extra
        },
        sampler,
    );
    assert!(fast.1.fast, "{}: --fast is obeyed", stage.name);
    let render = agree(stage.name, &course, &fast);
    (fast.0, render)
}

/// Renders `course` and `fast`, the same scene without and with the fast engine,
/// asserts that they display as the same 8-bit image, that each pixel's radiance
/// agrees to within a few roundings (the fast engine takes its sines and cosines on
/// its lanes, within 2 units in the last place of the C library's), and that they
/// count the same rays and samples; returns the fast engine's render.
fn agree(name: &str, course: &Job, fast: &Job) -> Render {
    let (by_course, by_fast) = (render(&course.0, &course.1), render(&fast.0, &fast.1));
    let gamma = course.0.settings.gamma;
    let (a, b) = (
        displayed(&by_course.film, gamma),
        displayed(&by_fast.film, gamma),
    );
    let first = a.pixels().zip(b.pixels()).position(|(a, b)| a != b);
    assert_eq!(first, None, "{name}: first pixel that displays otherwise");
    let farthest = farthest_apart(&by_course, &by_fast);
    assert!(
        farthest <= AGREEMENT,
        "{name}: radiances {farthest:e} apart"
    );
    assert_eq!(by_course.rays, by_fast.rays, "{name}: rays");
    assert_eq!(by_course.samples, by_fast.samples, "{name}: samples");
    assert_eq!(by_course.dropped, by_fast.dropped, "{name}: dropped");
    by_fast
}

/// How far apart two renders' radiances may be, relative to the larger of each
/// channel and 1: 4096 roundings. A bounce's direction one unit in the last place away
/// from the course's moves its hit on a wall a thousand units away by about a
/// thousand roundings of a unit, and the light there by as much; measured, the
/// farthest apart on these stages are 28 roundings in double precision and 411 in
/// single.
const AGREEMENT: Real = 4096.0 * Real::EPSILON;

/// The largest difference between the two renders' channels, relative to the
/// larger of the channel and 1.
fn farthest_apart(a: &Render, b: &Render) -> Real {
    let channels =
        |r: &Render| -> Vec<Real> { r.film.pixels.iter().flat_map(|c| c.to_array()).collect() };
    let (a, b) = (channels(a), channels(b));
    a.iter()
        .zip(&b)
        .map(|(a, b)| (a - b).abs() / a.abs().max(1.0))
        .fold(0.0, Real::max)
}

/// The stages whose objects are all diffuse (spheres, and meshes, which always
/// are), in the course's order: the fast engine follows their paths four at a time.
const DIFFUSE_STAGES: [&str; 17] = [
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
    "mesh",
    "mesh-bbox",
    "bvh",
    "smooth-normals",
    "textures",
    "camera",
];

#[test]
fn every_stage_renders_the_same_bytes_with_the_fast_engine() {
    let mut four_at_a_time = vec![];
    for stage in stages() {
        let (scene, _) = same(stage, 4, BeyondOverrides::default(), None);
        if paths_at_once::applies(&scene) {
            four_at_a_time.push(stage.name);
        }
        for mesh in &scene.meshes {
            let search = match stage.name {
                "mesh" => "brute force, fast",
                "mesh-bbox" => "bounding box, fast",
                _ => "fast",
            };
            assert_eq!(
                mesh.search.name(),
                search,
                "{}: the fast search",
                stage.name
            );
        }
    }
    // The mirror, glass and Fresnel stages take the course's recursion; the stages
    // of later sessions are absent from an earlier session's build.
    let expected: Vec<&str> = DIFFUSE_STAGES
        .into_iter()
        .filter(|name| stages().any(|stage| stage.name == *name))
        .collect();
    assert_eq!(four_at_a_time, expected);
    assert!(four_at_a_time.contains(&"indirect"));
}

#[test]
fn adaptive_sampling_stops_each_pixel_at_the_same_sample() {
    let adaptive = BeyondOverrides {
        noise: Some(0.05),
        ..BeyondOverrides::default()
    };
    let stage = stages().find(|s| s.name == "antialiasing").unwrap();
    let (scene, render) = same(stage, 16, adaptive, None);
    assert!(paths_at_once::applies(&scene));
    let fewest = render.samples.iter().min().unwrap();
    let most = render.samples.iter().max().unwrap();
    assert!(
        fewest < most,
        "pixels stop at different counts: {fewest} to {most}"
    );
}

#[test]
fn stratified_and_sobol_numbers_are_drawn_in_the_course_order() {
    for name in ["antialiasing", "light-sampling", "depth-of-field"] {
        let Some(stage) = stages().find(|s| s.name == name) else {
            continue;
        };
        for sampler in [Sampler::Stratified, Sampler::Sobol] {
            let (scene, _) = same(stage, 8, BeyondOverrides::default(), Some(sampler));
            assert!(paths_at_once::applies(&scene), "{name}");
        }
    }
}

/// The mesh stages lit by a point light instead of their sphere light, with shadows:
/// a shadow ray is blocked by the cow's triangles as well as by the spheres, and
/// the fast engine's test of the meshes (`meshes_at_once::in_the_way`) decides as
/// the course's `Scene::occluded` does, with the brute force and with the fast
/// hierarchy.
#[cfg(feature = "s6")]
#[test]
fn meshes_cast_the_same_shadows_under_a_point_light() {
    for name in ["mesh", "bvh"] {
        let stage = stages().find(|s| s.name == name).unwrap();
        let source = stage
            .source
            .replacen("radius = 5\n", "", 1)
            .replace("light_sampling = true", "shadows = true");
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(stage.path);
        let scene = |fast: bool| {
            let overrides = Overrides::sized(24, 20, 2);
            let fast = BeyondOverrides {
                fast,
                ..BeyondOverrides::default()
            };
            parse_with_beyond(&source, &path, &overrides, &fast, &Disk).unwrap()
        };
        let (course, fast) = (scene(false), scene(true));
        assert!(
            course
                .0
                .light
                .is_some_and(|l| matches!(l, raycourse::lights::Light::Point(_)))
        );
        assert!(
            course.0.settings.shadows && paths_at_once::applies(&fast.0),
            "{name}"
        );
        let render = agree(name, &course, &fast);
        assert!(render.rays > 2 * 24 * 20 * 2, "{name}: shadow rays traced");
    }
}

/// In single precision the fast engine follows eight paths at once, and its images
/// are single precision's, not double's bytes: they must still match the
/// double-precision references of the exercises (`tests/exercises/references/`, at
/// their size, with many more samples) by `check`'s statistical test, block by
/// block against the noise; and a wrong image (the light a quarter dimmer) must
/// not.
#[cfg(feature = "f32")]
#[test]
fn single_precision_images_match_the_double_precision_references() {
    use raycourse::check::compare::{Linear, compare_blocks};
    for name in ["indirect", "light-sampling", "depth-of-field"] {
        let Some(stage) = stages().find(|s| s.name == name) else {
            continue;
        };
        let reference = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(format!("tests/exercises/references/{name}.png"));
        let reference = image::open(&reference).unwrap().into_rgb16();
        let overrides = Overrides::sized(reference.width(), reference.height(), 0);
        let fast = BeyondOverrides {
            fast: true,
            ..BeyondOverrides::default()
        };
        let (scene, beyond) = stage_with_beyond(stage, &overrides, &fast).unwrap();
        assert!(
            paths_at_once::applies(&scene),
            "{name}: eight paths at once"
        );
        let gamma = scene.settings.gamma;
        let film = render(&scene, &beyond).film;
        let values = reference.as_raw().iter();
        let reference = Linear {
            width: reference.width(),
            height: reference.height(),
            values: values
                .map(|&v| (f64::from(v) / 256.0).powf(f64::from(gamma)))
                .collect(),
        };
        let linear = Linear::from_film(&film, gamma);
        let outcome = compare_blocks(&linear, &reference, gamma);
        assert!(!outcome.image_differs, "{name}: {:?}", outcome.differs);
        let dimmer = Linear {
            values: linear.values.iter().map(|v| v * 0.75).collect(),
            ..linear
        };
        assert!(
            compare_blocks(&dimmer, &reference, gamma).image_differs,
            "{name}"
        );
    }
}
