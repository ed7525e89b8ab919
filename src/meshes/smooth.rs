//! Smooth shading: normals interpolated across triangles.

use crate::maths::{Real, Vec3};
use crate::meshes::Mesh;

impl Mesh {
    // ANCHOR: smooth_normal
    /// The shading normal `b_A N_A + b_B N_B + b_C N_C`, normalised, for the
    /// barycentric `weights` of a point of `triangle`: the vertex normals of the
    /// model, blended so that light varies smoothly across triangle edges. Falls
    /// back to the `geometric` normal if the mesh has no normals (a flat-shaded mesh
    /// has its normals removed when it is loaded) or they cancel, and is turned to
    /// the geometric normal's side.
    ///
    /// Exercise s6.3, the interpolated normal: book session 6, "Smooth normals".
    pub fn smooth_normal(&self, triangle: u32, weights: [Real; 3], geometric: Vec3) -> Vec3 {
        if self.normals.is_empty() {
            return geometric;
        }
        let corners = self.triangles[triangle as usize];
        let blended: Vec3 = (0..3)
            .map(|k| weights[k] * self.normals[corners[k] as usize])
            .sum();
        match blended.try_normalize() {
            Some(n) if n.dot(geometric) < 0.0 => -n,
            Some(n) => n,
            None => geometric,
        }
    }
    // ANCHOR_END: smooth_normal
}
