//! Direct light from a sphere light, by sampling the cone of directions it is seen
//! under.

use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::lights::{Light, SphereLight};
use crate::maths::{Colour, PI, uniform_pair};

impl Tracer<'_> {
    // ANCHOR: sphere_light
    /// Light from a sphere light reflected by a diffuse surface: sampled when the
    /// scene asks for light sampling; otherwise only indirect rays that happen to
    /// hit the light bring its light.
    pub fn sphere_light(&mut self, light: &SphereLight, hit: &Hit, albedo: Colour) -> Colour {
        if self.scene.settings.light_sampling {
            self.sample_light(light, hit, albedo)
        } else {
            Colour::ZERO
        }
    }
    // ANCHOR_END: sphere_light

    // ANCHOR: light_sampling
    /// Light arriving straight from the sphere light at a diffuse point, estimated
    /// with one direction sampled towards the light: what [`Tracer::light_sample`]
    /// brings if the first object its ray meets is the light, 0 when another object
    /// is in the way (only the object it meets first is looked up).
    pub fn sample_light(&mut self, light: &SphereLight, hit: &Hit, albedo: Colour) -> Colour {
        match self.light_sample(light, hit, albedo) {
            Some((ray, lit)) => match self.scene.nearest(&ray) {
                Some((_, seen)) if seen == light.object => lit,
                _ => Colour::ZERO,
            },
            None => Colour::ZERO,
        }
    }

    /// One direction drawn towards the sphere light from a diffuse point, as a ray
    /// from the point (counted as one ray), and the light it brings if nothing is in
    /// the way: `L = Le (albedo / pi) cos(theta) / pdf(w)`. `None` where it brings
    /// nothing: the point is inside the light, or the direction lies below the
    /// surface.
    pub fn light_sample(
        &mut self,
        light: &SphereLight,
        hit: &Hit,
        albedo: Colour,
    ) -> Option<(Ray, Colour)> {
        let (u1, u2) = uniform_pair(&mut self.rng);
        let (direction, pdf) = light.sample(hit.point, u1, u2)?;
        let cos = direction.dot(hit.normal);
        if cos <= 0.0 {
            return None;
        }
        self.rays += 1;
        let lit = light.emission * albedo / PI * cos / pdf;
        Some((hit.spawn(direction), lit))
    }
    // ANCHOR_END: light_sampling

    // ANCHOR: indirect_skipping
    /// [`Tracer::indirect_light`] as session 3 has it, but with light sampling the
    /// bounced ray does not count the glow of the light already sampled at this
    /// point: it would be counted twice.
    pub fn indirect_light(&mut self, hit: &Hit, albedo: Colour, bounces: u32) -> Colour {
        let skip = self.sampled_light();
        self.bounce(bounces, |tracer, next| {
            let direction = tracer.cosine_direction(hit);
            albedo * tracer.radiance_skipping(&hit.spawn(direction), next, skip)
        })
    }

    /// The object whose glow a bounced ray does not count: the sphere light, when
    /// light sampling counts its light at every diffuse hit.
    pub fn sampled_light(&self) -> Option<usize> {
        match self.scene.light {
            Some(Light::Sphere(light)) if self.scene.settings.light_sampling => Some(light.object),
            _ => None,
        }
    }

    /// [`Tracer::radiance`], but the glow of object `skip` is not counted.
    pub fn radiance_skipping(&mut self, ray: &Ray, bounces: u32, skip: Option<usize>) -> Colour {
        let Some(hit) = self.trace(ray) else {
            return Colour::ZERO;
        };
        let reflected = self.reflected(ray, &hit, bounces);
        if skip == Some(hit.object) {
            reflected
        } else {
            hit.emission + reflected
        }
    }
    // ANCHOR_END: indirect_skipping
}
