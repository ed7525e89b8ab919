//! Values that are acceptable on their own but not together.

use std::path::Path;

use crate::scene_file::SceneError;
use crate::scene_file::format::{MAX_PIXELS, SceneFile};

/// Checks that the values of `file` make sense together: the image is not too
/// large, an aim has a point to look at, shadow rays go with a point light and light sampling with a sphere light.
pub fn check_consistency(file: &SceneFile, path: &Path) -> Result<(), SceneError> {
    let inconsistent = |key: &str, message: String| {
        Err(SceneError::Inconsistent {
            path: path.to_owned(),
            key: key.into(),
            message,
        })
    };
    let (r, c) = (&file.render, &file.camera);
    let pixels = u64::from(r.width.get()) * u64::from(r.height.get());
    let sphere_light = file.light.as_ref().is_some_and(|l| l.radius.is_some());
    if pixels > MAX_PIXELS {
        let size = format!("{} x {} is {pixels} pixels", r.width, r.height);
        return inconsistent(
            "render.width",
            format!("{size}; at most {MAX_PIXELS} are allowed"),
        );
    }
    if c.look_at.is_none() && (c.up.is_some() || c.plunge.is_some()) {
        let message = "`up` and `plunge` aim the camera: give it a `look_at` point";
        return inconsistent("camera.look_at", message.into());
    }
    if r.shadows && sphere_light {
        let message = "shadow rays are for a point light; a sphere light's shadows come from \
                       light_sampling or indirect rays";
        return inconsistent("render.shadows", message.into());
    }
    if r.light_sampling && !sphere_light {
        let message = "light sampling needs a sphere light: give [light] a radius";
        return inconsistent("render.light_sampling", message.into());
    }
    Ok(())
}
