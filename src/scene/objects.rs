//! Everything a render needs: the camera, the objects, the light and the settings.

use crate::camera::pinhole::Camera;
use crate::geometry::hit::Hit;
use crate::geometry::ray::Ray;
use crate::geometry::sphere::Sphere;
use crate::integrator::termination::Termination;
use crate::lights::light::Light;
use crate::maths::numbers::Real;

/// How a scene is rendered: the settings a scene file's `[render]` table holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Camera rays averaged in each pixel.
    pub samples: u32,
    /// How many times a path may bounce off mirrors and glass before it stops.
    pub bounces: u32,
    /// Seed of the per-pixel random generators.
    pub seed: u64,
    /// Display gamma: an 8-bit pixel is `min(255, L^(1/gamma))`; 1 leaves radiance as is.
    pub gamma: Real,
    /// Whether a shadow ray checks that the point light is visible before shading.
    pub shadows: bool,
    /// Whether diffuse surfaces also reflect light arriving from other surfaces
    /// (session 3), or only the light source's.
    pub indirect: bool,
    /// Whether a sphere light is sampled directly at each diffuse hit (session 4),
    /// or found only by indirect rays that happen to hit it.
    pub light_sampling: bool,
    /// What happens to a path that runs out of bounces.
    pub termination: Termination,
}

/// A scene ready to render.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The eye and the image size.
    pub camera: Camera,
    /// The spheres.
    pub spheres: Vec<Sphere>,
    /// The triangle meshes; in hits they are numbered after the spheres.
    #[cfg(feature = "s5")]
    pub meshes: Vec<crate::meshes::mesh::Mesh>,
    /// The light source, if the scene has one.
    pub light: Option<Light>,
    /// Render settings.
    pub settings: Settings,
}

impl Scene {
    /// The render settings in a few words, such as `512x512, 1 spp, 5 bounces, gamma 2.2,
    /// shadows`.
    pub fn summary(&self) -> String {
        let s = &self.settings;
        let mut text = format!(
            "{}x{}, {} spp, {} bounces",
            self.camera.width, self.camera.height, s.samples, s.bounces
        );
        if s.gamma != 1.0 {
            text += &format!(", gamma {}", s.gamma);
        }
        for (on, name) in [
            (s.shadows, "shadows"),
            (s.indirect, "indirect"),
            (s.light_sampling, "light sampling"),
            (
                s.termination != Termination::BounceLimit,
                "Russian roulette",
            ),
        ] {
            if on {
                text += ", ";
                text += name;
            }
        }
        text
    }

    // ANCHOR: nearest
    /// The nearest hit of `ray` among all objects: every sphere is tested and the
    /// smallest positive distance wins.
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let mut nearest: Option<(Real, usize)> = None;
        for (i, sphere) in self.spheres.iter().enumerate() {
            if let Some(t) = sphere.intersect(ray)
                && nearest.is_none_or(|(best, _)| t < best)
            {
                nearest = Some((t, i));
            }
        }
        #[cfg(feature = "s5")]
        if let Some(hit) = self.nearest_mesh(ray, nearest.map_or(Real::INFINITY, |n| n.0)) {
            return Some(hit);
        }
        nearest.map(|(t, i)| self.spheres[i].hit_at(ray, t, i))
    }
    // ANCHOR_END: nearest

    /// The object whose emission is sampled directly at diffuse hits, if any: the
    /// sphere light when the scene uses light sampling. Indirect rays that reach it
    /// must not count its light a second time.
    pub fn sampled_light(&self) -> Option<usize> {
        match self.light {
            #[cfg(feature = "s4")]
            Some(Light::Sphere(light)) if self.settings.light_sampling => Some(light.object),
            _ => None,
        }
    }

    /// Whether any object lies on `ray` closer than `distance`: the shadow-ray test.
    pub fn occluded(&self, ray: &Ray, distance: Real) -> bool {
        #[cfg(feature = "s5")]
        if self.meshes.iter().any(|m| m.occluded(ray, distance)) {
            return true;
        }
        self.spheres
            .iter()
            .any(|s| s.intersect(ray).is_some_and(|t| t < distance))
    }
}
