//! The nearest hit of a ray among the objects of a scene from session 5 on: the
//! spheres, then the meshes.

use crate::geometry::{Hit, Ray};
use crate::maths::Real;
use crate::meshes::MeshHit;
use crate::scene::Scene;

impl Scene {
    // ANCHOR: nearest
    /// The nearest hit of `ray` among all objects: the nearest sphere, unless a mesh
    /// is hit closer.
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let nearest = self.nearest_sphere(ray);
        if let Some(hit) = self.nearest_mesh(ray, nearest.map_or(Real::INFINITY, |n| n.0)) {
            return Some(hit);
        }
        nearest.map(|(t, i)| self.spheres[i].hit_at(ray, t, i))
    }
    // ANCHOR_END: nearest

    // ANCHOR: nearest_mesh
    /// The nearest mesh hit closer than `t_max`, numbered after the spheres.
    pub fn nearest_mesh(&self, ray: &Ray, t_max: Real) -> Option<Hit> {
        let mut best: Option<(MeshHit, usize)> = None;
        for (k, mesh) in self.meshes.iter().enumerate() {
            let limit = best.map_or(t_max, |(b, _)| b.at.t);
            if let Some(hit) = mesh.intersect(ray, limit) {
                best = Some((hit, k));
            }
        }
        best.map(|(hit, k)| self.meshes[k].hit_record(ray, hit, self.spheres.len() + k))
    }
    // ANCHOR_END: nearest_mesh

    // ANCHOR: nearest_distance
    /// The distance to the nearest object, sphere or mesh, that `ray` hits and that
    /// object's index: what [`Scene::intersect`] finds, returned without the hit
    /// record a shadow ray has no use for (a mesh's is still built, then dropped).
    pub fn nearest(&self, ray: &Ray) -> Option<(Real, usize)> {
        let nearest = self.nearest_sphere(ray);
        if let Some(hit) = self.nearest_mesh(ray, nearest.map_or(Real::INFINITY, |n| n.0)) {
            return Some((hit.t, hit.object));
        }
        nearest
    }
    // ANCHOR_END: nearest_distance
}
