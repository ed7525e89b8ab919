//! What session 6 adds to a scene file: bounding volume hierarchies and smooth
//! normals.

use std::path::Path;

use std::sync::Arc;

use crate::acceleration::Bvh;
use crate::fast::FastBvh;
use crate::files::Files;
use crate::scene::Scene;
use crate::scene_file::format::{AccelerationSpec, SceneFile};
use crate::scene_file::{SceneError, session5};

/// The scene of session 5 with what session 6 reads in `file`: each mesh searched
/// through a hierarchy when `render.acceleration` asks for one (the course's, or with
/// `render.fast` the fast engine's, with leaves of at most `render.leaf_size`
/// triangles, 8 by default), and
/// shaded with its vertex normals only where `smooth_normals` says so.
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let mut scene = session5::scene(file, path, files)?;
    let leaf_size = file.render.leaf_size.map_or(8, |l| l.get());
    for (mesh, spec) in scene.meshes.iter_mut().zip(&file.meshes) {
        match file.render.acceleration {
            AccelerationSpec::Bvh if file.render.fast => {
                mesh.search = Arc::new(FastBvh::build(mesh, leaf_size));
            }
            AccelerationSpec::Bvh => mesh.search = Arc::new(Bvh::build(mesh)),
            AccelerationSpec::None | AccelerationSpec::Bbox => {}
        }
        if !spec.smooth_normals {
            mesh.normals.clear();
        }
    }
    Ok(scene)
}
