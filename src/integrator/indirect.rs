//! Indirect lighting: light that reaches a diffuse surface after bouncing off other
//! surfaces, estimated by Monte Carlo. Session 4 replaces it by a version that
//! knows about light sampling (`integrator/light_sampling.rs`).

use crate::geometry::Hit;
use crate::integrator::Tracer;
use crate::maths::Colour;

impl Tracer<'_> {
    // ANCHOR: indirect
    /// Light reflected by a diffuse surface of `albedo` after arriving from other
    /// surfaces: the integral of `L(w) (albedo / pi) cos(theta)` over the hemisphere,
    /// estimated with one direction drawn with density `cos(theta) / pi`. The cosine
    /// and the `pi` cancel, leaving `albedo L(w)`. Session 4 changes one thing: with
    /// light sampling, the sampled light's own glow is not counted again.
    ///
    /// Exercise s3.3, the indirect bounce: book session 3, "Indirect lighting".
    pub fn indirect_light(&mut self, hit: &Hit, albedo: Colour, bounces: u32) -> Colour {
        self.bounce(bounces, |tracer, next| {
            let direction = tracer.cosine_direction(hit);
            albedo * tracer.radiance(&hit.spawn(direction), next)
        })
    }
    // ANCHOR_END: indirect
}
