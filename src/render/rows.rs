//! The render loop: every pixel's radiance, rows shared among threads.

use rayon::prelude::*;

use crate::integrator::Tracer;
use crate::maths::Colour;
use crate::render::Film;
use crate::scene::Scene;

// One pixel's radiance: the course's function of this build, which `raycourse probe`
// also runs.
#[cfg(not(feature = "s3"))]
pub use crate::render::pixel::pixel;
#[cfg(feature = "s3")]
pub use crate::render::samples::pixel;

/// A finished render: the film and how many rays it took.
#[derive(Clone, Debug, PartialEq)]
pub struct Render {
    /// Linear radiance of every pixel.
    pub film: Film,
    /// Rays traced: camera rays, shadow rays and secondary rays.
    pub rays: u64,
    /// The samples each pixel took, row by row: one before session 3, the scene's
    /// count after, more or fewer where adaptive sampling decides.
    pub samples: Vec<u32>,
    /// Samples whose radiance was NaN or infinite, left out of their pixel's mean.
    pub dropped: u64,
}

/// Renders `scene` on the current rayon thread pool: [`render_reporting`] with no
/// one to report to.
pub fn render(scene: &Scene) -> Render {
    render_reporting(scene, &|_| {})
}

// ANCHOR: render
/// Renders `scene` on the current rayon thread pool, row by row with
/// [`render_row`], calling `progress` with the number of samples per pixel at each
/// finished row (so that a bar of `height x samples` fills once).
pub fn render_reporting(scene: &Scene, progress: &(dyn Fn(u64) + Sync)) -> Render {
    render_rows(scene, progress, |row, line, taken| {
        render_row(scene, row, line, taken)
    })
}

/// Renders `scene` on the current rayon thread pool, one row per task:
/// `render_row(row, line, taken)` fills a row's pixels with their radiance (`line`)
/// and the samples each took (`taken`), and returns the rays it traced and the
/// samples it dropped. Each pixel depends only on the scene and its position, so the
/// image is the same whatever the number of threads.
pub fn render_rows(
    scene: &Scene,
    progress: &(dyn Fn(u64) + Sync),
    render_row: impl Fn(u32, &mut [Colour], &mut [u32]) -> (u64, u64) + Sync,
) -> Render {
    let camera = scene.camera;
    let width = camera.width as usize;
    let mut pixels = vec![Colour::ZERO; width * camera.height as usize];
    let mut samples = vec![0; pixels.len()];
    let (rays, dropped) = pixels
        .par_chunks_mut(width)
        .zip(samples.par_chunks_mut(width))
        .enumerate()
        .map(|(row, (line, taken))| {
            let counts = render_row(row as u32, line, taken);
            progress(u64::from(scene.settings.samples));
            counts
        })
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    Render {
        film: Film {
            width: camera.width,
            height: camera.height,
            pixels,
        },
        rays,
        samples,
        dropped,
    }
}
// ANCHOR_END: render

// ANCHOR: render_row
/// Renders row `row` of `scene` into `line` (each pixel's radiance) and `taken` (the
/// samples each took); returns the rays traced and the samples dropped.
pub fn render_row(scene: &Scene, row: u32, line: &mut [Colour], taken: &mut [u32]) -> (u64, u64) {
    let mut tracer = Tracer::new(scene);
    for (column, (value, taken)) in line.iter_mut().zip(taken).enumerate() {
        let before = tracer.samples;
        *value = pixel(&mut tracer, row, column as u32);
        *taken = (tracer.samples - before) as u32;
    }
    (tracer.rays, tracer.dropped)
}
// ANCHOR_END: render_row
