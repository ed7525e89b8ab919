//! A diffuse surface's light: direct, and from session 3 indirect.

use crate::geometry::Hit;
use crate::integrator::Tracer;
use crate::maths::frame::Frame;
use crate::maths::sampling::sample_cosine_hemisphere;
use crate::maths::{Colour, Vec3, uniform_pair};

impl Tracer<'_> {
    // ANCHOR: diffuse
    /// Light reflected by a diffuse surface of `albedo`: direct light from the light
    /// source, plus, when the scene asks for it, light bounced off other surfaces.
    pub fn diffuse(&mut self, hit: &Hit, albedo: Colour, bounces: u32) -> Colour {
        let direct = self.direct_light(hit, albedo);
        if self.scene.settings.indirect {
            direct + self.indirect_light(hit, albedo, bounces)
        } else {
            direct
        }
    }
    // ANCHOR_END: diffuse

    // ANCHOR: cosine_direction
    /// A direction around the hit's normal drawn with density `cos(theta) / pi`: a
    /// direction around `+z` ([`sample_cosine_hemisphere`]) turned into the frame
    /// `(T1, T2, N)` of the normal.
    pub fn cosine_direction(&mut self, hit: &Hit) -> Vec3 {
        let (u1, u2) = uniform_pair(&mut self.rng);
        let local = sample_cosine_hemisphere(u1, u2);
        Frame::new(hit.normal).to_world(local)
    }
    // ANCHOR_END: cosine_direction
}
