//! What session 5 adds to a scene file: triangle meshes, tested by brute force or
//! behind their bounding box.

use std::path::Path;
use std::sync::Arc;

use crate::acceleration::BoundingBox;
use crate::files::Files;
use crate::geometry::TriangleTest;
use crate::maths::{Colour, Mat3, Vec3};
use crate::meshes::{Mesh, MeshAlbedo, Placement, read_obj_from};
use crate::messages::said::Said;
use crate::scene::Scene;
use crate::scene_file::format::{AccelerationSpec, MeshSpec, SceneFile, TriangleTestSpec};
use crate::scene_file::{SceneError, one_line, session4};

/// The scene of session 4 with what session 5 reads in `file`: its meshes, their OBJ
/// files found next to the scene file at `path` in `files`, each placed, coloured, tested with the
/// file's ray-triangle test, and searched by brute force or behind its bounding box.
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let mut scene = session4::scene(file, path, files)?;
    let test = match file.render.triangle_test.unwrap_or_default() {
        TriangleTestSpec::MollerTrumbore => TriangleTest::MollerTrumbore,
        TriangleTestSpec::Watertight => TriangleTest::Watertight,
    };
    for spec in &file.meshes {
        let mut mesh = load_mesh(spec, path, files)?;
        mesh.triangle_test = test;
        if file.render.acceleration == AccelerationSpec::Bbox {
            mesh.search = Arc::new(BoundingBox);
        }
        scene.meshes.push(mesh);
    }
    Ok(scene)
}

/// The mesh of `spec`, its OBJ file read from `files` next to the scene file at
/// `path`, placed by `p' = rotation (scale p) + translation` and given its albedo.
pub fn load_mesh(spec: &MeshSpec, path: &Path, files: &dyn Files) -> Result<Mesh, SceneError> {
    let obj = path.parent().unwrap_or(Path::new("")).join(&spec.obj);
    let data = read_obj_from(&obj, files).map_err(|e| SceneError::Asset {
        scene: path.to_owned(),
        file: obj.clone(),
        message: Said::new("scene-cannot-load-mesh").with("why", one_line(&e)),
    })?;
    let [rx, ry, rz] = spec.rotation.map_or([0.0; 3], |r| r.0.to_array());
    let placement = Placement {
        scale: spec.scale.map_or(1.0, |s| s.0),
        rotation: Mat3::from_rotation_z(rz.to_radians())
            * Mat3::from_rotation_y(ry.to_radians())
            * Mat3::from_rotation_x(rx.to_radians()),
        translation: spec.translation.map_or(Vec3::ZERO, |t| t.0),
    };
    let mut mesh = Mesh::new(&data, &placement);
    mesh.albedo = MeshAlbedo::Constant(spec.albedo.map_or(Colour::ONE, |a| a.0));
    Ok(mesh)
}
