//! Looking inside a render: the probe follows the render's own path to the last bit,
//! explains it in numbers that can be checked by hand, and the images of what the
//! renderer sees count exactly what each search tests.

use raycourse::inspect::aov::{Aov, see};
use raycourse::inspect::path::Probe;
use raycourse::inspect::probe::{ProbeError, probe};
use raycourse::maths::Real;
use raycourse::{Overrides, Scene, render, stages};

use crate::common::{run, text};

/// Stage `name` at `size` x `size` and at most `samples` samples a pixel.
fn small(name: &str, size: u32, samples: u32) -> Scene {
    let stage = stages().find(|s| s.name == name).unwrap();
    let course = stage.scene(&Overrides::default()).unwrap().settings.samples;
    let overrides = Overrides::sized(size, size, course.min(samples));
    stage.scene(&overrides).unwrap()
}

/// The bits of a colour, to compare to the last bit.
fn bits(c: [Real; 3]) -> [u64; 3] {
    c.map(|x| raycourse::maths::to_double(x).to_bits())
}

/// For every stage of the build and a few pixels of each, the probe's pixel is the
/// render's to the last bit; so, before session 3, is the sample's radiance, and
/// from session 3 the mean of every sample's probed radiance.
#[test]
fn the_probe_reports_the_radiance_the_render_computes() {
    for stage in stages() {
        let scene = small(stage.name, 12, 3);
        let film = render(&scene).film;
        for (x, y) in [(6, 6), (2, 9), (10, 1)] {
            let pixel = film.pixels[(y * 12 + x) as usize].to_array();
            let samples: Vec<Probe> = (0..scene.settings.samples)
                .map(|k| probe(&scene, x, y, k).unwrap())
                .collect();
            assert_eq!(
                bits(samples[0].pixel),
                bits(pixel),
                "{} ({x}, {y})",
                stage.name
            );
            assert_eq!(
                bits(mean_of(&samples)),
                bits(pixel),
                "{} ({x}, {y}): the samples",
                stage.name
            );
        }
    }
}

/// The mean of the probed samples' radiance, as the render takes it.
#[cfg(feature = "s3")]
fn mean_of(samples: &[Probe]) -> [Real; 3] {
    let mut mean = raycourse::render::samples::SampleMean::default();
    for s in samples {
        mean.add(s.radiance.into());
    }
    mean.mean().to_array()
}

/// The one sample's radiance: before session 3 it is the pixel's.
#[cfg(not(feature = "s3"))]
fn mean_of(samples: &[Probe]) -> [Real; 3] {
    samples[0].radiance
}

/// What each level adds sums to the sample's radiance (up to the rounding of a sum
/// taken in another order), and each level's arriving radiance is what it adds
/// plus the next level's, weighted.
#[test]
fn the_levels_add_up_to_the_sample() {
    for name in stages().map(|s| s.name) {
        let scene = small(name, 12, 2);
        for k in 0..scene.settings.samples {
            let found = probe(&scene, 5, 7, k).unwrap();
            let total: [Real; 3] = found.levels.iter().fold([0.0; 3], |sum, level| {
                [0, 1, 2].map(|c| sum[c] + level.adds[c])
            });
            for c in 0..3 {
                let expected = found.radiance[c];
                assert!(
                    (total[c] - expected).abs() <= 1e3 * Real::EPSILON * expected.abs().max(1.0),
                    "{name} sample {k}: levels add {total:?}, the sample is {:?}",
                    found.radiance
                );
            }
        }
    }
}

/// At the centre of the Fresnel glass ball the camera ray meets the glass almost
/// head on, where Fresnel's reflectance is `((n - 1) / (n + 1))^2 = 0.04` for
/// `n = 1.5`; the probe names the choice and the refraction's `eta = 1 / 1.5`.
#[cfg(feature = "s4")]
#[test]
fn a_glass_pixel_shows_the_refraction_and_fresnel_s_choice() {
    let scene = small("fresnel", 64, 8);
    let found = probe(&scene, 32, 32, 0).unwrap();
    let first = &found.levels[0];
    assert!(
        first
            .hit
            .as_ref()
            .unwrap()
            .material
            .starts_with("FresnelGlass")
    );
    let next = first.next.as_ref().unwrap();
    let f = next.fresnel.unwrap();
    assert!((f - 0.04).abs() < 1e-3, "F = {f}");
    let kind = next.kind.to_string();
    assert!(kind.contains("Fresnel's choice"), "{kind}");
    if kind.starts_with("refraction") {
        assert!(kind.contains("eta = n1 / n2 = 0.6667"), "{kind}");
        let french = next
            .kind
            .say(raycourse::messages::language::Language::French);
        assert!(french.contains("eta = n1 / n2 = 0,6667"), "{french}");
    }
}

