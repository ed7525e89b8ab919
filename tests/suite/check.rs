//! `raycourse check`: a right image of every stage passes, whatever its seed and
//! its number of samples; each classic mistake, made by a real mutant of the
//! renderer (a scene-file edit, or a variant of the code written here), fails and
//! gets its hint.

use std::path::{Path, PathBuf};

use crate::common::{run, run_in_locale, text};
use image::codecs::pnm::{PnmEncoder, PnmSubtype, SampleEncoding};
use image::{ExtendedColorType, ImageEncoder, RgbImage};
use raycourse::check::expected::{Renderer, Source};
use raycourse::check::report::{Report, Verdict, check};
use raycourse::geometry::Ray;
use raycourse::integrator::Tracer;
use raycourse::lights::Light;
use raycourse::materials::Material;
use raycourse::maths::{Colour, PI, Real, pixel_rng};
use raycourse::messages::language::Language;
use raycourse::render::cache::Folder;
use raycourse::render::film::display;
use raycourse::{Overrides, Scene, Stage, encode_png, stages};

/// Width and height of the images checked.
const SIZE: u32 = 64;

/// The stage called `name`.
fn stage(name: &str) -> &'static Stage {
    stages().find(|s| s.name == name).unwrap()
}

/// The scene of `stage` with its file text changed by `edit`, at `SIZE`, with `seed`
/// and, if given, `samples`.
fn scene(stage: &Stage, edit: &dyn Fn(&str) -> String, seed: u64, samples: Option<u32>) -> Scene {
    scene_at(stage, edit, (seed, samples), SIZE)
}

/// [`scene`] at `size` x `size` pixels, its meshes searched by a hierarchy, read
/// by [`RENDERER`].
fn scene_at(
    stage: &Stage,
    edit: &dyn Fn(&str) -> String,
    (seed, samples): (u64, Option<u32>),
    size: u32,
) -> Scene {
    let overrides = Overrides {
        seed: Some(seed),
        ..Overrides::sized(size, size, samples.unwrap_or(0))
    };
    let mut file: toml::Table = edit(stage.source).parse().unwrap();
    file["render"]
        .as_table_mut()
        .unwrap()
        .insert("acceleration".into(), "bvh".into());
    let text = toml::to_string(&file).unwrap();
    RENDERER
        .scene(&text, &stage.file(), &overrides, &raycourse::Disk)
        .unwrap()
}

/// What renders the references and the students' images: the fast engine where the
/// build has it, which gives the course's bytes in less time.
#[cfg(feature = "beyond")]
const RENDERER: &dyn Renderer = &raycourse::engines::Fast;
/// What renders the references and the students' images: the course's code.
#[cfg(not(feature = "beyond"))]
const RENDERER: &dyn Renderer = &raycourse::check::expected::Course;

/// A student's image: the scene rendered by the crate, written as a PNG and read back.
fn picture(scene: &Scene) -> RgbImage {
    let film = RENDERER.render(scene, &|_| {}).film;
    let png = encode_png(&film, scene.settings.gamma);
    image::load_from_memory(&png).unwrap().to_rgb8()
}

/// The checker's report on `image` of `stage`, its references cached in `cache`.
fn checked(stage: &Stage, image: &RgbImage, cache: &Path) -> Report {
    let source = Source {
        stage,
        size: image.dimensions(),
        cache: &Folder(cache),
        files: &raycourse::Disk,
        progress: &|_| {},
        renderer: RENDERER,
    };
    check(&source, image, false).unwrap()
}

/// A folder for the references, shared by the tests of one run.
fn cache() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raycourse-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The stage's own scene file.
fn same(text: &str) -> String {
    text.to_owned()
}

