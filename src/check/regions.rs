//! Which object each pixel of a stage shows, by name, to say where an image differs.

use crate::lights::Light;
use crate::scene::Scene;

/// The place of the image that each pixel shows: the object the camera ray through
/// it meets first, row-major from the top, named as the catalogue names places
/// (`place-floor` is "floor"): "floor", "left-wall", "light", "sphere", "mesh",
/// or "background" where the ray meets nothing.
pub fn object_names(scene: &Scene) -> Vec<&'static str> {
    let camera = scene.camera;
    (0..camera.height)
        .flat_map(|row| (0..camera.width).map(move |column| (row, column)))
        .map(|(row, column)| {
            let hit = scene.intersect(&camera.ray(row, column));
            hit.map_or("background", |hit| name(scene, hit.object))
        })
        .collect()
}

/// The place name of object `object` of `scene`.
fn name(scene: &Scene, object: usize) -> &'static str {
    if matches!(scene.light, Some(Light::Sphere(l)) if l.object == object) {
        return "light";
    }
    let Some(sphere) = scene.spheres.get(object) else {
        return "mesh";
    };
    if sphere.radius < 100.0 {
        return "sphere";
    }
    let c = sphere.centre.normalize();
    let walls = [
        (-c.y, "floor"),
        (c.y, "ceiling"),
        (-c.x, "left-wall"),
        (c.x, "right-wall"),
        (-c.z, "back-wall"),
        (c.z, "wall-behind-camera"),
    ];
    walls
        .into_iter()
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map_or("wall", |w| w.1)
}
