//! The book's comparison figures, each made of renders of the crate side by side
//! with a label above each panel, written twice from the same renders: with English
//! labels into the output folder, and with French ones into its `fr/` folder, for
//! the French edition:
//!
//! - `antialiasing.png`: the edge of the sphere, magnified, without and with the
//!   Gaussian jitter of session 3 (crops of the figures `indirect` and `antialiasing`);
//! - `glass-shadow.png`: the glass ball with and without shadow rays: the dark patch
//!   at its top is its own shadow on the floor, seen upside down through it;
//! - `smooth-normals.png`: Spot's head under a dimmer light and direct light only, so
//!   that nothing is clipped to white, with flat and with smooth normals;
//! - `roulette.png`: the room with 2 bounces, with 2 bounces and Russian roulette,
//!   and with 5 bounces;
//! - `texture-gamma.png`: the textured cow with its texture read as the display shows
//!   it and, wrongly, as if its values were linear;
//! - `epsilon.png`: the session-2 room at three scales, its shadow rays started with
//!   the course's fixed epsilon (top) and with the renderer's own offset (bottom);
//! - `cost.png`: the tests each camera ray takes in the stages `mesh`, `mesh-bbox`
//!   and `bvh` (`--aov cost`), each labelled with its mean.
//!
//! ```text
//! cargo run --release -p raycourse-book-figures -- book/src/figures/compare
//! ```

use std::num::NonZeroU32;
use std::path::{Path, PathBuf};

use image::{Rgb, RgbImage, imageops};
use plotters::prelude::*;
use plotters::style::FontStyle;
use raycourse::geometry::{Hit, Ray};
use raycourse::inspect::aov::{Aov, see};
use raycourse::lights::Light;
use raycourse::materials::Material;
use raycourse::maths::{Colour, Real, Vec3};
use raycourse::messages::catalogue::{Catalogue, with_own};
use raycourse::messages::language::Language;
use raycourse::messages::said::Said;
use raycourse::render::film::display;
use raycourse::studies::scale::scaled;
use raycourse::{Overrides, Scene, encode_png, find_stage, parse_scene, render};

/// Height of the band above each panel that holds its label.
const BAND: u32 = 28;

/// DejaVu Sans (see `assets/fonts/DejaVuSans.LICENSE`).
const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// The image of stage `name` of `session` at `size` x `size` pixels, its scene file
/// first changed by `edit`.
fn render_stage(session: u32, name: &str, size: u32, edit: &dyn Fn(&str) -> String) -> RgbImage {
    let stage = find_stage(session, name).expect("the stage is in this build");
    let overrides = Overrides {
        width: NonZeroU32::new(size),
        height: NonZeroU32::new(size),
        ..Overrides::default()
    };
    let scene = parse_scene(&edit(stage.source), &stage.file(), &overrides).expect("loads");
    let png = encode_png(&render(&scene).film, scene.settings.gamma);
    image::load_from_memory(&png).expect("a PNG").to_rgb8()
}

/// A panel's label: a message of the book's catalogue (`messages/*/book.ftl`),
/// said in each edition's language.
type Label = Said;

/// The label of the message `id`, without arguments.
fn say(id: &'static str) -> Label {
    Said::new(id)
}

/// The book's own messages, beside the library's: `messages/<code>/book.ftl`.
const BOOK: [(Language, &str); 2] = [
    (
        Language::English,
        include_str!("../../messages/en/book.ftl"),
    ),
    (Language::French, include_str!("../../messages/fr/book.ftl")),
];

/// The catalogue of `language`: the library's files and the book's.
fn catalogue(language: Language) -> Catalogue {
    with_own(language, "book.ftl", &BOOK)
}

/// A figure: rows of labelled panels, the rows one above the other.
type Figure = Vec<Vec<(Label, RgbImage)>>;

