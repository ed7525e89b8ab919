//! Russian roulette: a path that has used its bounces may go on, by chance.

use crate::integrator::Tracer;
use crate::maths::{Real, uniform};

impl Tracer<'_> {
    // ANCHOR: roulette
    /// Whether a path with `bounces` still allowed goes on, and if so the bounces
    /// left after this one and the weight of the light it brings back: as in session
    /// 2 while `bounces` is above 0, with weight 1. Once the bounces are used up, with
    /// Russian roulette the path goes on with probability `survival` and its light is
    /// weighted by `1 / survival`, so that on average nothing is lost (unbiased), at
    /// the price of some noise; without it, the path stops.
    pub fn next_bounce(&mut self, bounces: u32) -> Option<(u32, Real)> {
        if let Some(next) = bounces.checked_sub(1) {
            return Some((next, 1.0));
        }
        match self.scene.settings.russian_roulette {
            Some(survival) if uniform(&mut self.rng) < survival => Some((0, 1.0 / survival)),
            _ => None,
        }
    }
    // ANCHOR_END: roulette
}