/// A diffuse bounce's pdf is `cos(theta) / pi` of its own cosine, and its weight the
/// albedo (times `1 / survival` past the bounce limit).
#[cfg(feature = "s3")]
#[test]
fn a_diffuse_bounce_shows_its_pdf_and_weight() {
    let scene = small("indirect", 16, 4);
    let found = probe(&scene, 8, 12, 1).unwrap();
    let bounce = found.levels[0].next.as_ref().unwrap();
    let (cos, pdf) = (bounce.cos.unwrap(), bounce.pdf.unwrap());
    assert!(cos > 0.0 && cos <= 1.0);
    assert!((pdf - cos / raycourse::maths::PI).abs() <= Real::EPSILON);
    let material = &found.levels[0].hit.as_ref().unwrap().material;
    assert!(material.starts_with("Diffuse"), "{material}");
}

/// `probe --json` prints one document with a block per level, the same as the text.
#[test]
fn the_json_parses_and_matches_the_text() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["probe", "shading", "256", "256", "--json"];
    let out = run(&args, dir.path());
    assert!(out.status.success(), "{}", text(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let levels = json["levels"].as_array().unwrap();
    assert_eq!(levels.len(), 1, "shading: the camera ray only");
    let t = levels[0]["hit"]["t"].as_f64().unwrap();
    // The camera at z = 55 looks at a sphere of radius 10 at the origin.
    assert!((t - 45.0).abs() < 0.01, "t = {t}");
    let out = run(&args[..4], dir.path());
    assert_eq!(text(&out.stdout).matches("level ").count(), levels.len());
}

/// A pixel outside the image and a sample past the last are refused, with exit 2.
#[test]
fn a_probe_outside_the_image_is_refused() {
    let scene = small("shading", 8, 1);
    assert_eq!(
        probe(&scene, 8, 0, 0),
        Err(ProbeError::Outside {
            x: 8,
            y: 0,
            width: 8,
            height: 8
        })
    );
    assert_eq!(
        probe(&scene, 0, 0, 1),
        Err(ProbeError::NoSuchSample {
            sample: 1,
            samples: 1
        })
    );
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["probe", "shading", "512", "3"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("outside the image, which is 512x512"));
}

/// Near the sphere's nearest point the normal is about `(0, 0, 1)`, shown as
/// `(128, 128, 255)` (the pixel's centre is half a pixel off the axis: N is off by
/// about 0.05 in x and y); its distance from the camera is 45; the spheres have colours of their own.
#[test]
fn the_images_show_normals_distances_and_objects() {
    let scene = small("shading", 64, 1);
    let centre = |rgb: &[u8]| {
        let at = (32 * 64 + 32) * 3;
        [rgb[at], rgb[at + 1], rgb[at + 2]]
    };
    let normal = see(&scene, Aov::Normal);
    let [r, g, b] = centre(&normal.rgb);
    assert!(
        r.abs_diff(128) <= 7 && g.abs_diff(128) <= 7 && b >= 254,
        "{:?}",
        [r, g, b]
    );
    let n = probe(&scene, 32, 32, 0).unwrap().levels[0]
        .hit
        .as_ref()
        .unwrap()
        .normal;
    let shown = n.map(|c| ((c + 1.0) * 127.5).round() as u8);
    assert_eq!([r, g, b], shown, "the normal the probe finds, N = {n:?}");
    let depth = see(&scene, Aov::Depth);
    let (low, _) = depth.range.unwrap();
    assert!((low - 45.0).abs() < 0.05, "nearest distance {low}");
    assert_eq!(depth.height, 64 + 15, "the legend is under the image");
    let scene = small("spheres", 64, 1);
    let objects = see(&scene, Aov::Object);
    let colours: std::collections::HashSet<&[u8]> = objects.rgb.chunks(3).collect();
    assert!(
        colours.len() > scene.spheres.len().min(3),
        "{} colours",
        colours.len()
    );
}

/// Brute force tests every sphere and every triangle for every camera ray; the box
/// adds one test and, for a ray that misses it, replaces all the triangles; the BVH
/// tests far fewer: their means fall in that order.
#[cfg(feature = "s6")]
#[test]
fn the_cost_of_a_ray_falls_from_brute_force_to_the_box_to_the_bvh() {
    let mean = |name: &str| {
        let scene = small(name, 48, 1);
        let triangles: usize = scene.meshes.iter().map(|m| m.triangles.len()).sum();
        let spheres = scene.spheres.len() as Real;
        let image = see(&scene, Aov::Cost);
        (
            image.range.unwrap(),
            image.mean.unwrap(),
            spheres,
            triangles as Real,
        )
    };
    let (range, brute, spheres, triangles) = mean("mesh");
    assert_eq!(range, (spheres + triangles, spheres + triangles));
    let (range, boxed, ..) = mean("mesh-bbox");
    assert_eq!(range, (spheres + 1.0, spheres + 1.0 + triangles));
    let (_, bvh, ..) = mean("bvh");
    assert!(brute > boxed && boxed > 10.0 * bvh, "{brute} {boxed} {bvh}");
}

/// `--aov cost` writes the image instead of the render and gives its mean.
#[test]
fn the_cost_image_gives_its_mean() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(
        &[
            "s1", "spheres", "--width", "16", "--height", "16", "--aov", "cost",
        ],
        dir.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let spheres = small("spheres", 8, 1).spheres.len();
    let line = text(&out.stdout);
    assert!(
        line.contains(&format!("mean cost {spheres}.0 tests a ray")),
        "{line}"
    );
    let image = image::open(dir.path().join("out/spheres-cost.png")).unwrap();
    assert_eq!((image.width(), image.height()), (16, 16 + 15));
    assert!(
        !dir.path().join("out/spheres.png").exists(),
        "no render written"
    );
}

/// `--aov cost` with the fast engine is refused, naming the option to leave out,
/// and writes no image: the fast engine's searches count no tests.
#[cfg(feature = "beyond")]
#[test]
fn the_cost_image_refuses_the_fast_engine() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(
        &[
            "s5", "mesh", "--width", "8", "--height", "8", "--aov", "cost", "--fast",
        ],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stdout));
    let error = text(&out.stderr);
    assert!(
        error.contains("mesh: `--aov cost` counts the tests of the course's searches")
            && error.contains("leave out `--fast`"),
        "{error}"
    );
    assert!(!dir.path().join("out/mesh-cost.png").exists());
}

