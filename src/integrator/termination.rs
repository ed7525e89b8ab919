//! When a path stops: at the bounce limit, or by Russian roulette.

use crate::integrator::radiance::Tracer;
use crate::maths::numbers::Real;

/// What happens when a path has used up its bounces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Termination {
    /// The path stops: the light of longer paths is lost, a bias towards dark.
    BounceLimit,
    /// The path goes on with probability `survival`, its contribution divided by
    /// `survival`, and stops otherwise: on average nothing is lost (unbiased), at
    /// the price of some noise.
    #[cfg(feature = "s4")]
    RussianRoulette {
        /// Probability of going on, in `(0, 1]`.
        survival: Real,
    },
}

impl Tracer<'_> {
    // ANCHOR: continue_path
    /// Whether the path goes on after a reflection, with `bounces` bounces left:
    /// `Some((bounces left afterwards, weight))` or `None` when it stops.
    pub fn continue_path(&mut self, bounces: u32) -> Option<(u32, Real)> {
        if bounces > 0 {
            return Some((bounces - 1, 1.0));
        }
        match self.scene.settings.termination {
            Termination::BounceLimit => None,
            #[cfg(feature = "s4")]
            Termination::RussianRoulette { survival } => {
                (crate::maths::random::uniform(&mut self.rng) < survival)
                    .then_some((0, 1.0 / survival))
            }
        }
    }
    // ANCHOR_END: continue_path
}
