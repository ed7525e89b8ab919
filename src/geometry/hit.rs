//! What a ray finds: the hit record.

use crate::materials::Material;
use crate::maths::{Colour, Real, Vec3};

// ANCHOR: hit
/// The nearest intersection of a ray with the scene: everything the renderer needs
/// to know about the point to decide its colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the ray.
    pub t: Real,
    /// The hit point `P`.
    pub point: Vec3,
    /// The unit normal `N` that shades the point, pointing out of the object. On a
    /// mesh with smooth normals (session 6) it is interpolated from the vertices.
    pub normal: Vec3,
    /// A bound on the rounding error of each coordinate of `point`: the true surface
    /// point lies in the box `point ± error`.
    pub error: Vec3,
    /// How far a new ray leaving the point starts from it (session 2), along the
    /// surface's own normal, outwards: just far enough to clear `error` (on a
    /// triangle, by the triangle's clearance too, session 5).
    pub offset: Vec3,
    /// What the surface is made of.
    pub material: Material,
    /// The radiance the surface emits.
    pub emission: Colour,
    /// Index of the object that was hit in the scene's list.
    pub object: usize,
    /// Whether the ray came from outside the object. For a sphere, decided by where
    /// the ray started, inside or outside, which rounding cannot get wrong (the sign
    /// of `d . N` can, for a ray that grazes the surface); a triangle has no inside,
    /// so for a mesh it is the sign of `d . N` with the triangle's own normal.
    pub from_outside: bool,
}
// ANCHOR_END: hit

impl Hit {
    // ANCHOR: facing
    /// The hit with its normal turned towards the side the ray came from. A diffuse
    /// surface is lit on whichever side a ray meets it, such as the inside of an
    /// enclosing sphere.
    pub fn facing_the_ray(&self) -> Hit {
        let side = if self.from_outside { 1.0 } else { -1.0 };
        Hit {
            normal: side * self.normal,
            ..*self
        }
    }
    // ANCHOR_END: facing
}

// ANCHOR: offset_along
/// The offset of a new ray's origin from a hit point whose coordinates are within
/// `error` of the surface with unit normal `normal`: along the normal by
/// `|N| . error`, the largest distance from the surface that the error box reaches
/// (pbrt-v4, section 6.8.6).
pub fn offset_along(normal: Vec3, error: Vec3) -> Vec3 {
    normal.abs().dot(error) * normal
}
// ANCHOR_END: offset_along
