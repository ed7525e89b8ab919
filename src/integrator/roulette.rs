//! Russian roulette: a path that has used its bounces may go on, by chance.

use crate::integrator::Tracer;
use crate::maths::{Colour, uniform};

impl Tracer<'_> {
    // ANCHOR: roulette
    /// The light a path brings back from one more bounce, `go_on(tracer, bounces left
    /// after it)`: as in session 2 while `bounces` is above 0. Once the bounces are
    /// used up, with Russian roulette the path goes on with probability `survival`
    /// and its light is divided by `survival`, so that on average nothing is lost
    /// (unbiased), at the price of some noise; without it, the path stops.
    pub fn bounce(&mut self, bounces: u32, go_on: impl FnOnce(&mut Self, u32) -> Colour) -> Colour {
        if let Some(next) = bounces.checked_sub(1) {
            return go_on(self, next);
        }
        match self.scene.settings.russian_roulette {
            Some(survival) if uniform(&mut self.rng) < survival => {
                (1.0 / survival) * go_on(self, 0)
            }
            _ => Colour::ZERO,
        }
    }
    // ANCHOR_END: roulette
}
