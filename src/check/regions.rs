//! Which object each pixel of a stage shows, by name, to say where an image differs.

use crate::lights::Light;
use crate::scene::Scene;

/// The name of the object the camera ray through each pixel meets first, row-major
/// from the top: "the floor", "the left wall", "the light", "the sphere", "the
/// mesh", or "the background" where the ray meets nothing.
pub fn object_names(scene: &Scene) -> Vec<&'static str> {
    let camera = scene.camera;
    (0..camera.height)
        .flat_map(|row| (0..camera.width).map(move |column| (row, column)))
        .map(|(row, column)| {
            let hit = scene.intersect(&camera.ray(row, column));
            hit.map_or("the background", |hit| name(scene, hit.object))
        })
        .collect()
}

/// The name of object `object` of `scene`.
fn name(scene: &Scene, object: usize) -> &'static str {
    if matches!(scene.light, Some(Light::Sphere(l)) if l.object == object) {
        return "the light";
    }
    let Some(sphere) = scene.spheres.get(object) else {
        return "the mesh";
    };
    if sphere.radius < 100.0 {
        return "the sphere";
    }
    let c = sphere.centre.normalize();
    let walls = [
        (-c.y, "the floor"),
        (c.y, "the ceiling"),
        (-c.x, "the left wall"),
        (c.x, "the right wall"),
        (-c.z, "the back wall"),
        (c.z, "the wall behind the camera"),
    ];
    walls
        .into_iter()
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map_or("a wall", |w| w.1)
}
