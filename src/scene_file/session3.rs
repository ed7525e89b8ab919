//! What session 3 adds to a scene file: antialiasing, and beyond the course the
//! sampler and adaptive sampling.

use std::path::Path;

use crate::camera::PixelFilter;
use crate::files::Files;
use crate::scene::Scene;
use crate::scene::beyond::Beyond;
use crate::scene::beyond::Sampler;
use crate::scene_file::format::{SamplerSpec, SceneFile};
use crate::scene_file::{SceneError, session1};

/// The scene of session 1 with what session 3 reads in `file`: the Gaussian jitter of
/// camera rays (`camera.antialiasing`, its standard deviation in pixels), the
/// sampler (`render.sampler`), adaptive sampling's target (`render.noise`) and the
/// fast engine (`render.fast`), all three beyond the course.
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let mut scene = session1::scene(file, path, files)?;
    if let Some(sigma) = file.camera.antialiasing {
        scene.camera.filter = PixelFilter::Gaussian { sigma: sigma.0 };
    }
    scene.settings.beyond = Beyond {
        sampler: match file.render.sampler.unwrap_or_default() {
            SamplerSpec::Independent => Sampler::Independent,
            SamplerSpec::Stratified => Sampler::Stratified,
            SamplerSpec::Sobol => Sampler::Sobol,
        },
        noise: file.render.noise.map(|n| n.0),
        fast: file.render.fast,
    };
    Ok(scene)
}
