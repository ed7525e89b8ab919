//! The meshes of [paths followed at once](crate::fast::paths::paths_at_once): once the
//! four-ray test has found a ray's nearest sphere, the meshes are searched closer
//! than it, as the course's [`Scene::intersect`] and [`Scene::nearest`] do after
//! their loop over the spheres, with the course's own searches ([`Mesh::intersect`],
//! [`Mesh::occluded`]), so a path meets what the recursion meets, to the bit.
//!
//! [`Mesh::intersect`]: crate::meshes::Mesh::intersect
//! [`Mesh::occluded`]: crate::meshes::Mesh::occluded

use crate::fast::paths::direct_at_once::{Direct, Towards};
use crate::geometry::{Hit, Ray};
use crate::materials::Material;
use crate::maths::{Colour, Real};
use crate::scene::Scene;
use crate::scene::occlusion::closer_than;

/// The hit record of the nearest mesh that `ray` meets closer than its nearest
/// sphere, `sphere` (distance and number), if one is, facing the ray, and the
/// mesh's albedo.
pub fn nearer_mesh(
    scene: &Scene,
    ray: &Ray,
    sphere: Option<(Real, usize)>,
) -> Option<(Hit, Colour)> {
    let hit = scene.nearest_mesh(ray, sphere.map_or(Real::INFINITY, |(t, _)| t))?;
    let Material::Diffuse { albedo } = hit.material else {
        unreachable!("paths at once are used only where every object is diffuse")
    };
    Some((hit.facing_the_ray(), albedo))
}

// ANCHOR: in_the_way
/// Whether a mesh lies on the shadow ray of `direct` before the light that its
/// nearest sphere, `sphere`, lets through: a triangle closer than the point light,
/// or than the sphere light's body where that body is the nearest sphere. It is
/// what [`Scene::nearest`] decides with its search of the meshes, asked of
/// [`Mesh::occluded`](crate::meshes::Mesh::occluded), which stops at the first
/// triangle it finds (both keep the hits closer than the limit, strictly).
pub fn in_the_way(scene: &Scene, direct: &Direct, sphere: Option<(Real, usize)>) -> bool {
    let Direct::Shadowed { ray, towards, .. } = direct else {
        return false;
    };
    let limit = match (*towards, sphere) {
        (Towards::Point(distance), _) if !closer_than(sphere, distance) => distance,
        (Towards::Body(light), Some((t, seen))) if seen == light => t,
        _ => return false,
    };
    scene.meshes.iter().any(|mesh| mesh.occluded(ray, limit))
}
// ANCHOR_END: in_the_way
