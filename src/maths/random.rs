//! One random generator per pixel, so images do not depend on the thread count.

use rand::{RngExt, SeedableRng};

use crate::maths::Real;

/// The random generator of one pixel: a small, fast PCG (64-bit output, 128-bit state).
pub type PixelRng = rand_pcg::Pcg64Mcg;

// ANCHOR: pixel_rng
/// The generator of pixel number `pixel` (row-major from the top-left) for the scene
/// seed `seed`. Its stream depends on nothing else, so whichever thread renders the
/// pixel draws the same numbers. The two numbers are mixed by SplitMix64 so that
/// neighbouring pixels and seeds get unrelated streams.
pub fn pixel_rng(seed: u64, pixel: u64) -> PixelRng {
    PixelRng::seed_from_u64(splitmix64(seed ^ splitmix64(pixel)))
}
// ANCHOR_END: pixel_rng

/// A number drawn uniformly from `[0, 1)`.
pub fn uniform(rng: &mut PixelRng) -> Real {
    rng.random::<Real>()
}

/// SplitMix64's finaliser: a bijection of `u64` that scatters nearby inputs.
fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

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
