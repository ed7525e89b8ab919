//! How far from a triangle's plane a ray leaving the triangle must start, so that the
//! watertight test cannot meet the triangle again.

use crate::maths::{Real, Vec3, error_bound};

// ANCHOR: clearance
/// The distance from the plane of the triangle `corners` at which a ray leaving the
/// triangle's point `point` must start, so that the watertight test
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
/// `err(Z)` their errors, and `det` the sum of the edge functions. With `reach` the
/// corners' largest coordinate difference from `point`, the sheared corners have
/// `|x|, |y| <= 2 reach` and `|z| <= sqrt(3) reach`; a ray through the triangle has
/// `E <= |det|`; and `|det| >= 2 area cos(theta)`, with `theta` the ray's angle to
/// the normal. A ray starting at a distance `zeta` from the plane meets it at
/// `t = -zeta / cos(theta)`, behind its start, and stays behind it by more than the
/// error, whatever `theta`, once
///
/// `zeta = 3 sqrt(3) reach (2 delta_3 + (4 delta_2 + 15 delta_5) reach^2 / area)`.
///
/// Only a sliver (a small area for its reach) needs much: `zeta` is capped at the
/// reach, which also stands for a triangle of no area.
pub fn clearance(corners: [Vec3; 3], point: Vec3, double_area: Real) -> Real {
    let reach = corners
        .iter()
        .map(|&corner| (corner - point).abs().max_element())
        .fold(0.0, Real::max);
    let shape = reach * reach / (0.5 * double_area);
    let zeta = 3.0
        * Real::sqrt(3.0)
        * reach
        * (2.0 * error_bound(3) + (4.0 * error_bound(2) + 15.0 * error_bound(5)) * shape);
    zeta.min(reach)
}

/// [`offset_along`](crate::geometry::hit::offset_along) lengthened to `clearance`
/// where it is shorter: the offset of a ray leaving a triangle, which must clear both
/// the hit point's rounding `error` and the triangle test's own ([`clearance`]).
pub fn offset_clearing(normal: Vec3, error: Vec3, clearance: Real) -> Vec3 {
    normal.abs().dot(error).max(clearance) * normal
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
    fn is_never_more_than_the_triangle_s_reach_nor_nan() {
        let (corners, point) = ground();
        let reach = 200.0 * 2.0 / 3.0;
        assert_eq!(clearance(corners, point, 0.0), reach);
        let point_triangle = [point; 3];
        assert_eq!(clearance(point_triangle, point, 0.0), 0.0);
    }
}
