//! How far from a triangle's plane a ray leaving the triangle must start, so that the
//! watertight test cannot meet the triangle again.

use crate::maths::{Real, Vec3, error_bound};

// ANCHOR: clearance
/// The distance from the plane of the triangle `corners`, beyond the hit point's own
/// error, at which a ray leaving the triangle's point `point` along a unit direction
/// must start, so that the watertight test
/// ([`ShearedRay::intersect`](crate::geometry::ShearedRay::intersect)) cannot find
/// the triangle again in front of it; `double_area` is `|(B - A) x (C - A)|`.
///
/// The hit point's own error ([`Hit::offset`](crate::geometry::Hit::offset)) is not
/// enough: a large triangle through the origin, such as a ground of two triangles at
/// `y = 0`, has points with no error at all along its normal, and a ray leaving one of
/// them starts on the plane, where the test computes a `t` of either sign. pbrt-v4
/// bounds the error of that `t` (section 6.8.7) by
/// `3 (delta_3 E Z + err(E) Z + err(Z) E) / |det|`, with, in the ray's sheared frame,
/// `Z` the corners' largest `|z|`, `E` the largest edge function, `err(E)` and
/// `err(Z)` their errors, and `det` the sum of the edge functions. With `extent` the
/// corners' largest coordinate difference from `point`, the sheared corners have
/// `|x|, |y| <= 2 extent` and `|z| <= sqrt(3) extent`; a ray through the triangle
/// has `E <= |det|`; and `|det| >= 2 area cos(theta)`, with `theta` the ray's angle
/// to the normal. The error of `t` is then at most
/// `3 sqrt(3) extent (2 delta_3 + (4 delta_2 + 15 delta_5) extent^2 / (area cos(theta)))`,
/// which is at most `zeta / cos(theta)` (as `cos(theta) <= 1`) for
///
/// `zeta = 3 sqrt(3) extent (2 delta_3 + (4 delta_2 + 15 delta_5) extent^2 / area)`;
///
/// and a ray starting `zeta` from the plane meets it at `t = -zeta / cos(theta)`,
/// behind its start, whatever `theta`. The bound is to first order, as pbrt's.
///
/// Only a sliver (a small area for its extent) needs much: `zeta` is capped at the
/// extent, which also stands for a triangle of no area, and where the guarantee no
/// longer holds. It is the hit triangle's own: a coplanar neighbour sliver whose
/// error is far larger can still be met again by a ray leaving near their shared
/// edge (`tests/suite/large_triangles.rs` shows it).
pub fn clearance(corners: [Vec3; 3], point: Vec3, double_area: Real) -> Real {
    let extent = corners
        .iter()
        .map(|&corner| (corner - point).abs().max_element())
        .fold(0.0, Real::max);
    let shape = extent * extent / (0.5 * double_area);
    let zeta = 3.0
        * Real::sqrt(3.0)
        * extent
        * (2.0 * error_bound(3) + (4.0 * error_bound(2) + 15.0 * error_bound(5)) * shape);
    zeta.min(extent)
}

/// [`offset_along`](crate::geometry::hit::offset_along) lengthened by `clearance`:
/// the offset of a ray leaving a triangle. The point may lie `|N| . error` on the
/// wrong side of the plane, so the new ray starts at least `clearance` from the plane
/// only if it moves by both.
pub fn offset_clearing(normal: Vec3, error: Vec3, clearance: Real) -> Vec3 {
    (normal.abs().dot(error) + clearance) * normal
}
// ANCHOR_END: clearance

#[cfg(test)]
mod tests {
    use super::*;

    /// Half of a square of side 200 on `y = 0`, the hit at its centre of mass.
    fn ground() -> ([Vec3; 3], Vec3) {
        let corners = [
            Vec3::new(-100.0, 0.0, -100.0),
            Vec3::new(100.0, 0.0, 100.0),
            Vec3::new(100.0, 0.0, -100.0),
        ];
        (corners, (corners[0] + corners[1] + corners[2]) / 3.0)
    }

    #[test]
    fn grows_with_the_triangle_and_its_thinness() {
        let (corners, point) = ground();
        let h = clearance(corners, point, 40_000.0);
        assert!(h > 0.0);
        let twice = clearance(corners.map(|c| 2.0 * c), 2.0 * point, 160_000.0);
        assert!((twice / h - 2.0).abs() < 1e-9, "{twice} against {h}");
        let thin = clearance(corners, point, 400.0);
        assert!(thin > 50.0 * h, "{thin} against {h}");
    }

    #[test]
    fn is_never_more_than_the_triangle_s_extent_nor_nan() {
        let (corners, point) = ground();
        let extent = 200.0 * 2.0 / 3.0;
        assert_eq!(clearance(corners, point, 0.0), extent);
        let point_triangle = [point; 3];
        assert_eq!(clearance(point_triangle, point, 0.0), 0.0);
    }
}
