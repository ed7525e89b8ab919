//! The nearest hit among the meshes of a scene.

use crate::geometry::{Hit, Ray};
use crate::maths::Real;
use crate::meshes::MeshHit;
use crate::scene::Scene;

impl Scene {
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
}
