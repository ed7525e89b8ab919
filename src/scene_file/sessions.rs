//! What each session adds to the scene file format, and the error for a scene that
//! asks for more than this build has: "a mirror material needs feature s2".

use std::path::Path;

use crate::scene_file::SceneError;
use crate::scene_file::features::{SESSION, comes_with};
use crate::scene_file::format::{AccelerationSpec, SceneFile};

/// The materials of later sessions, by their name in a scene file: the session that
/// teaches each and what it is (a message of the catalogue's `scene.ftl`).
const MATERIALS: &[(&str, u32, &str)] = &[
    ("mirror", 2, "scene-part-mirror"),
    ("glass", 2, "scene-part-glass"),
    ("fresnel-glass", 4, "scene-part-fresnel-glass"),
];

/// `Ok` if this build has `session`, else the error naming its feature; `what` is
/// the message that names what the scene asked for.
pub fn require(path: &Path, key: &str, session: u32, what: &'static str) -> Result<(), SceneError> {
    if session <= SESSION {
        Ok(())
    } else {
        Err(SceneError::NeedsFeature {
            path: path.to_owned(),
            key: key.to_owned(),
            what,
            remedy: comes_with(session),
        })
    }
}

/// Checks the materials of scene-file text `source` before it is read as a scene:
/// a material of a later session is not a variant this build can read, so it is
/// named here. Text that is not valid TOML is left to the reader, which reports
/// where.
pub fn check_materials(source: &str, path: &Path) -> Result<(), SceneError> {
    let Ok(file) = source.parse::<toml::Table>() else {
        return Ok(());
    };
    let spheres = file.get("spheres").and_then(toml::Value::as_array);
    for (i, sphere) in spheres.into_iter().flatten().enumerate() {
        let kind = match sphere.get("material") {
            Some(toml::Value::String(name)) => name.as_str(),
            Some(toml::Value::Table(table)) if table.len() == 1 => table.keys().next().unwrap(),
            _ => continue,
        };
        if let Some(&(_, session, what)) = MATERIALS.iter().find(|m| m.0 == kind) {
            require(path, &format!("spheres[{i}].material"), session, what)?;
        }
    }
    Ok(())
}

/// A key of the scene file that a session brings: whether a file uses it, its
/// dotted name, the session and what it is (a message of the catalogue's
/// `scene.ftl`).
type SessionKey = (fn(&SceneFile) -> bool, &'static str, u32, &'static str);

/// The keys that sessions 2 to 7 bring, in course order.
const KEYS: &[SessionKey] = &[
    (
        |f| f.render.gamma.is_some(),
        "render.gamma",
        2,
        "scene-part-gamma",
    ),
    (
        |f| f.render.shadows,
        "render.shadows",
        2,
        "scene-part-shadows",
    ),
    (
        |f| f.render.shadow_offset.is_some(),
        "render.shadow_offset",
        2,
        "scene-part-shadow-offset",
    ),
    (
        |f| f.render.indirect,
        "render.indirect",
        3,
        "scene-part-indirect",
    ),
    (
        |f| f.camera.antialiasing.is_some(),
        "camera.antialiasing",
        3,
        "scene-part-antialiasing",
    ),
    (
        |f| f.render.light_sampling,
        "render.light_sampling",
        4,
        "scene-part-light-sampling",
    ),
    (
        |f| f.render.russian_roulette.is_some(),
        "render.russian_roulette",
        4,
        "scene-part-russian-roulette",
    ),
    (
        |f| f.camera.lens.is_some(),
        "camera.lens",
        4,
        "scene-part-lens",
    ),
    (
        |f| f.light.as_ref().is_some_and(|l| l.radius.is_some()),
        "light.radius",
        4,
        "scene-part-sphere-light",
    ),
    (|f| !f.meshes.is_empty(), "meshes", 5, "scene-part-meshes"),
    (
        |f| f.render.acceleration != AccelerationSpec::None,
        "render.acceleration",
        5,
        "scene-part-acceleration",
    ),
    (
        |f| f.render.triangle_test.is_some(),
        "render.triangle_test",
        5,
        "scene-part-meshes",
    ),
    (
        |f| f.render.acceleration == AccelerationSpec::Bvh,
        "render.acceleration",
        6,
        "scene-part-bvh",
    ),
    (
        |f| f.camera.look_at.is_some() || f.camera.up.is_some() || f.camera.plunge.is_some(),
        "camera.look_at",
        7,
        "scene-part-aimed-camera",
    ),
];

/// Checks that every key `file` uses belongs to a session this build has.
pub fn check_sessions(file: &SceneFile, path: &Path) -> Result<(), SceneError> {
    for (used, key, session, what) in KEYS {
        if used(file) {
            require(path, key, *session, what)?;
        }
    }
    for (i, mesh) in file.meshes.iter().enumerate() {
        if mesh.smooth_normals {
            require(
                path,
                &format!("meshes[{i}].smooth_normals"),
                6,
                "scene-part-smooth-normals",
            )?;
        }
        if mesh.textured || mesh.texture.is_some() || mesh.texture_filter.is_some() {
            require(
                path,
                &format!("meshes[{i}].textured"),
                7,
                "scene-part-textures",
            )?;
        }
    }
    Ok(())
}
