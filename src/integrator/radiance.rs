//! The recursive `radiance` function of the course: the light arriving at the eye
//! along a ray.

use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::materials::Material;
use crate::maths::Colour;

impl Tracer<'_> {
    // ANCHOR: radiance
    /// The radiance arriving along `ray`, with at most `bounces` more bounces
    /// allowed: what the surface it hits emits, plus what it reflects. A ray that
    /// leaves the scene sees black.
    pub fn radiance(&mut self, ray: &Ray, bounces: u32) -> Colour {
        let Some(hit) = self.trace(ray) else {
            return Colour::ZERO;
        };
        let reflected = self.reflected(ray, &hit, bounces);
        hit.emission + reflected
    }
    // ANCHOR_END: radiance

    // ANCHOR: reflected
    /// The light that the surface of `hit`, met by `ray`, reflects towards the ray's
    /// origin: what each material does.
    #[cfg_attr(
        not(feature = "s2"),
        expect(unused_variables, reason = "session 2's mirror and glass use the ray")
    )]
    pub fn reflected(&mut self, ray: &Ray, hit: &Hit, bounces: u32) -> Colour {
        match hit.material {
            Material::Diffuse { albedo } => self.diffuse(&hit.facing_the_ray(), albedo, bounces),
            #[cfg(feature = "s2")]
            Material::Mirror => self.mirror(ray, hit, bounces),
            #[cfg(feature = "s2")]
            Material::Glass { index } => self.glass(ray, hit, index, bounces),
            #[cfg(feature = "s4")]
            Material::FresnelGlass { index } => self.fresnel_glass(ray, hit, index, bounces),
        }
    }
    // ANCHOR_END: reflected
}
