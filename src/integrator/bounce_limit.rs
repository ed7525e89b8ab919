//! Whether a path may bounce once more: while bounces are left. Session 4 replaces
//! it by Russian roulette (`integrator/roulette.rs`).

use crate::integrator::Tracer;
use crate::maths::Real;

impl Tracer<'_> {
    // ANCHOR: next_bounce
    /// Whether a path with `bounces` still allowed goes on: while `bounces` is above
    /// 0, `Some` of the bounces left after this one and the weight of the light it
    /// brings back, 1; `None` once they are used up. Session 4 lets a path go on past
    /// the limit by chance, with a larger weight (Russian roulette).
    pub fn next_bounce(&mut self, bounces: u32) -> Option<(u32, Real)> {
        bounces.checked_sub(1).map(|next| (next, 1.0))
    }
    // ANCHOR_END: next_bounce
}
