//! Texture coordinates at a point of a triangle.

use crate::maths::Real;
use crate::meshes::Mesh;

impl Mesh {
    // ANCHOR: uv
    /// The texture coordinates of the point of barycentric `weights` in `triangle`:
    /// `b_A uv_A + b_B uv_B + b_C uv_C`.
    pub fn uv_at(&self, triangle: u32, weights: [Real; 3]) -> [Real; 2] {
        let corners = self.triangles[triangle as usize];
        let mut uv = [0.0; 2];
        for (k, &corner) in corners.iter().enumerate() {
            let [u, v] = self.uvs[corner as usize];
            uv[0] += weights[k] * u;
            uv[1] += weights[k] * v;
        }
        uv
    }
    // ANCHOR_END: uv
}
