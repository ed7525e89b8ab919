//! What session 3 adds to a scene file: antialiasing.

use std::path::Path;

use crate::camera::PixelFilter;
use crate::files::Files;
use crate::scene::Scene;
use crate::scene_file::format::SceneFile;
use crate::scene_file::{SceneError, session1};

/// The scene of session 1 with what session 3 reads in `file`: the Gaussian jitter of
/// camera rays (`camera.antialiasing`, its standard deviation in pixels).
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let mut scene = session1::scene(file, path, files)?;
    if let Some(sigma) = file.camera.antialiasing {
        scene.camera.filter = PixelFilter::Gaussian { sigma: sigma.0 };
    }
    Ok(scene)
}