/// `figure` with its labels from `catalogue`: each row's panels side by
/// side, each under its label, with a white gap between them.
fn compose(figure: &Figure, catalogue: &Catalogue) -> RgbImage {
    let rows: Vec<RgbImage> = figure
        .iter()
        .map(|row| side_by_side(row, catalogue))
        .collect();
    let mut out = RgbImage::from_pixel(
        rows[0].width(),
        rows.iter().map(|r| r.height()).sum(),
        Rgb([255; 3]),
    );
    let mut y = 0;
    for row in &rows {
        imageops::replace(&mut out, row, 0, i64::from(y));
        y += row.height();
    }
    out
}

/// `panels` side by side, each under its label from `catalogue`, with a
/// white gap between them.
fn side_by_side(panels: &[(Label, RgbImage)], catalogue: &Catalogue) -> RgbImage {
    let (w, h) = panels[0].1.dimensions();
    let gap = 8;
    let width = panels.len() as u32 * (w + gap) - gap;
    let mut out = RgbImage::from_pixel(width, h + BAND, Rgb([255, 255, 255]));
    for (k, (_, panel)) in panels.iter().enumerate() {
        imageops::replace(
            &mut out,
            panel,
            i64::from(k as u32 * (w + gap)),
            i64::from(BAND),
        );
    }
    let labels: Vec<(String, u32)> = panels
        .iter()
        .enumerate()
        .map(|(k, (label, _))| (label.say_from(catalogue), k as u32 * (w + gap)))
        .collect();
    label(&mut out, &labels);
    out
}

/// Writes each `(text, x)` of `labels` in the band at the top of `image`.
fn label(image: &mut RgbImage, labels: &[(String, u32)]) {
    plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
        .unwrap_or_else(|_| panic!("the built-in font is a valid TrueType font"));
    let (w, h) = image.dimensions();
    let root = BitMapBackend::with_buffer(image.as_mut(), (w, h)).into_drawing_area();
    for (text, x) in labels {
        let style = ("sans-serif", 18).into_font().color(&BLACK);
        root.draw_text(text, &style, (*x as i32 + 4, 5))
            .expect("text fits the image");
    }
    root.present().expect("drawn into memory");
}

/// A `size` x `size` crop of `image` at `(x, y)`, magnified `zoom` times with
/// nearest-neighbour so that pixels show as squares.
fn magnified(image: &RgbImage, (x, y): (u32, u32), size: u32, zoom: u32) -> RgbImage {
    let crop = imageops::crop_imm(image, x, y, size, size).to_image();
    imageops::resize(
        &crop,
        size * zoom,
        size * zoom,
        imageops::FilterType::Nearest,
    )
}

/// The edge of the sphere without and with antialiasing, from the book's figures.
fn antialiasing(figures: &Path) -> Figure {
    let open = |name: &str| image::open(figures.join(name)).expect("a figure").to_rgb8();
    let corner = (300, 190);
    vec![vec![
        (
            say("figure-without-antialiasing"),
            magnified(&open("indirect.png"), corner, 64, 4),
        ),
        (
            say("figure-with-antialiasing"),
            magnified(&open("antialiasing.png"), corner, 64, 4),
        ),
    ]]
}

/// The glass ball with its shadow rays, and without.
fn glass_shadow() -> Figure {
    let same = |text: &str| text.to_owned();
    let off = |text: &str| text.replace("shadows = true", "shadows = false");
    vec![vec![
        (
            say("figure-with-shadow-rays"),
            render_stage(2, "glass", 256, &same),
        ),
        (
            say("figure-without-shadow-rays"),
            render_stage(2, "glass", 256, &off),
        ),
    ]]
}

/// Spot under a light five times dimmer and direct light only, so that its
/// shading follows its normals, flat and smooth, magnified on its head.
fn smooth_normals() -> Figure {
    let dim = |text: &str| {
        text.replace("intensity = 2e10", "intensity = 4e9")
            .replace("indirect = true", "indirect = false")
    };
    let head = (96, 64);
    vec![vec![
        (
            say("figure-flat-normals"),
            magnified(&render_stage(6, "bvh", 320, &dim), head, 128, 2),
        ),
        (
            say("figure-smooth-normals"),
            magnified(&render_stage(6, "smooth-normals", 320, &dim), head, 128, 2),
        ),
    ]]
}

