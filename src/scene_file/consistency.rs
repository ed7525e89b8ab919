//! Values that are acceptable on their own but not together.

use std::path::Path;

use crate::messages::said::Said;
use crate::scene_file::SceneError;
use crate::scene_file::format::{MAX_PIXELS, SceneFile};

/// Checks that the values of `file` make sense together: the image is not too
/// large, an aim has a point to look at, shadow rays go with a point light and light sampling with a sphere light.
pub fn check_consistency(file: &SceneFile, path: &Path) -> Result<(), SceneError> {
    let inconsistent = |key: &str, message: Said| {
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
        let message = Said::new("scene-too-many-pixels")
            .with("width", r.width.to_string())
            .with("height", r.height.to_string())
            .with("pixels", pixels)
            .with("most", MAX_PIXELS);
        return inconsistent("render.width", message);
    }
    if c.look_at.is_none() && (c.up.is_some() || c.plunge.is_some()) {
        return inconsistent("camera.look_at", Said::new("scene-aim-needs-look-at"));
    }
    if r.shadows && sphere_light {
        let message = Said::new("scene-shadows-need-point-light");
        return inconsistent("render.shadows", message);
    }
    if r.light_sampling && !sphere_light {
        let message = Said::new("scene-light-sampling-needs-sphere");
        return inconsistent("render.light_sampling", message);
    }
    Ok(())
}
