//! Stratified numbers and Sobol points: each decision of a path spread evenly over
//! the samples of a pixel, rather than drawn independently.

use crate::maths::NumberSource;
use crate::maths::Real;
use crate::maths::random::pixel_hash;
use crate::samplers::sobol::{mix_bits, owen_scramble, permute, sobol_pair};
use crate::scene::beyond::Sampler;

/// The numbers of one pixel by a stratified or Sobol sampler: each decision is a
/// dimension, and the samples of a block take its points in a permuted order.
#[derive(Clone, Debug)]
pub struct Spread {
    /// Stratified or Sobol.
    sampler: Sampler,
    /// A hash of the scene's seed and the pixel's index.
    pixel: u64,
    /// The samples that are spread evenly together: the pixel's sample count, or the
    /// batch size of adaptive sampling.
    block: u32,
    /// The columns of the stratified sampler's grid of `block` cells.
    columns: u32,
    /// The number of the current sample.
    sample: u32,
    /// The next dimension of the current sample.
    dimension: u32,
}

impl Spread {
    /// The numbers of pixel number `pixel` for the scene seed `seed`, chosen by
    /// `sampler` (stratified or Sobol), spread evenly over each `block` of
    /// consecutive samples.
    pub fn new(sampler: Sampler, seed: u64, pixel: u64, block: u32) -> Spread {
        let block = block.max(1);
        Spread {
            sampler,
            pixel: pixel_hash(seed, pixel),
            block,
            columns: columns(block),
            sample: 0,
            dimension: 0,
        }
    }

    // ANCHOR: next_dimension
    /// The hash of the current dimension, and the sample's place among the `block`
    /// samples of its batch, permuted differently for every pixel, dimension and
    /// batch so that dimensions are not correlated.
    fn next_dimension(&mut self) -> (u64, u32) {
        let hash = mix_bits(self.pixel ^ u64::from(self.dimension).wrapping_mul(GOLDEN));
        self.dimension += 1;
        let (batch, place) = (self.sample / self.block, self.sample % self.block);
        let batch_hash = match batch {
            0 => hash,
            _ => mix_bits(hash ^ u64::from(batch)),
        };
        (
            hash,
            batch * self.block + permute(place, self.block, batch_hash),
        )
    }
    // ANCHOR_END: next_dimension

    /// A number of `[0, 1)` for the current sample and the dimension of `hash`: the
    /// place inside a stratum.
    fn jitter(&self, hash: u64) -> Real {
        unit((mix_bits(hash ^ mix_bits(u64::from(self.sample))) >> 32) as u32)
    }
}

impl NumberSource for Spread {
    fn start_sample(&mut self, sample: u32) {
        self.sample = sample;
        self.dimension = 0;
    }

    fn number(&mut self) -> Real {
        let (hash, index) = self.next_dimension();
        if self.sampler == Sampler::Stratified {
            stratum(index % self.block, self.block, self.jitter(hash))
        } else {
            unit(owen_scramble(index.reverse_bits(), hash))
        }
    }

    // ANCHOR: spread_pair
    fn pair(&mut self) -> (Real, Real) {
        let (hash, index) = self.next_dimension();
        if self.sampler == Sampler::Stratified {
            let (columns, cell) = (self.columns, index % self.block);
            let x = stratum(cell % columns, columns, self.jitter(hash));
            let y = stratum(
                cell / columns,
                self.block / columns,
                self.jitter(hash ^ GOLDEN),
            );
            (x, y)
        } else {
            let (x, y) = sobol_pair(index);
            (
                unit(owen_scramble(x, hash)),
                unit(owen_scramble(y, mix_bits(!hash))),
            )
        }
    }
    // ANCHOR_END: spread_pair

    fn copy(&self) -> Box<dyn NumberSource> {
        Box::new(self.clone())
    }
}

/// The point `jitter` of the way through stratum `k` of `count` equal strata of
/// `[0, 1)`.
fn stratum(k: u32, count: u32, jitter: Real) -> Real {
    ((k as Real + jitter) / count as Real).min(ONE_BELOW)
}

