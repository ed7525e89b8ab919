//! What a scene file may ask beyond the course: another sampler
//! (`render.sampler`), adaptive sampling (`render.noise`) and the fast engine
//! (`render.fast`, whose hierarchy has leaves of at most `render.leaf_size`
//! triangles). The course's scene comes first; these settings go on top of it.

use std::path::Path;
use std::sync::Arc;

use crate::fast::FastBvh;
use crate::files::Files;
use crate::maths::Real;
use crate::maths::values::Positive;
use crate::scene::Scene;
use crate::scene::beyond::{Beyond, Sampler};
use crate::scene_file::format::{AccelerationSpec, SamplerSpec, SceneFile};
use crate::scene_file::{SceneError, session7};

/// The course's scene of `file` with what it asks beyond the course: its sampler,
/// its adaptive sampling's target, and with `render.fast` the fast engine, each mesh
/// searched by the fast engine's hierarchy where `render.acceleration` asks for one.
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let r = &file.render;
    let fast_bvh = r.fast && r.acceleration == AccelerationSpec::Bvh;
    if r.leaf_size.is_some() && !fast_bvh {
        return Err(SceneError::Inconsistent {
            path: path.to_owned(),
            key: "render.leaf_size".into(),
            message: "only the fast engine's hierarchy has a leaf size: `fast = true` with \
                      `acceleration = \"bvh\"`"
                .into(),
        });
    }
    let mut scene = if fast_bvh {
        // The course's hierarchy would be built only to be replaced.
        let mut course = file.clone();
        course.render.acceleration = AccelerationSpec::None;
        session7::scene(&course, path, files)?
    } else {
        session7::scene(file, path, files)?
    };
    if fast_bvh {
        let leaf_size = r.leaf_size.map_or(8, |l| l.get());
        for mesh in &mut scene.meshes {
            mesh.search = Arc::new(FastBvh::build(mesh, leaf_size));
        }
    }
    scene.settings.beyond = Beyond {
        sampler: match r.sampler.unwrap_or_default() {
            SamplerSpec::Independent => Sampler::Independent,
            SamplerSpec::Stratified => Sampler::Stratified,
            SamplerSpec::Sobol => Sampler::Sobol,
        },
        noise: r.noise.map(|n| n.0),
        fast: r.fast,
    };
    Ok(scene)
}

/// Puts the command line's `--noise` and `--fast` into `file`; an error names the
/// key if the noise is not a positive number.
pub fn apply_overrides(
    (noise, fast): (Option<Real>, bool),
    file: &mut SceneFile,
) -> Result<(), (&'static str, String)> {
    if let Some(noise) = noise {
        file.render.noise = Some(Positive::try_from(noise).map_err(|e| ("render.noise", e))?);
    }
    file.render.fast |= fast;
    Ok(())
}
