//! Glass that reflects as well as refracts, as the Fresnel equations say.

use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::materials::fresnel::fresnel_reflectance;
use crate::materials::optics::{interface, reflect, refract};
use crate::maths::{Colour, Real, uniform};

impl Tracer<'_> {
    // ANCHOR: fresnel_glass
    /// Radiance seen through glass that also reflects: the path follows the
    /// reflected ray with probability `F` and the refracted one otherwise. Each
    /// choice is weighted by its probability, which cancels the factor `F` or
    /// `1 - F` of the light it carries.
    pub fn fresnel_glass(&mut self, ray: &Ray, hit: &Hit, index: Real, bounces: u32) -> Colour {
        self.bounce(bounces, |tracer, next| {
            let (normal, eta) = interface(ray.direction, hit.normal, index);
            let cos_i = -ray.direction.dot(normal);
            let direction = match refract(ray.direction, normal, eta) {
                Some(t) if uniform(&mut tracer.rng) >= fresnel_reflectance(cos_i, eta) => t,
                _ => reflect(ray.direction, normal),
            };
            tracer.radiance(&hit.spawn(direction), next)
        })
    }
    // ANCHOR_END: fresnel_glass
}
