//! One pixel from session 3 on: the mean of many random samples.

use crate::integrator::Tracer;
use crate::maths::{Colour, Real, pixel_rng};

// ANCHOR: sample_mean
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

    /// The sum of the finite samples.
    pub fn sum(&self) -> Colour {
        self.sum
    }

    /// How many samples were finite.
    pub fn count(&self) -> u32 {
        self.count
    }
}
// ANCHOR_END: sample_mean

// ANCHOR: samples
/// The radiance of pixel (`row`, `column`): the mean of its samples
/// ([`pixel_samples`]). Samples that are not finite are left out and counted in
/// [`Tracer::dropped`].
pub fn pixel(tracer: &mut Tracer, row: u32, column: u32) -> Colour {
    let mut mean = SampleMean::default();
    for sample in pixel_samples(tracer, row, column) {
        mean.add(sample);
    }
    tracer.dropped += u64::from(mean.dropped);
    mean.mean()
}

/// The radiance of each of the scene's samples of pixel (`row`, `column`), in
/// order: each the radiance of one path started by a camera ray through a random
/// point of the pixel ([`sample_ray`](crate::camera::Camera::sample_ray)). The
/// random numbers come from the pixel's own generator.
pub fn pixel_samples(tracer: &mut Tracer, row: u32, column: u32) -> impl Iterator<Item = Colour> {
    let scene = tracer.scene;
    let index = u64::from(row) * u64::from(scene.camera.width) + u64::from(column);
    tracer.rng = pixel_rng(scene.settings.seed, index);
    (0..scene.settings.samples).map(move |_| {
        tracer.samples += 1;
        let ray = scene.camera.sample_ray(row, column, &mut tracer.rng);
        tracer.radiance(&ray, scene.settings.bounces)
    })
}
// ANCHOR_END: samples

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
