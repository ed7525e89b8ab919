//! What session 3 adds to a scene file: antialiasing.

use crate::camera::PixelFilter;
use crate::scene::Scene;
use crate::scene_file::format::SceneFile;

/// Adds to `scene` what session 3 reads in `file`: the Gaussian jitter of camera
/// rays (`camera.antialiasing`, its standard deviation in pixels).
pub fn add(file: &SceneFile, mut scene: Scene) -> Scene {
    if let Some(sigma) = file.camera.antialiasing {
        scene.camera.filter = PixelFilter::Gaussian { sigma: sigma.0 };
    }
    scene
}