#[test]
fn every_deterministic_stage_passes_its_own_image() {
    let cache = cache();
    let deterministic =
        stages().filter(|s| s.scene(&Overrides::default()).unwrap().settings.samples == 1);
    let mut count = 0;
    for stage in deterministic {
        let report = checked(stage, &picture(&scene(stage, &same, 0, None)), &cache);
        assert_eq!(
            report.verdict,
            Verdict::Matches,
            "{}: {report:?}",
            stage.name
        );
        let ratio = report.ratio;
        assert!(
            ratio.iter().all(|r| (r - 1.0).abs() < 0.02),
            "{}: {ratio:?}",
            stage.name
        );
        count += 1;
    }
    assert_eq!(count, 7);
}

/// A right image of each deterministic stage saved as a JPEG of quality 85 (whose
/// colour is stored at half the resolution) passes: the compression moves pixels by
/// more than a PNG's tolerance near every edge. A JPEG of a wrong image still fails
/// with its hint.
#[test]
fn every_deterministic_stage_passes_as_a_jpeg_of_quality_85() {
    let cache = cache();
    let as_jpeg = |stage: &Stage, edit: &dyn Fn(&str) -> String| {
        let image = picture(&scene_at(stage, edit, (0, None), 256));
        let mut jpeg = vec![];
        image::codecs::jpeg::JpegEncoder::new_with_quality(&mut jpeg, 85)
            .encode_image(&image)
            .unwrap();
        let read = image::load_from_memory(&jpeg).unwrap().to_rgb8();
        let source = Source {
            stage,
            size: read.dimensions(),
            cache: &Folder(&cache),
            files: &raycourse::Disk,
            progress: &|_| {},
            renderer: RENDERER,
        };
        check(&source, &read, true).unwrap()
    };
    let deterministic =
        stages().filter(|s| s.scene(&Overrides::default()).unwrap().settings.samples == 1);
    for stage in deterministic {
        let report = as_jpeg(stage, &same);
        assert_eq!(
            report.verdict,
            Verdict::Matches,
            "{}: {report:?}",
            stage.name
        );
    }
    let without_gamma = as_jpeg(stage("glass"), &|t| t.replace("gamma = 2.2\n", ""));
    assert!(caught(&without_gamma, "no gamma"), "{without_gamma:?}");
}

/// A right render with another seed, at the course's samples or a quarter of them,
/// passes: no false alarm in the trials. The naive soft shadows are tried at the
/// course's samples only: their light is found by chance, so nearly every pixel
/// is black or clipped to white, and with fewer samples more of them are black: the
/// picture is darker, as any renderer's would be.
#[test]
fn monte_carlo_stages_pass_with_any_seed_and_fewer_samples() {
    let cache = cache();
    let monte_carlo: Vec<&Stage> = stages()
        .filter(|s| s.scene(&Overrides::default()).unwrap().settings.samples > 1)
        .collect();
    let mut trials = 0;
    let mut alarms = vec![];
    for stage in &monte_carlo {
        let course = stage.scene(&Overrides::default()).unwrap().settings.samples;
        let fewer = if stage.name == "soft-shadows" {
            course
        } else {
            course / 4
        };
        for (seed, samples) in [(1, course), (2, course), (3, fewer)] {
            let report = checked(
                stage,
                &picture(&scene(stage, &same, seed, Some(samples))),
                &cache,
            );
            trials += 1;
            if report.verdict != Verdict::Matches {
                alarms.push(format!(
                    "{} seed {seed} at {samples} spp: {report:?}",
                    stage.name
                ));
            }
            if samples < course {
                let (noise, _) = report.noise.expect(stage.name);
                assert!(
                    noise > 2.0,
                    "{}: a quarter of the samples is noisier ({noise})",
                    stage.name
                );
            }
        }
    }
    assert_eq!(trials, 3 * monte_carlo.len());
    assert!(
        alarms.is_empty(),
        "{} false alarms in {trials} trials: {alarms:#?}",
        alarms.len()
    );
}

/// Whether `report` says the image differs, with the hint of the mistake whose
/// English name is `name`.
fn caught(report: &Report, name: &str) -> bool {
    let named = report.hint.map(|m| m.words(Language::English)[0].clone());
    report.verdict == Verdict::Differs && named.as_deref() == Some(name)
}

