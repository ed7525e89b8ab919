//! The nearest hit of a ray among the objects of a scene, before session 5: the
//! spheres. Session 5 adds the meshes (`scene/mesh_hits.rs`).

use crate::geometry::{Hit, Ray};
use crate::maths::Real;
use crate::scene::Scene;

impl Scene {
    // ANCHOR: nearest
    /// The nearest hit of `ray` among all objects: every sphere is tested and the
    /// smallest positive distance wins.
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let nearest = self.nearest_sphere(ray);
        nearest.map(|(t, i)| self.spheres[i].hit_at(ray, t, i))
    }
    // ANCHOR_END: nearest

    /// The distance to the nearest object that `ray` hits and that object's index:
    /// what [`Scene::intersect`] finds, without the hit record a shadow ray has no
    /// use for.
    pub fn nearest(&self, ray: &Ray) -> Option<(Real, usize)> {
        self.nearest_sphere(ray)
    }
}
