//! The simplest search of a mesh: every triangle, for every ray.

use crate::geometry::{Ray, ShearedRay};
use crate::maths::Real;
use crate::meshes::{Mesh, MeshHit, Search};

// ANCHOR: brute_force
/// Every triangle, for every ray: the course's first mesh stage.
#[derive(Clone, Copy, Debug)]
pub struct BruteForce;

impl Search for BruteForce {
    fn name(&self) -> &'static str {
        "brute force"
    }

    fn nearest(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        let all = 0..mesh.triangles.len() as u32;
        mesh.nearest_among(ray, &ShearedRay::new(ray), all, None, t_max)
    }
}
// ANCHOR_END: brute_force
