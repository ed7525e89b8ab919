//! What session 6 adds to a scene file: bounding volume hierarchies and smooth
//! normals.

use std::path::Path;

use std::sync::Arc;

use crate::acceleration::Bvh;
use crate::files::Files;
use crate::scene::Scene;
use crate::scene_file::format::{AccelerationSpec, SceneFile};
use crate::scene_file::{SceneError, session5};

/// The scene of session 5 with what session 6 reads in `file`: each mesh searched
/// through the course's hierarchy when `render.acceleration` asks for one, and
/// shaded with its vertex normals only where `smooth_normals` says so.
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let mut scene = session5::scene(file, path, files)?;
    for (mesh, spec) in scene.meshes.iter_mut().zip(&file.meshes) {
        if file.render.acceleration == AccelerationSpec::Bvh {
            mesh.search = Arc::new(Bvh::build(mesh));
        }
        if !spec.smooth_normals {
            mesh.normals.clear();
        }
    }
    Ok(scene)
}
