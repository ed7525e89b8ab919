//! Meshes as a scene file declares them: loaded, placed, and given their search,
//! shading and colour.

use std::path::Path;

use crate::geometry::triangle::TriangleTest;
use crate::maths::numbers::{Colour, Mat3, Vec3};
use crate::meshes::mesh::{Mesh, MeshAlbedo, Placement, Search, read_obj};
use crate::scene_file::error::{SceneError, one_line};
use crate::scene_file::load::{AccelerationSpec, MeshSpec, TriangleTestSpec, require};

/// The meshes of `specs`, files resolved next to the scene file at `scene`, each
/// searched as `acceleration` says (with leaves of at most `leaf_size` triangles
/// for the fast hierarchy) with the ray-triangle test `triangle_test`.
pub fn build_meshes(
    specs: &[MeshSpec],
    acceleration: AccelerationSpec,
    leaf_size: u16,
    triangle_test: TriangleTestSpec,
    scene: &Path,
) -> Result<Vec<Mesh>, SceneError> {
    let folder = scene.parent().unwrap_or(Path::new(""));
    let mut meshes = Vec::with_capacity(specs.len());
    for (i, spec) in specs.iter().enumerate() {
        let obj = folder.join(&spec.obj);
        let data = read_obj(&obj).map_err(|e| SceneError::Asset {
            scene: scene.to_owned(),
            file: obj.clone(),
            message: format!("cannot load the mesh: {}", one_line(&e)),
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
        if spec.smooth_normals {
            require(
                scene,
                &format!("meshes[{i}].smooth_normals"),
                6,
                "smooth normals",
            )?;
            #[cfg(feature = "s6")]
            {
                mesh.shading = crate::meshes::mesh::Shading::Smooth;
            }
        }
        if spec.textured || spec.texture.is_some() || spec.texture_filter.is_some() {
            require(scene, &format!("meshes[{i}].textured"), 7, "textures")?;
            #[cfg(feature = "s7")]
            if let Some(texture) = crate::materials::texture::mesh_texture(spec, &data, scene)? {
                mesh.albedo = MeshAlbedo::Texture(texture);
            }
        }
        mesh.triangle_test = match triangle_test {
            TriangleTestSpec::MollerTrumbore => TriangleTest::MollerTrumbore,
            TriangleTestSpec::Watertight => TriangleTest::Watertight,
        };
        mesh.search = search(acceleration, leaf_size, &mesh);
        meshes.push(mesh);
    }
    Ok(meshes)
}

/// The search of `acceleration` over `mesh`. The scene file was checked against
/// this build, so a BVH is only asked for from session 6 on.
#[cfg_attr(
    not(feature = "s6"),
    expect(unused_variables, reason = "no BVH before session 6")
)]
fn search(acceleration: AccelerationSpec, leaf_size: u16, mesh: &Mesh) -> Search {
    #[allow(unreachable_patterns, reason = "every arm exists from session 6 on")]
    match acceleration {
        AccelerationSpec::Bbox => Search::BoundingBox,
        #[cfg(feature = "s6")]
        AccelerationSpec::Bvh => Search::Bvh(crate::acceleration::bvh::Bvh::build(mesh)),
        #[cfg(feature = "s6")]
        AccelerationSpec::Fast => Search::FastBvh(crate::acceleration::fast_bvh::FastBvh::build(
            mesh, leaf_size,
        )),
        _ => Search::BruteForce,
    }
}
