//! Everything a render needs: the camera, the objects, the light and the settings.

use crate::camera::Camera;
use crate::geometry::{Ray, Sphere};
use crate::lights::Light;
use crate::maths::Real;
use crate::messages::language::Language;
use crate::messages::say;
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

    /// The render settings in a few words of `language`, such as `512x512, 1 spp, 5
    /// bounces, gamma 2.2, shadows` (the catalogue's `summary-*` messages).
    pub fn summary(&self, language: Language) -> String {
        let s = &self.settings;
        let size = [
            ("width", self.camera.width.into()),
            ("height", self.camera.height.into()),
            ("samples", s.samples.into()),
            ("bounces", s.bounces.into()),
        ];
        let mut text = say(language, "summary-settings", &size);
        if s.gamma != 1.0 {
            // The gamma as the scene file wrote it, whatever the precision of `Real`.
            let gamma = s.gamma.to_string().parse::<f64>().unwrap_or(f64::NAN);
            text += &say(language, "summary-gamma", &[("gamma", gamma.into())]);
        }
        for (on, id) in [
            (s.shadows, "summary-shadows"),
            (s.indirect, "summary-indirect"),
            (s.light_sampling, "summary-light-sampling"),
            (s.russian_roulette.is_some(), "summary-russian-roulette"),
        ] {
            if on {
                text += &say(language, id, &[]);
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
