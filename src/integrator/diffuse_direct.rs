//! A diffuse surface's light in sessions 1 and 2: the light source's alone. Session 3
//! replaces it by direct and indirect light (`integrator/diffuse.rs`).

use crate::geometry::Hit;
use crate::integrator::Tracer;
use crate::maths::Colour;

impl Tracer<'_> {
    // ANCHOR: diffuse
    /// Light reflected by a diffuse surface of `albedo`: the light source's
    /// ([`Tracer::direct_light`]). The bounces still allowed do not matter yet: from
    /// session 3 a diffuse surface also reflects light bounced off other surfaces.
    pub fn diffuse(&mut self, hit: &Hit, albedo: Colour, _bounces: u32) -> Colour {
        self.direct_light(hit, albedo)
    }
    // ANCHOR_END: diffuse
}