/// A texture made from Spot's by `change` of each 8-bit channel value, written in
/// `dir`; its path.
fn changed_texture(dir: &Path, name: &str, change: &dyn Fn(RgbImage) -> RgbImage) -> PathBuf {
    let texture =
        image::open(Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/spot/spot_texture.png"))
            .unwrap()
            .to_rgb8();
    let path = dir.join(name);
    change(texture).save(&path).unwrap();
    path
}

/// A change of a scene file's text.
type Edit = Box<dyn Fn(&str) -> String>;

/// Mistakes a scene-file edit reproduces: gamma left out or applied twice, a light
/// pi times too bright or too dark (the 1/pi of the BRDF forgotten or doubled), a
/// refractive index inverted, paths stopped after one bounce, a texture used without
/// its gamma or upside down.
#[test]
fn scene_file_mistakes_are_caught_with_their_hint() {
    let cache = cache();
    let dir = tempfile::tempdir().unwrap();
    let raw = changed_texture(dir.path(), "raw.png", &|mut t| {
        t.pixels_mut().for_each(|p| {
            p.0 =
                p.0.map(|v| (255.0 * (f64::from(v) / 255.0).powf(1.0 / 2.2)).round() as u8)
        });
        t
    });
    let flipped = changed_texture(dir.path(), "flipped.png", &|t| {
        image::imageops::flip_vertical(&t)
    });
    let texture = |file: &Path| format!("textured = true\ntexture = {:?}", file.to_string_lossy());
    let cases: Vec<(&str, Edit, &str)> = vec![
        (
            "glass",
            Box::new(|t: &str| t.replace("gamma = 2.2\n", "")),
            "no gamma",
        ),
        (
            "glass",
            Box::new(|t: &str| t.replace("gamma = 2.2", "gamma = 4.84")),
            "gamma twice",
        ),
        (
            "indirect",
            Box::new(|t: &str| t.replace("intensity = 2e10", "intensity = 6.283185307179586e10")),
            "1/pi missing",
        ),
        (
            "shading",
            Box::new(|t: &str| t.replace("intensity = 2e7", "intensity = 6366197.723675814")),
            "1/pi twice",
        ),
        (
            "glass",
            Box::new(|t: &str| t.replace("glass = 1.5", "glass = 0.6666666666666666")),
            "inverted index",
        ),
        (
            "indirect",
            Box::new(|t: &str| t.replace("bounces = 5", "bounces = 1")),
            "bounce limit",
        ),
        (
            "textures",
            Box::new(move |t: &str| t.replace("textured = true", &texture(&raw))),
            "texture gamma",
        ),
        (
            "textures",
            Box::new(move |t: &str| t.replace("textured = true", &texture(&flipped))),
            "texture v flipped",
        ),
    ];
    for (name, edit, mistake) in cases {
        assert_ne!(
            edit(stage(name).source),
            stage(name).source,
            "{mistake}: the edit applies"
        );
        // The cow is small in a small image: its texture needs more pixels.
        let size = if name == "textures" { 2 * SIZE } else { SIZE };
        let image = picture(&scene_at(stage(name), &*edit, (9, None), size));
        let report = checked(stage(name), &image, &cache);
        assert!(caught(&report, mistake), "{name}, {mistake}: {report:?}");
    }
}

/// The mistakes are made by editing the stage's scene file as TOML, not as text: the
/// same file written with other spacing and a comment gets the same diagnosis.
#[test]
fn a_scene_file_written_otherwise_gets_the_same_diagnosis() {
    let cache = cache();
    let glass = stage("glass");
    let rewritten = glass
        .source
        .replace(" = ", "=")
        .replace("[render]\n", "[render] # the course's settings\n");
    assert!(rewritten.contains("{ glass=1.5 }"), "{rewritten}");
    let other = Stage {
        source: Box::leak(rewritten.into_boxed_str()),
        ..*glass
    };
    let inverted = |t: &str| t.replace("glass = 1.5", "glass = 0.6666666666666666");
    let image = picture(&scene(glass, &inverted, 9, None));
    for stage in [glass, &other] {
        let report = checked(stage, &image, &cache);
        assert!(caught(&report, "inverted index"), "{report:?}");
    }
}

/// A pixel loop off by one moves the image by a pixel: caught with its hint, on
/// stages where the move changes many pixels (spheres, glass) and on one where it
/// changes only the edges, which the comparison allows for (shading).
#[test]
fn an_image_moved_by_a_pixel_is_caught_with_its_hint() {
    let cache = cache();
    for name in ["spheres", "shading", "glass"] {
        let image = picture(&scene(stage(name), &same, 4, None));
        let (w, h) = image.dimensions();
        let down = RgbImage::from_fn(w, h, |x, y| *image.get_pixel(x, y.saturating_sub(1)));
        let right = RgbImage::from_fn(w, h, |x, y| *image.get_pixel(x.saturating_sub(1), y));
        for (way, moved) in [("down", down), ("right", right)] {
            let report = checked(stage(name), &moved, &cache);
            assert!(
                caught(&report, "shifted a pixel"),
                "{name}, {way}: {report:?}"
            );
        }
    }
}

/// Mistakes of the image's rows and columns: written upside down, mirrored, both
/// (half a turn), or with rows and columns swapped.
#[test]
fn flipped_images_are_caught_with_their_hint() {
    let cache = cache();
    for name in ["spheres", "antialiasing"] {
        let image = picture(&scene(stage(name), &same, 4, None));
        let upside_down = checked(stage(name), &image::imageops::flip_vertical(&image), &cache);
        assert!(
            caught(&upside_down, "upside down"),
            "{name}: {upside_down:?}"
        );
        let mirrored = checked(
            stage(name),
            &image::imageops::flip_horizontal(&image),
            &cache,
        );
        assert!(caught(&mirrored, "mirrored"), "{name}: {mirrored:?}");
        let turned = checked(stage(name), &image::imageops::rotate180(&image), &cache);
        assert!(caught(&turned, "half a turn"), "{name}: {turned:?}");
        let swapped = checked(
            stage(name),
            &image::imageops::rotate90(&image::imageops::flip_vertical(&image)),
            &cache,
        );
        assert!(
            caught(&swapped, "rows and columns swapped"),
            "{name}: {swapped:?}"
        );
    }
}

/// The image of `scene` by a renderer whose radiance along a camera ray is `radiance`
/// (averaged over the scene's samples, each pixel with its own random numbers).
fn mutant_picture(scene: &Scene, radiance: &dyn Fn(&mut Tracer, &Ray) -> Colour) -> RgbImage {
    let camera = scene.camera;
    let mut tracer = Tracer::new(scene);
    RgbImage::from_fn(camera.width, camera.height, |column, row| {
        tracer.rng = pixel_rng(scene.settings.seed, u64::from(row * camera.width + column));
        let mut sum = Colour::ZERO;
        for _ in 0..scene.settings.samples {
            let ray = camera.sample_ray(row, column, &mut tracer.rng);
            sum += radiance(&mut tracer, &ray);
        }
        let mean = sum / scene.settings.samples as Real;
        image::Rgb(mean.to_array().map(|v| display(v, scene.settings.gamma)))
    })
}

/// What a student's path tracer gets wrong in the mutants below.
#[derive(Clone, Copy)]
enum Slip {
    /// A bounced ray that meets the sampled light adds its glow again.
    LightTwice,
    /// Directions drawn with density `cos / pi`, weighted as uniform ones
    /// (`2 albedo cos`).
    CosineAsUniform,
}

/// A student's path tracer for diffuse scenes, with `slip`.
fn slipped_radiance(tracer: &mut Tracer, ray: &Ray, bounces: u32, slip: Slip) -> Colour {
    let Some(hit) = tracer.trace(ray) else {
        return Colour::ZERO;
    };
    let Material::Diffuse { albedo } = hit.material else {
        return hit.emission;
    };
    let hit = hit.facing_the_ray();
    let direct = tracer.direct_light(&hit, albedo);
    if bounces == 0 {
        return hit.emission + direct;
    }
    let direction = tracer.cosine_direction(&hit);
    let weight = match slip {
        Slip::LightTwice => albedo,
        Slip::CosineAsUniform => albedo * 2.0 * direction.dot(hit.normal),
    };
    hit.emission
        + direct
        + weight * slipped_radiance(tracer, &hit.spawn(direction), bounces - 1, slip)
}

/// A point light's Lambert shading without the `1 / (4 pi r^2)` of its falloff.
fn no_falloff(t: &mut Tracer, ray: &Ray) -> Colour {
    let light = t.scene.light;
    let Some(hit) = t.trace(ray) else {
        return Colour::ZERO;
    };
    let (Material::Diffuse { albedo }, Some(Light::Point(light))) = (hit.material, light) else {
        return hit.emission;
    };
    let hit = hit.facing_the_ray();
    let l = (light.position - hit.point).normalize();
    hit.emission + light.intensity * hit.normal.dot(l).max(0.0) * albedo / PI
}

/// Lambert shading with shadow rays started on the surface itself.
fn acne(t: &mut Tracer, ray: &Ray) -> Colour {
    let scene = t.scene;
    let Some(hit) = t.trace(ray) else {
        return Colour::ZERO;
    };
    let (Material::Diffuse { albedo }, Some(Light::Point(light))) = (hit.material, scene.light)
    else {
        return hit.emission;
    };
    let hit = hit.facing_the_ray();
    let shadow = Ray::new(hit.point, light.position - hit.point);
    if scene.occluded(&shadow, hit.point.distance(light.position)) {
        return hit.emission;
    }
    hit.emission + light.lambert(hit.point, hit.normal, albedo)
}

/// Mistakes in a student's code, made by variants of the renderer written here: the
/// light counted twice with light sampling, the weight of cosine-weighted bounces
/// taken as that of uniform ones, a point light without its `1 / (4 pi r^2)`, and
/// shadow rays started on the surface (shadow acne).
#[test]
fn code_mutants_are_caught_with_their_hint() {
    let cache = cache();
    let slips = [
        ("light-sampling", Slip::LightTwice, "light counted twice"),
        ("indirect", Slip::CosineAsUniform, "bounce weight"),
    ];
    for (name, slip, mistake) in slips {
        let scene = scene(stage(name), &same, 6, None);
        let bounces = scene.settings.bounces;
        let image = mutant_picture(&scene, &|t, ray| slipped_radiance(t, ray, bounces, slip));
        let report = checked(stage(name), &image, &cache);
        assert!(caught(&report, mistake), "{name}, {mistake}: {report:?}");
    }
    // In the room, whose walls are far from the light: on the sphere alone the
    // light is strong enough to clip to white with or without the falloff.
    let spheres = scene(stage("spheres"), &same, 0, None);
    let report = checked(
        stage("spheres"),
        &mutant_picture(&spheres, &no_falloff),
        &cache,
    );
    assert!(caught(&report, "no falloff"), "{report:?}");
    let shadows = scene(stage("shadows"), &same, 0, None);
    let image = mutant_picture(&shadows, &acne);
    let report = checked(stage("shadows"), &image, &cache);
    assert!(caught(&report, "shadow acne"), "{report:?}");
}

/// The command as a student runs it: exit code 0 for a right image, 1 for a wrong
/// one with its hint, 2 for a file that is not an image or an unknown stage; and a
/// teacher's grading of a folder.
#[test]
fn the_command_answers_with_its_exit_code_and_grades_a_folder() {
    let dir = tempfile::tempdir().unwrap();
    let cache = cache();
    let glass = picture(&scene(stage("glass"), &same, 0, None));
    glass.save(dir.path().join("glass.png")).unwrap();
    let dark = scene(stage("glass"), &|t| t.replace("gamma = 2.2\n", ""), 0, None);
    picture(&dark).save(dir.path().join("dark.png")).unwrap();
    std::fs::write(dir.path().join("note.png"), b"not a picture").unwrap();
    let check = |args: &[&str]| check_in(dir.path(), &cache, args);
    let right = check(&["glass", "glass.png"]);
    assert_eq!(right.status.code(), Some(0), "{}", text(&right.stdout));
    assert!(text(&right.stdout).starts_with("glass: matches"));
    let wrong = check(&["glass", "dark.png", "--diff", "diff.png"]);
    assert_eq!(wrong.status.code(), Some(1));
    assert!(
        text(&wrong.stdout).contains("hint (no gamma)"),
        "{}",
        text(&wrong.stdout)
    );
    let diff = image::open(dir.path().join("diff.png")).unwrap().to_rgb8();
    assert!(
        diff.pixels().filter(|p| p.0 == [230, 30, 30]).count() > 1000,
        "differences painted red"
    );
    let not_an_image = check(&["glass", "note.png"]);
    assert_eq!(not_an_image.status.code(), Some(2));
    assert_eq!(
        text(&not_an_image.stderr).lines().count(),
        1,
        "one line: {}",
        text(&not_an_image.stderr)
    );
    assert_eq!(
        check(&["no-such-stage", "glass.png"]).status.code(),
        Some(2)
    );
    std::fs::rename(dir.path().join("dark.png"), dir.path().join("gamma.png")).unwrap();
    let graded = check(&["--all", "."]);
    let table = text(&graded.stdout);
    assert_eq!(graded.status.code(), Some(1), "{table}");
    assert!(
        table
            .lines()
            .any(|l| l.starts_with("glass") && l.contains("matches")),
        "{table}"
    );
    assert!(
        table
            .lines()
            .any(|l| l.starts_with("gamma") && l.contains("differs")),
        "{table}"
    );
    assert!(
        table
            .lines()
            .any(|l| l.starts_with("indirect") && l.contains("missing")),
        "{table}"
    );
    let sheet = std::fs::read_to_string(dir.path().join("grades.csv")).unwrap();
    assert_eq!(sheet.lines().count(), 1 + stages().count());
    assert!(
        sheet
            .lines()
            .next()
            .unwrap()
            .starts_with("stage,session,figure,verdict")
    );
    grades_a_class(&dir, &check);
}

/// `image` as a plain PPM (`P3`), the text a renderer in C++ writes by hand: a
/// header, a comment, then each pixel's three levels.
fn plain_ppm(image: &RgbImage) -> String {
    let (width, height) = image.dimensions();
    let mut text = format!("P3\n# written by hand\n{width} {height}\n255\n");
    for pixel in image.pixels() {
        let [r, g, b] = pixel.0;
        text.push_str(&format!("{r} {g} {b}\n"));
    }
    text
}

/// A PPM, plain (`P3`) or binary (`P6`), is read like a PNG: a right one matches, a
/// wrong one differs, and `--all` finds `STAGE.ppm`.
#[test]
fn ppm_images_are_checked_like_png_ones() {
    let dir = tempfile::tempdir().unwrap();
    let cache = cache();
    let glass = picture(&scene(stage("glass"), &same, 0, None));
    std::fs::write(dir.path().join("plain.ppm"), plain_ppm(&glass)).unwrap();
    let mut binary = vec![];
    let pixmap = PnmSubtype::Pixmap(SampleEncoding::Binary);
    PnmEncoder::new(&mut binary)
        .with_subtype(pixmap)
        .write_image(glass.as_raw(), SIZE, SIZE, ExtendedColorType::Rgb8)
        .unwrap();
    assert!(binary.starts_with(b"P6"));
    std::fs::write(dir.path().join("binary.ppm"), binary).unwrap();
    let dark = scene(stage("glass"), &|t| t.replace("gamma = 2.2\n", ""), 0, None);
    std::fs::write(dir.path().join("dark.ppm"), plain_ppm(&picture(&dark))).unwrap();
    let check = |args: &[&str]| check_in(dir.path(), &cache, args);
    for file in ["plain.ppm", "binary.ppm"] {
        let right = check(&["glass", file]);
        assert_eq!(
            right.status.code(),
            Some(0),
            "{file}: {}",
            text(&right.stdout)
        );
    }
    let wrong = check(&["glass", "dark.ppm"]);
    assert_eq!(wrong.status.code(), Some(1), "{}", text(&wrong.stdout));
    std::fs::rename(dir.path().join("plain.ppm"), dir.path().join("glass.ppm")).unwrap();
    let graded = check(&["--all", "."]);
    let table = text(&graded.stdout);
    assert!(
        table
            .lines()
            .any(|l| l.starts_with("glass") && l.contains("matches")),
        "{table}"
    );
}

/// `check` speaks French where the locale is French, with French decimal commas,
/// and `--lang` overrides the locale; the verdict and the exit code are the same in
/// both languages.
#[test]
fn the_report_follows_the_locale_or_lang() {
    let dir = tempfile::tempdir().unwrap();
    let cache = cache();
    let dark = scene(stage("glass"), &|t| t.replace("gamma = 2.2\n", ""), 0, None);
    picture(&dark).save(dir.path().join("dark.png")).unwrap();
    let check = |locale: &str, more: &[&str]| {
        let mut args = vec!["check", "-q", "--cache", cache.to_str().unwrap()];
        args.extend(["glass", "dark.png"]);
        args.extend(more);
        let output = run_in_locale(&args, dir.path(), locale);
        assert_eq!(output.status.code(), Some(1), "{}", text(&output.stdout));
        text(&output.stdout)
    };
    let french = check("fr_FR.UTF-8", &[]);
    assert!(french.starts_with("glass\u{a0}: diffère ("), "{french}");
    assert!(french.contains("  où\u{a0}: "), "{french}");
    let hint = "  indice (pas de gamma)\u{a0}: l'image semble affichée sans correction gamma";
    assert!(french.contains(hint), "{french}");
    assert!(
        french.contains("min(255, L^(1/2,2))"),
        "a decimal comma: {french}"
    );
    let english = check("fr_FR.UTF-8", &["--lang", "en"]);
    assert!(
        english.contains("  hint (no gamma): the image looks displayed"),
        "{english}"
    );
    let plain = check("C.UTF-8", &[]);
    assert_eq!(plain, english, "English without a French locale");
    assert_eq!(check("C.UTF-8", &["--lang", "fr"]), french);
}

/// A teacher's sheet is safe to open: a cell that a spreadsheet would run as a
/// formula (a student's folder named `=HYPERLINK(...)`) is written as text; and a
/// folder without any stage's image is refused, with no sheet written.
#[test]
fn a_sheet_shows_formulas_as_text_and_an_empty_folder_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let cache = cache();
    let student = dir.path().join("class").join("=HYPERLINK(\"x\")");
    std::fs::create_dir_all(&student).unwrap();
    picture(&scene(stage("shading"), &same, 0, None))
        .save(student.join("shading.png"))
        .unwrap();
    let check = |args: &[&str]| check_in(dir.path(), &cache, args);
    let graded = check(&["--all", "class"]);
    assert_eq!(graded.status.code(), Some(0), "{}", text(&graded.stderr));
    let sheet = std::fs::read_to_string(dir.path().join("class/grades.csv")).unwrap();
    let row = sheet.lines().nth(1).unwrap();
    assert!(row.starts_with("\"'=HYPERLINK(\"\"x\"\")\","), "{row}");
    std::fs::create_dir(dir.path().join("empty")).unwrap();
    std::fs::remove_file(dir.path().join("class/grades.csv")).unwrap();
    std::fs::remove_file(student.join("shading.png")).unwrap();
    for folder in ["empty", "class"] {
        let refused = check(&["--all", folder]);
        assert_eq!(
            refused.status.code(),
            Some(2),
            "{folder}: {}",
            text(&refused.stdout)
        );
        let said = text(&refused.stderr);
        assert!(said.contains("no image of a stage here"), "{said}");
        let refused = check(&["--all", folder, "--lang", "fr"]);
        let said = text(&refused.stderr);
        assert!(said.contains("aucune image d'une étape ici"), "{said}");
        assert_eq!(said.lines().count(), 1, "one line: {said}");
        assert!(!dir.path().join(folder).join("grades.csv").exists());
    }
}

