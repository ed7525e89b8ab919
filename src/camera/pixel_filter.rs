//! Where in its pixel a camera ray aims: the centre, or a point drawn around it.

use crate::maths::sampling::sample_gaussian;
use crate::maths::{PixelRng, Real, uniform_pair};

/// Where in its pixel a camera ray aims.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum PixelFilter {
    /// At the centre: one ray per pixel is enough, and edges are jagged.
    #[default]
    Centre,
    /// At a point scattered around the centre with a Gaussian of standard deviation
    /// `sigma` pixels: averaging many samples smooths the edges (antialiasing).
    Gaussian {
        /// Standard deviation, in pixels.
        sigma: Real,
    },
}

impl PixelFilter {
    // ANCHOR: offset
    /// The offset `(dx, dy)`, in pixels, of a ray's aim from the pixel's centre:
    /// none for the centre, two normal numbers (Box-Muller) for the Gaussian.
    pub fn offset(&self, rng: &mut PixelRng) -> (Real, Real) {
        match *self {
            PixelFilter::Centre => (0.0, 0.0),
            PixelFilter::Gaussian { sigma } => {
                let (u1, u2) = uniform_pair(rng);
                sample_gaussian(u1, u2, sigma)
            }
        }
    }
    // ANCHOR_END: offset
}
