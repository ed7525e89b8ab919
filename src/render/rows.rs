//! The renderer: every pixel's radiance, rows shared among threads.

use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::integrator::radiance::Tracer;
use crate::maths::numbers::{Colour, Real};
use crate::maths::random::pixel_rng;
use crate::render::film::Film;
use crate::scene::objects::Scene;

/// A finished render: the film and how many rays it took.
#[derive(Clone, Debug, PartialEq)]
pub struct Render {
    /// Linear radiance of every pixel.
    pub film: Film,
    /// Rays traced: camera rays, shadow rays and secondary rays.
    pub rays: u64,
    /// Samples whose radiance was NaN or infinite, left out of their pixel's mean.
    pub dropped: u64,
}

/// The running mean of a pixel's samples. A sample that is not finite (a NaN from a
/// degenerate computation, an infinity) is dropped and counted, rather than
/// poisoning the pixel or being written as black.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SampleMean {
    sum: Colour,
    count: u32,
    /// Samples dropped so far.
    pub dropped: u32,
}

impl SampleMean {
    /// Adds one sample's radiance.
    pub fn add(&mut self, sample: Colour) {
        if sample.is_finite() {
            self.sum += sample;
            self.count += 1;
        } else {
            self.dropped += 1;
        }
    }

    /// The mean of the finite samples, black if there were none.
    pub fn mean(&self) -> Colour {
        if self.count == 0 {
            Colour::ZERO
        } else {
            self.sum / self.count as Real
        }
    }
}

// ANCHOR: pixel
/// The radiance of each of the scene's samples of pixel (`row`, `column`), in order.
/// The pixel's random generator is seeded from the scene's seed and the pixel's
/// index alone.
pub fn pixel_samples<'t, 's>(
    tracer: &'t mut Tracer<'s>,
    row: u32,
    column: u32,
) -> impl Iterator<Item = Colour> + use<'t, 's> {
    let scene = tracer.scene;
    let index = u64::from(row) * u64::from(scene.camera.width) + u64::from(column);
    tracer.rng = pixel_rng(scene.settings.seed, index);
    (0..scene.settings.samples).map(move |_| {
        let ray = scene.camera.ray(row, column, &mut tracer.rng);
        tracer.radiance(&ray, scene.settings.bounces)
    })
}

/// The samples of pixel (`row`, `column`), averaged.
pub fn pixel(tracer: &mut Tracer, row: u32, column: u32) -> SampleMean {
    let mut mean = SampleMean::default();
    pixel_samples(tracer, row, column).for_each(|sample| mean.add(sample));
    mean
}
// ANCHOR_END: pixel

// ANCHOR: render
/// Renders `scene` on the current rayon thread pool, one row per task, ticking
/// `progress` by the number of samples per pixel at each finished row (so a bar of
/// `height x samples` fills once). Each pixel depends only on the scene and its position,
/// so the image is the same whatever the number of threads.
pub fn render(scene: &Scene, progress: &ProgressBar) -> Render {
    let camera = scene.camera;
    let width = camera.width as usize;
    let mut pixels = vec![Colour::ZERO; width * camera.height as usize];
    let (rays, dropped) = pixels
        .par_chunks_mut(width)
        .enumerate()
        .map(|(row, line)| {
            let mut tracer = Tracer::new(scene);
            let mut dropped = 0;
            for (column, value) in line.iter_mut().enumerate() {
                let mean = pixel(&mut tracer, row as u32, column as u32);
                *value = mean.mean();
                dropped += u64::from(mean.dropped);
            }
            progress.inc(u64::from(scene.settings.samples));
            (tracer.rays, dropped)
        })
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    Render {
        film: Film {
            width: camera.width,
            height: camera.height,
            pixels,
        },
        rays,
        dropped,
    }
}
// ANCHOR_END: render

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_samples_are_dropped_and_counted() {
        let mut mean = SampleMean::default();
        mean.add(Colour::splat(2.0));
        mean.add(Colour::new(Real::NAN, 0.0, 0.0));
        mean.add(Colour::splat(4.0));
        mean.add(Colour::new(0.0, Real::INFINITY, 0.0));
        assert_eq!(mean.mean(), Colour::splat(3.0));
        assert_eq!(mean.dropped, 2);
        let mut none = SampleMean::default();
        none.add(Colour::splat(Real::NAN));
        assert_eq!(none.mean(), Colour::ZERO);
    }
}