/// The room with a bounce limit of 2, with Russian roulette past it, and with 5.
fn roulette() -> Figure {
    let limit = |text: &str| text.replace("russian_roulette = 0.7\n", "");
    let deep = |text: &str| limit(text).replace("bounces = 2", "bounces = 5");
    let same = |text: &str| text.to_owned();
    vec![vec![
        (
            Said::new("figure-bounces").with("bounces", 2u64),
            render_stage(4, "russian-roulette", 192, &limit),
        ),
        (
            Said::new("figure-bounces-and-roulette").with("bounces", 2u64),
            render_stage(4, "russian-roulette", 192, &same),
        ),
        (
            Said::new("figure-bounces").with("bounces", 5u64),
            render_stage(4, "russian-roulette", 192, &deep),
        ),
    ]]
}

/// The textured cow, its texture linearised as it should be and, wrongly, not: the
/// texture given to the second render holds `255 (v / 255)^(1 / 2.2)`, which the
/// renderer's conversion turns back into `v / 255`, the value a renderer that forgot
/// the conversion would use.
fn texture_gamma(scratch: &Path) -> Figure {
    let texture = image::open("assets/spot/spot_texture.png")
        .expect("the texture")
        .to_rgb8();
    let brightened = RgbImage::from_fn(texture.width(), texture.height(), |x, y| {
        let v = texture.get_pixel(x, y).0;
        Rgb(v.map(|c| (255.0 * (f64::from(c) / 255.0).powf(1.0 / 2.2)).round() as u8))
    });
    let file = scratch.join("spot_texture_linear.png");
    brightened.save(&file).expect("scratch file written");
    let wrong = move |text: &str| {
        text.replace(
            "textured = true",
            &format!("textured = true\ntexture = {:?}", file),
        )
    };
    let same = |text: &str| text.to_owned();
    let body = (72, 72);
    vec![vec![
        (
            say("figure-converted-to-linear"),
            magnified(&render_stage(7, "textures", 320, &same), body, 160, 2),
        ),
        (
            say("figure-used-as-it-is"),
            magnified(&render_stage(7, "textures", 320, &wrong), body, 160, 2),
        ),
    ]]
}

fn main() {
    let out = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "out/compare".into()),
    );
    let figures = Path::new("book/src/figures");
    std::fs::create_dir_all(&out).expect("output folder");
    let scratch = tempfile_dir();
    let made = [
        ("antialiasing.png", antialiasing(figures)),
        ("glass-shadow.png", glass_shadow()),
        ("smooth-normals.png", smooth_normals()),
        ("roulette.png", roulette()),
        ("texture-gamma.png", texture_gamma(&scratch)),
        ("epsilon.png", epsilon::figure()),
        ("cost.png", cost()),
    ];
    std::fs::create_dir_all(out.join("fr")).expect("output folder");
    for (name, figure) in made {
        for (language, folder) in [
            (Language::English, out.clone()),
            (Language::French, out.join("fr")),
        ] {
            let image = compose(&figure, &catalogue(language));
            let png =
                raycourse::render::png::encode_rgb8(image.as_raw(), image.width(), image.height());
            std::fs::write(folder.join(name), png).expect("figure written");
            println!("{}", folder.join(name).display());
        }
    }
    std::fs::remove_dir_all(scratch).expect("scratch folder removed");
}

/// The three mesh stages' images of cost (`--aov cost`), each labelled with its
/// mean: the tests a camera ray takes, from brute force to the BVH.
fn cost() -> Figure {
    let panels = [
        (5, "mesh", "brute-force"),
        (5, "mesh-bbox", "box"),
        (6, "bvh", "bvh"),
    ]
    .into_iter()
    .map(|(session, name, search)| {
        let stage = find_stage(session, name).expect("the stage is in this build");
        let overrides = Overrides {
            width: NonZeroU32::new(256),
            height: NonZeroU32::new(256),
            ..Overrides::default()
        };
        let scene = stage.scene(&overrides).expect("loads");
        let seen = see(&scene, Aov::Cost);
        let mean = seen.mean.expect("every ray costs something");
        let image = RgbImage::from_raw(seen.width, seen.height, seen.rgb).expect("the size");
        // The mean's one decimal as Rust rounds it; the catalogue writes it.
        let mean: f64 = format!("{mean:.1}").parse().expect("a number");
        let label = Said::new("figure-cost")
            .with("search", search)
            .with("mean", mean);
        (label, image)
    })
    .collect();
    vec![panels]
}

