//! What session 7 adds to a scene file: textures and an aimed camera.

use std::path::Path;

use crate::camera::aim::aim;
use crate::files::Files;
use crate::materials::texture::{Filter, Texture};
use crate::maths::Vec3;
use crate::meshes::{Mesh, MeshAlbedo};
use crate::messages::said::Said;
use crate::scene::Scene;
use crate::scene_file::format::{FilterSpec, MeshSpec, SceneFile};
use crate::scene_file::{SceneError, one_line, session6};

/// The scene of session 6 with what session 7 reads in `file`: textured meshes, and a
/// camera aimed at `camera.look_at`, raised by `camera.plunge` degrees around it.
pub fn scene(file: &SceneFile, path: &Path, files: &dyn Files) -> Result<Scene, SceneError> {
    let mut scene = session6::scene(file, path, files)?;
    for (mesh, spec) in scene.meshes.iter_mut().zip(&file.meshes) {
        let asked = spec.textured || spec.texture.is_some() || spec.texture_filter.is_some();
        if asked && let Some(texture) = mesh_texture(spec, mesh, path, files)? {
            mesh.albedo = MeshAlbedo::Texture(texture);
        }
    }
    let camera = &file.camera;
    if let Some(target) = camera.look_at {
        let up = camera.up.map_or(Vec3::Y, |u| u.0);
        let plunge = camera.plunge.map_or(0.0, |p| p.0);
        let (eye, orientation) = aim(camera.position.0, target.0, up, plunge).ok_or_else(|| {
            SceneError::Inconsistent {
                path: path.to_owned(),
                key: "camera.up".into(),
                message: Said::new("scene-camera-cannot-aim"),
            }
        })?;
        scene.camera.position = eye;
        scene.camera.orientation = orientation;
    }
    Ok(scene)
}

/// The texture a scene file's mesh asks for, read from `files`: its own `texture`
/// file (next to the scene file at `scene`), else the OBJ material's `map_Kd`, when
/// `textured`. `None` when there is neither, or when the OBJ file has no texture
/// coordinates: texturing is then off for that mesh.
pub fn mesh_texture(
    spec: &MeshSpec,
    mesh: &Mesh,
    scene: &Path,
    files: &dyn Files,
) -> Result<Option<Texture>, SceneError> {
    let file = match &spec.texture {
        Some(name) => Some(scene.parent().unwrap_or(Path::new("")).join(name)),
        None => mesh.texture_file.clone(),
    };
    let Some(file) = file.filter(|_| !mesh.uvs.is_empty()) else {
        return Ok(None);
    };
    let filter = match spec.texture_filter {
        Some(FilterSpec::Bilinear) => Filter::Bilinear,
        Some(FilterSpec::Nearest) | None => Filter::Nearest,
    };
    files
        .read(&file)
        .map_err(|e| e.to_string())
        .and_then(|bytes| Texture::decode(&bytes, filter))
        .map(Some)
        .map_err(|e| SceneError::Asset {
            scene: scene.to_owned(),
            file,
            message: Said::new("scene-cannot-read-texture").with("why", one_line(&e)),
        })
}