/// The number of columns of a grid of `count` strata: the largest divisor of
/// `count` not above its square root, so that the cells are as square as possible.
fn columns(count: u32) -> u32 {
    let root = (count as f64).sqrt() as u32;
    (1..=root.max(1))
        .rev()
        .find(|c| count.is_multiple_of(*c))
        .unwrap_or(1)
}

/// 2^64 divided by the golden ratio: an odd number whose multiples spread over all
/// 64 bits, to tell dimensions and coordinates apart before hashing.
const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;

/// The largest number below 1.
const ONE_BELOW: Real = 1.0 - Real::EPSILON / 2.0;

/// A 32-bit binary fraction as a number of `[0, 1)`.
fn unit(bits: u32) -> Real {
    (bits as Real * (0.5 as Real).powi(32)).min(ONE_BELOW)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_numbers_have_the_right_mean_and_range() {
        for sampler in [Sampler::Stratified, Sampler::Sobol] {
            let mut spread = Spread::new(sampler, 1, 2, 100);
            let n = 100_000;
            let values: Vec<Real> = (0..n)
                .map(|i| {
                    spread.start_sample(i);
                    spread.number()
                })
                .collect();
            assert!(values.iter().all(|v| (0.0..1.0).contains(v)));
            let mean = values.iter().sum::<Real>() / n as Real;
            // The standard error of the mean is sqrt(1/12 / n) = 0.0009.
            assert!((mean - 0.5).abs() < 0.004, "{sampler:?}: {mean}");
        }
    }

    /// The pairs of dimension `dimension` (after that many other decisions) of the
    /// first `count` samples of pixel `pixel`.
    fn pairs(sampler: Sampler, pixel: u64, count: u32, dimension: u32) -> Vec<(Real, Real)> {
        let mut spread = Spread::new(sampler, 3, pixel, count);
        (0..count)
            .map(|i| {
                spread.start_sample(i);
                for _ in 0..dimension {
                    spread.pair();
                }
                spread.pair()
            })
            .collect()
    }
    #[test]
    fn sobol_points_fill_every_elementary_interval_once() {
        for k in 0..=8 {
            let count = 1u32 << k;
            for (pixel, dimension) in [(0, 0), (5, 1), (77, 3)] {
                let points = pairs(Sampler::Sobol, pixel, count, dimension);
                for i in 0..=k {
                    let (nx, ny) = (1u32 << i, 1u32 << (k - i));
                    let mut cells = vec![0; count as usize];
                    for &(x, y) in &points {
                        let cell = (y * ny as Real) as u32 * nx + (x * nx as Real) as u32;
                        cells[cell as usize] += 1;
                    }
                    assert!(
                        cells.iter().all(|&c| c == 1),
                        "{count} points, boxes {nx}x{ny}, pixel {pixel}, dimension {dimension}"
                    );
                }
            }
        }
    }

    #[test]
    fn stratified_pairs_fill_every_cell_of_their_grid_once() {
        for count in [1, 7, 12, 64, 100] {
            let columns = columns(count);
            let rows = count / columns;
            let mut cells = vec![0; count as usize];
            for (x, y) in pairs(Sampler::Stratified, 9, count, 2) {
                cells[((y * rows as Real) as u32 * columns + (x * columns as Real) as u32)
                    as usize] += 1;
            }
            assert!(cells.iter().all(|&c| c == 1), "{count}: {cells:?}");
        }
    }

    #[test]
    fn every_pixel_and_dimension_is_scrambled_differently() {
        let first = pairs(Sampler::Sobol, 0, 16, 0);
        assert_ne!(first, pairs(Sampler::Sobol, 1, 16, 0));
        assert_ne!(first, pairs(Sampler::Sobol, 0, 16, 1));
        assert_ne!(
            pairs(Sampler::Stratified, 0, 16, 0),
            pairs(Sampler::Stratified, 1, 16, 0)
        );
    }
}
