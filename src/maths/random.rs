//! The random numbers of a pixel's samples. Each pixel draws from a generator of its
//! own, seeded from the scene's seed and the pixel's index, so that an image does
//! not depend on which thread renders which pixel.

use rand::{RngExt, SeedableRng};

use crate::maths::Real;

// ANCHOR: pixel_rng
/// The random numbers of one pixel. A copy draws the same numbers as the original
/// from where it was made, which is how `raycourse probe` replays part of a path.
#[derive(Clone, Debug)]
pub enum PixelRng {
    /// Independent numbers from a generator seeded by the pixel: the course's.
    Independent(rand_pcg::Pcg64Mcg),
    /// Numbers that a sampler beyond the course spreads evenly over the pixel's
    /// samples (`src/samplers/`).
    #[cfg(feature = "beyond")]
    Spread(Box<dyn crate::maths::spread::SpreadNumbers>),
}

/// The independent random numbers of pixel number `pixel` (row-major from the
/// top-left) for the scene seed `seed`. Their stream depends on nothing else, so
/// whichever thread renders the pixel draws the same numbers.
pub fn pixel_rng(seed: u64, pixel: u64) -> PixelRng {
    PixelRng::Independent(rand_pcg::Pcg64Mcg::seed_from_u64(pixel_hash(seed, pixel)))
}

/// The seed and the pixel's index mixed by SplitMix64, so that neighbouring pixels
/// and seeds get unrelated streams.
pub fn pixel_hash(seed: u64, pixel: u64) -> u64 {
    splitmix64(seed ^ splitmix64(pixel))
}
// ANCHOR_END: pixel_rng

// ANCHOR: uniform
/// A number drawn from `[0, 1)`: with the course's generator, the next number of
/// the pixel's stream.
#[inline]
pub fn uniform(rng: &mut PixelRng) -> Real {
    match rng {
        PixelRng::Independent(stream) => stream.random::<Real>(),
        #[cfg(feature = "beyond")]
        PixelRng::Spread(numbers) => numbers.number(),
    }
}

/// Two numbers drawn from `[0, 1)` for one two-dimensional decision (a point on the
/// pixel, the lens or a hemisphere): with the course's generator, two independent
/// numbers.
#[inline]
pub fn uniform_pair(rng: &mut PixelRng) -> (Real, Real) {
    match rng {
        PixelRng::Independent(stream) => (stream.random::<Real>(), stream.random::<Real>()),
        #[cfg(feature = "beyond")]
        PixelRng::Spread(numbers) => numbers.pair(),
    }
}
// ANCHOR_END: uniform

// ANCHOR: splitmix64
/// SplitMix64's finaliser: a bijection of `u64` that scatters nearby inputs.
fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
// ANCHOR_END: splitmix64

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_pixel_same_stream_other_pixel_other_stream() {
        let draw = |seed, pixel| {
            let mut rng = pixel_rng(seed, pixel);
            [uniform(&mut rng), uniform(&mut rng)]
        };
        assert_eq!(draw(7, 1000), draw(7, 1000));
        assert_ne!(draw(7, 1000), draw(7, 1001));
        assert_ne!(draw(7, 1000), draw(8, 1000));
        assert_ne!(
            draw(0, 1),
            draw(1, 0),
            "seed and pixel are not interchangeable"
        );
    }

    #[test]
    fn uniform_numbers_have_the_right_mean_and_range() {
        let mut rng = pixel_rng(1, 2);
        let n = 100_000;
        let values: Vec<Real> = (0..n).map(|_| uniform(&mut rng)).collect();
        assert!(values.iter().all(|v| (0.0..1.0).contains(v)));
        let mean = values.iter().sum::<Real>() / n as Real;
        // The standard error of the mean is sqrt(1/12 / n) = 0.0009.
        assert!((mean - 0.5).abs() < 0.004, "{mean}");
    }
}
