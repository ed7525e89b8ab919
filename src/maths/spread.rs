//! Beyond the course: random numbers that a sampler spreads evenly over a pixel's
//! samples, drawn through the course's [`PixelRng`](crate::maths::random::PixelRng).

use crate::maths::Real;

/// A sampler beyond the course: numbers for each decision of a path, spread evenly
/// over the samples of a pixel. Every sample starts with
/// [`start_sample`](SpreadNumbers::start_sample); each random decision of its path
/// (where in the pixel, where on the lens, which light direction, which bounce
/// direction, whether the path goes on) then takes the next dimension, one number or
/// a pair.
pub trait SpreadNumbers: std::fmt::Debug + Send {
    /// Starts sample number `sample` of the pixel at its first dimension.
    fn start_sample(&mut self, sample: u32);
    /// A number of `[0, 1)` for a one-dimensional decision.
    fn number(&mut self) -> Real;
    /// A point of `[0, 1)^2` for a two-dimensional decision.
    fn pair(&mut self) -> (Real, Real);
    /// A copy that draws the same numbers from here on.
    fn copy(&self) -> Box<dyn SpreadNumbers>;
}

impl Clone for Box<dyn SpreadNumbers> {
    fn clone(&self) -> Self {
        self.copy()
    }
}
