//! Everything a render needs: the camera, the objects, the light and the settings.

use crate::camera::Camera;
use crate::hit::Hit;
use crate::light::PointLight;
use crate::math::Real;
use crate::ray::Ray;
use crate::sphere::Sphere;

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
    /// Whether a shadow ray checks that the light is visible before shading.
    pub shadows: bool,
}

/// A scene ready to render.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The eye and the image size.
    pub camera: Camera,
    /// The objects.
    pub spheres: Vec<Sphere>,
    /// The light, if the scene has one.
    pub light: Option<PointLight>,
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
        if s.shadows {
            text += ", shadows";
        }
        text
    }

    // ANCHOR: nearest
    /// The nearest hit of `ray` among all objects: every sphere is tested and the
    /// smallest positive distance wins.
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let mut nearest: Option<(Real, &Sphere)> = None;
        for sphere in &self.spheres {
            if let Some(t) = sphere.intersect(ray)
                && nearest.is_none_or(|(best, _)| t < best)
            {
                nearest = Some((t, sphere));
            }
        }
        nearest.map(|(t, sphere)| sphere.hit_at(ray, t))
    }
    // ANCHOR_END: nearest

    /// Whether any object lies on `ray` closer than `distance`: the shadow-ray test.
    pub fn occluded(&self, ray: &Ray, distance: Real) -> bool {
        self.spheres
            .iter()
            .any(|s| s.intersect(ray).is_some_and(|t| t < distance))
    }
}
