//! Indirect lighting: light that reaches a diffuse surface after bouncing off other
//! surfaces, estimated by Monte Carlo.

use crate::geometry::hit::Hit;
use crate::integrator::radiance::Tracer;
use crate::maths::frame::Frame;
use crate::maths::numbers::Colour;
use crate::maths::random::uniform;
use crate::maths::sampling::sample_cosine_hemisphere;

impl Tracer<'_> {
    // ANCHOR: indirect
    /// Light reflected by a diffuse surface after arriving from other surfaces: the
    /// integral of `L(w) (albedo / pi) cos(theta)` over the hemisphere, estimated with
    /// one direction drawn with density `cos(theta) / pi`. The cosine and the `pi`
    /// cancel, leaving `albedo L(w)`.
    pub fn indirect_light(&mut self, hit: &Hit, albedo: Colour, bounces: u32) -> Colour {
        let Some((next, weight)) = self.continue_path(bounces) else {
            return Colour::ZERO;
        };
        let local = sample_cosine_hemisphere(uniform(&mut self.rng), uniform(&mut self.rng));
        let direction = Frame::new(hit.shading_normal).to_world(local);
        let skip = self.scene.sampled_light();
        weight * albedo * self.radiance_skipping(&hit.spawn(direction), next, skip)
    }
    // ANCHOR_END: indirect
}
