//! The bounding box test of session 5: the mesh's triangles are tested only for rays
//! that meet the box around them.

use crate::geometry::{Ray, ShearedRay};
use crate::maths::Real;
use crate::meshes::{Mesh, MeshHit, Search};

// ANCHOR: bounding_box
/// Every triangle, but only for rays that meet the mesh's bounding box.
#[derive(Clone, Copy, Debug)]
pub struct BoundingBox;

impl Search for BoundingBox {
    fn name(&self) -> &'static str {
        "bounding box"
    }

    fn nearest(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        mesh.bounds.entry(ray, ray.direction.recip(), t_max)?;
        let all = 0..mesh.triangles.len() as u32;
        mesh.nearest_among(ray, &ShearedRay::new(ray), all, None, t_max)
    }
}
// ANCHOR_END: bounding_box
