//! One more bounce of a path, while it may still bounce. Session 4 replaces it by
//! Russian roulette (`integrator/roulette.rs`).

use crate::integrator::Tracer;
use crate::maths::Colour;

impl Tracer<'_> {
    // ANCHOR: bounce
    /// The light a path brings back from one more bounce: `go_on(tracer, bounces
    /// left after it)` while `bounces`, the bounces still allowed, is above 0; black
    /// once they are used up. Session 4 lets a path go on past the limit by chance
    /// (Russian roulette).
    pub fn bounce(&mut self, bounces: u32, go_on: impl FnOnce(&mut Self, u32) -> Colour) -> Colour {
        match bounces.checked_sub(1) {
            Some(next) => go_on(self, next),
            None => Colour::ZERO,
        }
    }
    // ANCHOR_END: bounce
}
