//! One more bounce of a path, while it may still bounce.

use crate::integrator::Tracer;
use crate::maths::Colour;

impl Tracer<'_> {
    // ANCHOR: bounce
    /// The light a path brings back from one more bounce: `go_on(tracer, bounces
    /// left after it)`, times the bounce's weight, while [`Tracer::next_bounce`] lets
    /// the path go on; black once it stops.
    pub fn bounce(&mut self, bounces: u32, go_on: impl FnOnce(&mut Self, u32) -> Colour) -> Colour {
        match self.next_bounce(bounces) {
            Some((next, weight)) => weight * go_on(self, next),
            None => Colour::ZERO,
        }
    }
    // ANCHOR_END: bounce
}
