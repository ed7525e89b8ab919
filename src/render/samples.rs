//! One pixel from session 3 on: the mean of many random samples; beyond the course,
//! as many samples as the pixel needs.

use crate::geometry::Ray;
use crate::integrator::Tracer;
use crate::maths::{Colour, Real, pixel_sampler};
use crate::scene::Settings;
use crate::scene::sampling::MOST_SAMPLES;

/// The running mean of a pixel's samples. A sample that is not finite (a NaN from a
/// degenerate computation, an infinity) is dropped and counted, rather than
/// poisoning the pixel or being written as black.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SampleMean {
    sum: Colour,
    /// The sum of the squared luminances, for the variance.
    squares: Real,
    count: u32,
    /// Samples dropped so far.
    pub dropped: u32,
}

impl SampleMean {
    /// Adds one sample's radiance.
    pub fn add(&mut self, sample: Colour) {
        if sample.is_finite() {
            self.sum += sample;
            self.squares += luminance(sample) * luminance(sample);
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

    /// The estimated relative standard error of the mean's luminance `m`:
    /// `sqrt(s^2 / n) / max(m, 1)`, with `s^2` the samples' variance. A pixel darker
    /// than 1 (of the 255 that show as white) is held to an absolute error instead.
    pub fn relative_error(&self) -> Real {
        if self.count < 2 {
            return Real::INFINITY;
        }
        let n = self.count as Real;
        let mean = luminance(self.sum) / n;
        let variance = ((self.squares - n * mean * mean) / (n - 1.0)).max(0.0);
        (variance / n).sqrt() / mean.max(1.0)
    }
}

/// The luminance of a colour: `0.2126 R + 0.7152 G + 0.0722 B` (Rec. 709), the
/// brightness the eye sees.
pub fn luminance(colour: Colour) -> Real {
    0.2126 * colour.x + 0.7152 * colour.y + 0.0722 * colour.z
}

/// Adaptive sampling's batch: a pixel decides whether it has enough samples after
/// each batch. A quarter of the scene's count, rounded up to a power of two (so
/// that Sobol points stay evenly spread in each batch), and at least 2.
pub fn batch(samples: u32) -> u32 {
    (samples / 4).max(2).next_power_of_two()
}

// ANCHOR: samples
/// The radiance of each of the scene's samples of pixel (`row`, `column`), in order
/// (with adaptive sampling, up to [`MOST_SAMPLES`] times as many: the caller
/// stops).
pub fn pixel_samples<'t, 's>(
    tracer: &'t mut Tracer<'s>,
    row: u32,
    column: u32,
) -> impl Iterator<Item = Colour> + use<'t, 's> {
    let count = start_pixel(tracer, row, column);
    (0..count).map(move |i| {
        let ray = camera_sample(tracer, row, column, i);
        tracer.radiance(&ray, tracer.scene.settings.bounces)
    })
}

/// The radiance of pixel (`row`, `column`): the mean of its samples, those that
/// were not finite left out and counted in [`Tracer::dropped`]. With adaptive
/// sampling the pixel stops after the first batch whose mean is precise enough.
pub fn pixel(tracer: &mut Tracer, row: u32, column: u32) -> Colour {
    let settings = tracer.scene.settings;
    let mut mean = SampleMean::default();
    for (i, sample) in pixel_samples(tracer, row, column).enumerate() {
        mean.add(sample);
        if precise_enough(&settings, &mean, i as u32 + 1) {
            break;
        }
    }
    tracer.dropped += u64::from(mean.dropped);
    mean.mean()
}
// ANCHOR_END: samples

/// Gives `tracer` the random numbers of pixel (`row`, `column`), which come from the
/// scene's seed and the pixel's index alone, and returns how many samples the pixel
/// may take.
pub fn start_pixel(tracer: &mut Tracer, row: u32, column: u32) -> u32 {
    let scene = tracer.scene;
    let settings = scene.settings;
    let index = u64::from(row) * u64::from(scene.camera.width) + u64::from(column);
    let (count, block) = match settings.sampling.noise {
        None => (settings.samples, settings.samples),
        Some(_) => (settings.samples * MOST_SAMPLES, batch(settings.samples)),
    };
    tracer.rng = pixel_sampler(settings.sampling.sampler, settings.seed, index, block);
    count
}

/// The camera ray of sample `i` of pixel (`row`, `column`), counted in
/// [`Tracer::samples`]; the sample's random numbers start here.
pub fn camera_sample(tracer: &mut Tracer, row: u32, column: u32, i: u32) -> Ray {
    tracer.rng.start_sample(i);
    tracer.samples += 1;
    tracer.scene.camera.sample_ray(row, column, &mut tracer.rng)
}

/// Whether adaptive sampling stops a pixel whose first `taken` samples have the
/// mean `mean`: at the end of a batch whose relative error is at most the scene's
/// `noise`. Never without adaptive sampling.
pub fn precise_enough(settings: &Settings, mean: &SampleMean, taken: u32) -> bool {
    settings.sampling.noise.is_some_and(|noise| {
        taken.is_multiple_of(batch(settings.samples)) && mean.relative_error() <= noise
    })
}

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

    #[test]
    fn the_relative_error_is_the_standard_error_over_the_mean() {
        let mut mean = SampleMean::default();
        for v in [8.0, 12.0, 8.0, 12.0] {
            mean.add(Colour::splat(v));
        }
        // Luminance weights sum to 1: samples 8, 12, 8, 12 have mean 10 and
        // variance 16/3; the standard error is sqrt(16/3/4) = 1.1547.
        let expected = (16.0 / 3.0 / 4.0 as Real).sqrt() / 10.0;
        assert!((mean.relative_error() - expected).abs() < 1e-12);
        let mut dark = SampleMean::default();
        dark.add(Colour::splat(0.0));
        assert_eq!(dark.relative_error(), Real::INFINITY);
        dark.add(Colour::splat(0.2));
        assert!(
            (dark.relative_error() - 0.1).abs() < 1e-12,
            "held to 1, not to 0.1"
        );
    }
}
