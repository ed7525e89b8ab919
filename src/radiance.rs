//! The recursive `radiance` function of the course: the light arriving at the eye
//! along a ray.

use crate::hit::Hit;
use crate::material::Material;
use crate::math::Colour;
use crate::ray::Ray;
use crate::scene::Scene;

/// Traces the rays of one pixel through a scene, counting them.
pub struct Tracer<'a> {
    /// The scene being rendered.
    pub scene: &'a Scene,
    /// Rays traced so far: camera, shadow and secondary rays.
    pub rays: u64,
}

impl<'a> Tracer<'a> {
    /// A tracer over `scene` that has traced no ray yet.
    pub fn new(scene: &'a Scene) -> Self {
        Self { scene, rays: 0 }
    }

    /// The nearest hit of `ray`, counted as one ray traced.
    pub fn trace(&mut self, ray: &Ray) -> Option<Hit> {
        self.rays += 1;
        self.scene.intersect(ray)
    }

    // ANCHOR: radiance
    /// The radiance arriving along `ray`, with at most `bounces` more reflections or
    /// refractions allowed: what the surface it hits emits, plus what it reflects. A
    /// ray that leaves the scene sees black.
    pub fn radiance(
        &mut self,
        ray: &Ray,
        #[cfg_attr(not(feature = "s2"), expect(unused_variables))] bounces: u32,
    ) -> Colour {
        let Some(hit) = self.trace(ray) else {
            return Colour::ZERO;
        };
        let reflected = match hit.material {
            Material::Diffuse { albedo } => self.direct_light(&hit, albedo),
            #[cfg(feature = "s2")]
            Material::Mirror => self.mirror(ray, &hit, bounces),
            #[cfg(feature = "s2")]
            Material::Glass { index } => self.glass(ray, &hit, index, bounces),
        };
        hit.emission + reflected
    }
    // ANCHOR_END: radiance

    // ANCHOR: direct_light
    /// Light from the point light reflected by a diffuse surface (Lambert), zero if a
    /// shadow ray finds an object between the point and the light.
    pub fn direct_light(&mut self, hit: &Hit, albedo: Colour) -> Colour {
        let Some(light) = self.scene.light else {
            return Colour::ZERO;
        };
        if self.scene.settings.shadows {
            let (shadow_ray, distance) = hit.spawn_towards(light.position);
            self.rays += 1;
            if self.scene.occluded(&shadow_ray, distance) {
                return Colour::ZERO;
            }
        }
        light.lambert(hit.point, hit.normal, albedo)
    }
    // ANCHOR_END: direct_light
}