/// An image that is not there, or not an image, is a bad input (exit code 2)
/// named by its file, in one line, in the language asked for.
#[test]
fn an_image_that_cannot_be_read_is_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("notes.png"), "not a picture").unwrap();
    for (file, language, words) in [
        ("nowhere.png", "en", "nowhere.png: cannot read the image: "),
        (
            "notes.png",
            "en",
            "notes.png: not a PNG, JPEG or PPM image that can be read: ",
        ),
        (
            "nowhere.png",
            "fr",
            "nowhere.png: impossible de lire l'image\u{a0}: ",
        ),
        (
            "notes.png",
            "fr",
            "notes.png: ce n'est pas une image PNG, JPEG ou PPM lisible\u{a0}: ",
        ),
    ] {
        let refused = check_in(dir.path(), &cache(), &["glass", file, "--lang", language]);
        assert_eq!(refused.status.code(), Some(2), "{file}");
        let said = text(&refused.stderr);
        assert!(said.contains(words), "{said}");
        assert_eq!(said.lines().count(), 1, "one line: {said}");
    }
}

/// `raycourse check -q --cache CACHE ARGS...`, run in `dir`.
fn check_in(dir: &Path, cache: &Path, args: &[&str]) -> std::process::Output {
    let mut all = vec!["check", "-q", "--cache", cache.to_str().unwrap()];
    all.extend(args);
    run(&all, dir)
}

