//! Adaptive sampling: a pixel stops taking samples once the estimated error of its
//! mean is small enough.

use crate::maths::{Colour, Real};
use crate::render::samples::SampleMean;

/// With adaptive sampling, a pixel takes at most this many times the scene's sample
/// count.
pub const MOST_SAMPLES: u32 = 4;

/// The running mean of a pixel's samples and the sum of their squared luminances,
/// from which the variance of the samples is estimated.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Estimate {
    /// The mean of the finite samples, and how many were dropped.
    pub mean: SampleMean,
    /// The sum of the squared luminances of the finite samples.
    squares: Real,
}

impl Estimate {
    /// Adds one sample's radiance (a sample that is not finite is dropped, as
    /// [`SampleMean::add`] does).
    pub fn add(&mut self, sample: Colour) {
        if sample.is_finite() {
            self.squares += luminance(sample) * luminance(sample);
        }
        self.mean.add(sample);
    }

    /// The estimated relative standard error of the mean's luminance `m`:
    /// `sqrt(s^2 / n) / max(m, 1)`, with `s^2` the samples' variance. A pixel darker
    /// than 1 (of the 255 that show as white) is held to an absolute error instead.
    pub fn relative_error(&self) -> Real {
        let count = self.mean.count();
        if count < 2 {
            return Real::INFINITY;
        }
        let n = count as Real;
        let mean = luminance(self.mean.sum()) / n;
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

/// Whether adaptive sampling stops a pixel whose first `taken` samples have the
/// estimate `estimate`, in a scene of `samples` per pixel: at the end of a batch
/// whose relative error is at most `noise`. Never without adaptive sampling
/// (`noise` is `None`).
pub fn precise_enough(noise: Option<Real>, samples: u32, estimate: &Estimate, taken: u32) -> bool {
    noise.is_some_and(|noise| {
        taken.is_multiple_of(batch(samples)) && estimate.relative_error() <= noise
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_relative_error_is_the_standard_error_over_the_mean() {
        let mut estimate = Estimate::default();
        for v in [8.0, 12.0, 8.0, 12.0] {
            estimate.add(Colour::splat(v));
        }
        // Luminance weights sum to 1: samples 8, 12, 8, 12 have mean 10 and
        // variance 16/3; the standard error is sqrt(16/3/4) = 1.1547.
        let expected = (16.0 / 3.0 / 4.0 as Real).sqrt() / 10.0;
        assert!((estimate.relative_error() - expected).abs() < 1e-12);
        let mut dark = Estimate::default();
        dark.add(Colour::splat(0.0));
        assert_eq!(dark.relative_error(), Real::INFINITY);
        dark.add(Colour::splat(0.2));
        assert!(
            (dark.relative_error() - 0.1).abs() < 1e-12,
            "held to 1, not to 0.1"
        );
    }

    #[test]
    fn a_dropped_sample_counts_in_neither_the_mean_nor_the_variance() {
        let mut estimate = Estimate::default();
        for v in [8.0, Real::NAN, 12.0, 8.0, 12.0] {
            estimate.add(Colour::splat(v));
        }
        assert_eq!(estimate.mean.dropped, 1);
        let expected = (16.0 / 3.0 / 4.0 as Real).sqrt() / 10.0;
        assert!((estimate.relative_error() - expected).abs() < 1e-12);
    }
}
