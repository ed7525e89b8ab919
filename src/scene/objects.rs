//! Everything a render needs: the camera, the objects, the light and the settings.

use crate::camera::Camera;
use crate::geometry::{Ray, Sphere};
use crate::lights::Light;
use crate::maths::Real;
use crate::scene::Settings;

#[cfg(feature = "s5")]
use crate::meshes::Mesh;

// ANCHOR: scene
/// A scene ready to render. Later sessions add fields (the meshes of session 5);
/// they start empty, so the struct is built with `..Default::default()`, and
/// `non_exhaustive` tells other crates so.
#[derive(Clone, Debug, Default)]
#[non_exhaustive]
pub struct Scene {
    /// The eye and the image size.
    pub camera: Camera,
    /// The spheres.
    pub spheres: Vec<Sphere>,
    /// The triangle meshes (session 5); in hits they are numbered after the spheres.
    #[cfg(feature = "s5")]
    pub meshes: Vec<Mesh>,
    /// The light source, if the scene has one.
    pub light: Option<Light>,
    /// How it is rendered.
    pub settings: Settings,
}
// ANCHOR_END: scene

impl Scene {
    /// A scene of `spheres` seen by `camera`, lit by `light`, rendered as `settings`
    /// say.
    pub fn new(
        camera: Camera,
        spheres: Vec<Sphere>,
        light: Option<Light>,
        settings: Settings,
    ) -> Scene {
        Scene {
            camera,
            spheres,
            light,
            settings,
            ..Default::default()
        }
    }

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
            (s.russian_roulette.is_some(), "Russian roulette"),
        ] {
            if on {
                text += ", ";
                text += name;
            }
        }
        text
    }

    // ANCHOR: nearest_sphere
    /// The distance to the nearest sphere that `ray` hits and that sphere's index:
    /// every sphere is tested and the smallest positive distance wins, the first
    /// sphere on a tie.
    ///
    /// Exercise s1.3, the nearest hit: book session 1, "Several spheres".
    pub fn nearest_sphere(&self, ray: &Ray) -> Option<(Real, usize)> {
        let mut nearest: Option<(Real, usize)> = None;
        for (i, sphere) in self.spheres.iter().enumerate() {
            if let Some(t) = sphere.intersect(ray)
                && nearest.is_none_or(|(best, _)| t < best)
            {
                nearest = Some((t, i));
            }
        }
        nearest
    }
    // ANCHOR_END: nearest_sphere
}
