//! Mirrors and glass: the radiance of a ray that meets a specular surface.

use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::materials::optics::{interface, reflect, refract};
use crate::maths::{Colour, Real};

impl Tracer<'_> {
    // ANCHOR: mirror
    /// Radiance seen in a mirror: that of the reflected ray, one bounce fewer.
    pub fn mirror(&mut self, ray: &Ray, hit: &Hit, bounces: u32) -> Colour {
        self.bounce(bounces, |tracer, next| {
            let reflected = hit.spawn(reflect(ray.direction, hit.normal));
            tracer.radiance(&reflected, next)
        })
    }
    // ANCHOR_END: mirror

    // ANCHOR: glass
    /// Radiance seen through glass of refractive `index`: the ray enters or leaves
    /// and bends; past the critical angle it is reflected instead.
    pub fn glass(&mut self, ray: &Ray, hit: &Hit, index: Real, bounces: u32) -> Colour {
        self.bounce(bounces, |tracer, next| {
            let (normal, eta) = interface(ray.direction, hit.normal, index);
            let direction = refract(ray.direction, normal, eta)
                .unwrap_or_else(|| reflect(ray.direction, normal));
            tracer.radiance(&hit.spawn(direction), next)
        })
    }
    // ANCHOR_END: glass
}