/// `probe --scene FILE X Y` follows a scene file's pixel as `probe STAGE X Y` follows
/// the stage's; a stage with only one coordinate is refused.
#[test]
fn a_scene_file_is_probed_like_its_stage() {
    let dir = tempfile::tempdir().unwrap();
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("sessions/s1/shading.toml");
    let size = ["--width", "16", "--height", "16"];
    let by_file = run(
        &[
            &["probe", "--scene", file.to_str().unwrap(), "8", "5"][..],
            &size,
        ]
        .concat(),
        dir.path(),
    );
    let by_stage = run(
        &[&["probe", "shading", "8", "5"][..], &size].concat(),
        dir.path(),
    );
    assert!(by_file.status.success(), "{}", text(&by_file.stderr));
    assert_eq!(text(&by_file.stdout), text(&by_stage.stdout));
    let out = run(&["probe", "shading", "8"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("give STAGE X Y"),
        "{}",
        text(&out.stderr)
    );
}

/// The probe follows the course's code: a scene file that asks for the fast engine
/// or a sampler beyond the course is refused with exit 2, naming what it asks for.
#[cfg(feature = "beyond")]
#[test]
fn a_scene_beyond_the_course_is_not_probed() {
    let dir = tempfile::tempdir().unwrap();
    let shading = include_str!("../../sessions/s1/shading.toml");
    let file = dir.path().join("fast.toml");
    let text_of = shading.replace("[render]", "[render]\nfast = true\nsampler = \"sobol\"");
    std::fs::write(&file, text_of).unwrap();
    let out = run(
        &["probe", "--scene", file.to_str().unwrap(), "8", "5"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains(
            "the probe follows the course's code; this scene asks for the sampler Sobol and \
             the fast engine (--fast)"
        ),
        "{}",
        text(&out.stderr)
    );
}
