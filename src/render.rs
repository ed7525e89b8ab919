//! The renderer: every pixel's radiance, rows shared among threads.

use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::film::Film;
use crate::math::{Colour, Real};
use crate::radiance::Tracer;
use crate::scene::Scene;

/// A finished render: the film and how many rays it took.
#[derive(Clone, Debug, PartialEq)]
pub struct Render {
    /// Linear radiance of every pixel.
    pub film: Film,
    /// Rays traced: camera rays, shadow rays and secondary rays.
    pub rays: u64,
}

// ANCHOR: pixel
/// The radiance of pixel (`row`, `column`): the mean of the scene's samples per pixel.
pub fn pixel(tracer: &mut Tracer, row: u32, column: u32) -> Colour {
    let scene = tracer.scene;
    let samples = scene.settings.samples;
    let mut sum = Colour::ZERO;
    for _ in 0..samples {
        let ray = scene.camera.primary_ray(row, column);
        sum += tracer.radiance(&ray, scene.settings.bounces);
    }
    sum / samples as Real
}
// ANCHOR_END: pixel

// ANCHOR: render
/// Renders `scene` on the current rayon thread pool, one row per task, ticking
/// `progress` once per row. Each pixel depends only on the scene and its position,
/// so the image is the same whatever the number of threads.
pub fn render(scene: &Scene, progress: &ProgressBar) -> Render {
    let camera = scene.camera;
    let width = camera.width as usize;
    let mut pixels = vec![Colour::ZERO; width * camera.height as usize];
    let rays = pixels
        .par_chunks_mut(width)
        .enumerate()
        .map(|(row, line)| {
            let mut tracer = Tracer::new(scene);
            for (column, value) in line.iter_mut().enumerate() {
                *value = pixel(&mut tracer, row as u32, column as u32);
            }
            progress.inc(1);
            tracer.rays
        })
        .sum();
    Render {
        film: Film {
            width: camera.width,
            height: camera.height,
            pixels,
        },
        rays,
    }
}
// ANCHOR_END: render
