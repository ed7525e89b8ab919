//! What session 1 reads in a scene file: the camera, the spheres, a point light and
//! the render settings. Each later session starts from this scene.

use std::path::Path;

use crate::camera::Camera;
use crate::files::Files;
use crate::geometry::Sphere;
use crate::lights::{Light, PointLight};
use crate::maths::Colour;
use crate::scene::{Scene, Settings};
use crate::scene_file::SceneError;
use crate::scene_file::format::SceneFile;

// ANCHOR: scene
/// The scene as session 1 reads `file`: the camera, the spheres, a point light and
/// the render settings. Session 1 reads no other file, so `_path` and `_files` are
/// not used, and nothing can go wrong once the file is checked; the signature is
/// that of every session's `scene`, the later ones reading meshes and textures next
/// to `path`, from `files`.
pub fn scene(file: &SceneFile, _path: &Path, _files: &dyn Files) -> Result<Scene, SceneError> {
    let r = &file.render;
    let fov = file.camera.fov.0.to_radians();
    let camera = Camera::new(file.camera.position.0, fov, r.width.get(), r.height.get());
    let spheres = file.spheres.iter().map(|s| Sphere {
        centre: s.centre.0,
        radius: s.radius.0,
        material: s.material,
        emission: s.emission.map_or(Colour::ZERO, |e| e.0),
    });
    let light = file.light.as_ref().map(|l| {
        Light::Point(PointLight {
            position: l.position.0,
            intensity: l.intensity.0,
        })
    });
    Ok(Scene::new(camera, spheres.collect(), light, settings(file)))
}
// ANCHOR_END: scene

/// The render settings of the `[render]` table that session 1 reads; the later
/// sessions' settings keep their defaults here.
#[allow(
    clippy::needless_update,
    reason = "from session 3 `Settings` has more fields"
)]
pub fn settings(file: &SceneFile) -> Settings {
    let r = &file.render;
    Settings {
        samples: r.samples.get(),
        bounces: r.bounces,
        seed: r.seed,
        gamma: r.gamma.map_or(1.0, |g| g.0),
        shadows: r.shadows,
        shadow_offset: r.shadow_offset.map(|e| e.0),
        indirect: r.indirect,
        light_sampling: r.light_sampling,
        russian_roulette: r.russian_roulette.map(|p| p.0),
        ..Settings::default()
    }
}