/// A class: a folder of students' folders, graded into one sheet, a row per student.
fn grades_a_class(dir: &tempfile::TempDir, check: &dyn Fn(&[&str]) -> std::process::Output) {
    for (student, image) in [("alice", "glass.png"), ("bob", "gamma.png")] {
        let folder = dir.path().join("class").join(student);
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::copy(dir.path().join(image), folder.join("glass.png")).unwrap();
    }
    let graded = check(&["--all", "class"]);
    let table = text(&graded.stdout);
    assert_eq!(graded.status.code(), Some(1), "{table}");
    assert!(
        table
            .lines()
            .any(|l| l.starts_with("alice") && l.contains("1 of") && l.ends_with("differ: none")),
        "{table}"
    );
    assert!(
        table
            .lines()
            .any(|l| l.starts_with("bob") && l.ends_with("differ: glass")),
        "{table}"
    );
    let sheet = std::fs::read_to_string(dir.path().join("class/grades.csv")).unwrap();
    let lines: Vec<&str> = sheet.lines().collect();
    assert_eq!(lines.len(), 3, "{sheet}");
    assert!(
        lines[0].starts_with("student,white-disk,white-disk hint,"),
        "{sheet}"
    );
    let glass = lines[0].split(',').position(|c| c == "glass").unwrap();
    let cell = |row: &str, k: usize| row.split(',').nth(k).unwrap().to_owned();
    assert_eq!(
        (cell(lines[1], 0), cell(lines[1], glass)),
        ("alice".into(), "matches".into())
    );
    assert_eq!(
        (cell(lines[2], glass), cell(lines[2], glass + 1)),
        ("differs".into(), "no gamma".into())
    );
    assert_eq!(cell(lines[2], 1), "missing");
}
