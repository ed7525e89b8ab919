//! The figure of the book's chapter "Numbers at the extremes": the session-2 room
//! at three scales, each moved 1e4 from the origin, its shadow rays started with
//! the textbook's fixed epsilon (top row) and with the renderer's own offset,
//! which follows each hit's rounding error (bottom row).
//!
//! ```text
//! cargo run --release --example epsilon -- book/src/figures/epsilon.png
//! ```

use std::path::PathBuf;

use raycourse::geometry::{Hit, Ray};
use raycourse::lights::Light;
use raycourse::materials::Material;
use raycourse::maths::{Colour, Real, Vec3};
use raycourse::render::film::display;
use raycourse::studies::scale::scaled;
use raycourse::{Overrides, Scene, find_stage, parse_scene};

/// The fixed epsilon of the textbook renderer: right for a room 100 units wide.
const EPSILON: Real = 1e-4;

/// The scales shown, left to right.
const SCALES: [Real; 3] = [1e-6, 1.0, 1e9];

/// Width and height of each tile.
const TILE: u32 = 200;

/// How a shadow ray leaves the surface.
#[derive(Clone, Copy)]
enum Start {
    /// The course's way: `epsilon` along the normal, whatever the scene's size
    /// ([`Hit::spawn_with_epsilon`]).
    FixedEpsilon,
    /// Beyond the hit point's error bound ([`Hit::spawn`]).
    Robust,
}

/// Radiance seen through pixel (`row`, `column`): Lambert shading under the point
/// light, with a shadow ray started as `start` says.
fn shade(scene: &Scene, row: u32, column: u32, start: Start) -> Colour {
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
    let (shadow, distance) = match start {
        Start::FixedEpsilon => {
            let direction = (light.position - hit.point).normalize();
            let shadow = hit.spawn_with_epsilon(direction, EPSILON);
            (shadow, shadow.origin.distance(light.position))
        }
        Start::Robust => hit.spawn_towards(light.position),
    };
    if scene.occluded(&shadow, distance) {
        Colour::ZERO
    } else {
        light.lambert(hit.point, hit.normal, albedo)
    }
}

fn main() {
    let out = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "out/epsilon.png".into()),
    );
    let size = std::num::NonZeroU32::new(TILE);
    let overrides = Overrides {
        width: size,
        height: size,
        ..Overrides::default()
    };
    let room = find_stage(2, "shadows").expect("session 2 is built");
    let mut figure = image::RgbImage::new(TILE * SCALES.len() as u32, 2 * TILE);
    for (k, &scale) in SCALES.iter().enumerate() {
        let text = scaled(room.source, scale, Vec3::splat(1e4)).expect("the scene scales");
        let scene = parse_scene(&text, &room.file(), &overrides).expect("the scene loads");
        for (r, start) in [Start::FixedEpsilon, Start::Robust].into_iter().enumerate() {
            for row in 0..TILE {
                for column in 0..TILE {
                    let rgb = shade(&scene, row, column, start)
                        .to_array()
                        .map(|c| display(c, scene.settings.gamma));
                    let (x, y) = (k as u32 * TILE + column, r as u32 * TILE + row);
                    figure.put_pixel(x, y, image::Rgb(rgb));
                }
            }
        }
    }
    if let Some(folder) = out.parent() {
        std::fs::create_dir_all(folder).expect("output folder");
    }
    figure.save(&out).expect("PNG written");
    println!("{}", out.display());
}
