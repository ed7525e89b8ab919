//! The recursive `radiance` function of the course: the light arriving at the eye
//! along a ray.

use crate::geometry::hit::Hit;
use crate::geometry::ray::Ray;
use crate::lights::light::Light;
use crate::materials::material::Material;
use crate::maths::numbers::Colour;
use crate::maths::random::{PixelRng, pixel_rng};
use crate::scene::objects::Scene;

/// Traces the rays of one pixel through a scene, counting them.
pub struct Tracer<'a> {
    /// The scene being rendered.
    pub scene: &'a Scene,
    /// Rays traced so far: camera, shadow and secondary rays.
    pub rays: u64,
    /// The random generator of the pixel being rendered.
    pub rng: PixelRng,
}

impl<'a> Tracer<'a> {
    /// A tracer over `scene` that has traced no ray yet.
    pub fn new(scene: &'a Scene) -> Self {
        Self {
            scene,
            rays: 0,
            rng: pixel_rng(scene.settings.seed, 0),
        }
    }

    /// The nearest hit of `ray`, counted as one ray traced.
    pub fn trace(&mut self, ray: &Ray) -> Option<Hit> {
        self.rays += 1;
        self.scene.intersect(ray)
    }

    // ANCHOR: radiance
    /// The radiance arriving along `ray`, with at most `bounces` more bounces
    /// allowed: what the surface it hits emits, plus what it reflects. A ray that
    /// leaves the scene sees black.
    pub fn radiance(&mut self, ray: &Ray, bounces: u32) -> Colour {
        self.radiance_skipping(ray, bounces, None)
    }

    /// [`Tracer::radiance`], but the emission of object `skip` is not counted: after
    /// a diffuse bounce, the light that was already sampled directly.
    pub fn radiance_skipping(&mut self, ray: &Ray, bounces: u32, skip: Option<usize>) -> Colour {
        let Some(hit) = self.trace(ray) else {
            return Colour::ZERO;
        };
        let reflected = match hit.material {
            Material::Diffuse { albedo } => self.diffuse(&hit.facing_the_ray(), albedo, bounces),
            #[cfg(feature = "s2")]
            Material::Mirror => self.mirror(ray, &hit, bounces),
            #[cfg(feature = "s2")]
            Material::Glass { index } => self.glass(ray, &hit, index, bounces),
            #[cfg(feature = "s4")]
            Material::FresnelGlass { index } => self.fresnel_glass(ray, &hit, index, bounces),
        };
        let emitted = if skip == Some(hit.object) {
            Colour::ZERO
        } else {
            hit.emission
        };
        emitted + reflected
    }
    // ANCHOR_END: radiance

    // ANCHOR: diffuse
    /// Light reflected by a diffuse surface: direct light from the light source, plus
    /// (from session 3, when the scene asks for it) light bounced off other surfaces.
    pub fn diffuse(
        &mut self,
        hit: &Hit,
        albedo: Colour,
        #[cfg_attr(not(feature = "s3"), expect(unused_variables))] bounces: u32,
    ) -> Colour {
        let direct = self.direct_light(hit, albedo);
        #[cfg(feature = "s3")]
        if self.scene.settings.indirect {
            return direct + self.indirect_light(hit, albedo, bounces);
        }
        direct
    }
    // ANCHOR_END: diffuse

    // ANCHOR: direct_light
    /// Light from the light source reflected by a diffuse surface. A point light is
    /// shaded by Lambert's law, zero if a shadow ray finds an object between the
    /// point and the light; a sphere light is sampled when the scene asks for it.
    pub fn direct_light(&mut self, hit: &Hit, albedo: Colour) -> Colour {
        match self.scene.light {
            None => Colour::ZERO,
            Some(Light::Point(light)) => {
                if self.scene.settings.shadows {
                    let (shadow_ray, distance) = hit.spawn_towards(light.position);
                    self.rays += 1;
                    if self.scene.occluded(&shadow_ray, distance) {
                        return Colour::ZERO;
                    }
                }
                light.lambert(hit.point, hit.shading_normal, albedo)
            }
            #[cfg(feature = "s4")]
            Some(Light::Sphere(light)) if self.scene.settings.light_sampling => {
                self.sample_light(&light, hit, albedo)
            }
            #[cfg(feature = "s4")]
            Some(Light::Sphere(_)) => Colour::ZERO,
        }
    }
    // ANCHOR_END: direct_light
}
