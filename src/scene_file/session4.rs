//! What session 4 adds to a scene file: a sphere light and a thin lens.

use std::path::Path;

use crate::camera::{Lens, ThinLens};
use crate::files::Files;
use crate::lights::{Light, SphereLight};
use crate::scene::Scene;
use crate::scene_file::format::SceneFile;
use crate::scene_file::{SceneError, session3};

/// The scene of session 3 with what session 4 reads in `file`: a light with a radius
/// becomes a sphere light, whose body joins the spheres; `camera.lens` makes a thin
/// lens.
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let mut scene = session3::scene(file, path, files)?;
    if let Some(light) = &file.light
        && let Some(radius) = light.radius
    {
        let body = scene.spheres.len();
        let light = SphereLight::new(light.position.0, radius.0, light.intensity.0, body);
        scene.spheres.push(light.body());
        scene.light = Some(Light::Sphere(light));
    }
    if let Some(lens) = &file.camera.lens {
        scene.camera.lens = Lens::Thin(ThinLens {
            aperture: lens.aperture.0,
            focus: lens.focus.0,
        });
    }
    Ok(scene)
}
