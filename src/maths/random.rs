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
    /// Numbers from another source: chosen in advance (a test that sets each
    /// decision), or spread evenly over the pixel's samples by a sampler.
    Given(Box<dyn NumberSource>),
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
        PixelRng::Given(numbers) => numbers.number(),
    }
}

/// Two numbers drawn from `[0, 1)` for one two-dimensional decision (a point on the
/// pixel, the lens or a hemisphere): with the course's generator, two independent
/// numbers.
#[inline]
pub fn uniform_pair(rng: &mut PixelRng) -> (Real, Real) {
    match rng {
        PixelRng::Independent(stream) => (stream.random::<Real>(), stream.random::<Real>()),
        PixelRng::Given(numbers) => numbers.pair(),
    }
}
// ANCHOR_END: uniform

/// A source of the numbers of a pixel's samples other than the pixel's own
/// generator. Every sample starts with [`start_sample`](NumberSource::start_sample);
/// each random decision of its path (where in the pixel, where on the lens, which
/// light direction, which bounce direction, whether the path goes on) then takes the
/// next number, or the next pair for a two-dimensional decision.
pub trait NumberSource: std::fmt::Debug + Send {
    /// Starts sample number `sample` of the pixel: a source whose numbers depend on
    /// the sample (spread over the pixel's samples) moves to it; by default nothing.
    fn start_sample(&mut self, _sample: u32) {}
    /// A number of `[0, 1)` for a one-dimensional decision.
    fn number(&mut self) -> Real;
    /// A point of `[0, 1)^2` for a two-dimensional decision.
    fn pair(&mut self) -> (Real, Real);
    /// A copy that draws the same numbers from here on.
    fn copy(&self) -> Box<dyn NumberSource>;
}

impl Clone for Box<dyn NumberSource> {
    fn clone(&self) -> Self {
        self.copy()
    }
}

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

    /// Numbers chosen in advance, drawn in order.
    #[derive(Clone, Debug)]
    struct Chosen(Vec<Real>);

    impl NumberSource for Chosen {
        fn number(&mut self) -> Real {
            self.0.remove(0)
        }
        fn pair(&mut self) -> (Real, Real) {
            (self.number(), self.number())
        }
        fn copy(&self) -> Box<dyn NumberSource> {
            Box::new(self.clone())
        }
    }

    #[test]
    fn given_numbers_are_drawn_in_order_and_a_copy_replays_them() {
        let mut rng = PixelRng::Given(Box::new(Chosen(vec![0.25, 0.5, 0.75])));
        assert_eq!(uniform(&mut rng), 0.25);
        let mut copy = rng.clone();
        assert_eq!(uniform_pair(&mut rng), (0.5, 0.75));
        assert_eq!(uniform_pair(&mut copy), (0.5, 0.75));
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