/// A fresh scratch folder.
fn tempfile_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raycourse-figures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

/// The room at three scales, its shadow rays started with the course's fixed
/// epsilon (top row) and with the renderer's own offset, which follows each hit's
/// rounding error (bottom row).
mod epsilon {
    use super::*;

    /// The course's fixed epsilon: right for a room about 100 units wide.
    const EPSILON: Real = 1e-4;

    /// The scales shown, left to right, with their labels.
    const SCALES: [(Real, &str); 3] = [(1e-6, "1e-6"), (1.0, "1"), (1e11, "1e11")];

    /// Width and height of each tile.
    const TILE: u32 = 200;

    /// Radiance seen through pixel (`row`, `column`): Lambert shading under the
    /// point light, with a shadow ray started `epsilon` along the normal if
    /// `fixed`, else beyond the hit point's error bound ([`Hit::spawn`]).
    fn shade(scene: &Scene, row: u32, column: u32, fixed: bool) -> Colour {
        let ray = Ray::new(
            scene.camera.position,
            scene.camera.pixel_direction(row, column),
        );
        let (Some(hit), Some(Light::Point(light))) = (scene.intersect(&ray), scene.light) else {
            return Colour::ZERO;
        };
        let hit: Hit = hit.facing_the_ray();
        let Material::Diffuse { albedo } = hit.material else {
            return Colour::ZERO;
        };
        let (shadow, distance) = if fixed {
            let direction = (light.position - hit.point).normalize();
            let shadow = hit.spawn_with_epsilon(direction, EPSILON);
            (shadow, shadow.origin.distance(light.position))
        } else {
            hit.spawn_towards(light.position)
        };
        if scene.occluded(&shadow, distance) {
            Colour::ZERO
        } else {
            light.lambert(hit.point, hit.normal, albedo)
        }
    }

    /// One tile: the room scaled by `scale` and moved 1e4, shaded as `fixed` says.
    fn tile(scale: Real, fixed: bool) -> RgbImage {
        let room = find_stage(2, "shadows").expect("session 2 is built");
        let overrides = Overrides {
            width: NonZeroU32::new(TILE),
            height: NonZeroU32::new(TILE),
            ..Overrides::default()
        };
        let text = scaled(room.source, scale, Vec3::splat(1e4)).expect("the scene scales");
        let scene = parse_scene(&text, &room.file(), &overrides).expect("the scene loads");
        RgbImage::from_fn(TILE, TILE, |column, row| {
            let colour = shade(&scene, row, column, fixed);
            Rgb(colour.to_array().map(|c| display(c, scene.settings.gamma)))
        })
    }

    /// The two rows, one above the other.
    pub fn figure() -> Figure {
        let row = |fixed: bool, offset: &'static str| {
            SCALES
                .iter()
                .map(|(scale, text)| {
                    let label = Said::new("figure-at-scale")
                        .with("offset", offset)
                        .with("scale", *text);
                    (label, tile(*scale, fixed))
                })
                .collect()
        };
        vec![row(true, "fixed"), row(false, "bound")]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A label in each edition's language, its number written by the catalogue:
    /// a point and no grouping in English, a decimal comma and thousands in French.
    #[test]
    fn labels_are_the_catalogue_s_in_each_language() {
        let cost = Said::new("figure-cost")
            .with("search", "brute-force")
            .with("mean", 5863.0);
        let english = cost.say_from(&catalogue(Language::English));
        assert_eq!(english, "brute force: 5863.0 tests a ray");
        let french = cost.say_from(&catalogue(Language::French));
        assert_eq!(french, "force brute\u{a0}: 5\u{202f}863,0 tests");
        let two = Said::new("figure-bounces").with("bounces", 2u64);
        assert_eq!(two.say_from(&catalogue(Language::French)), "2 rebonds");
    }
}
