//! Ray-triangle intersection.

use crate::geometry::Ray;
use crate::maths::{Real, Vec3};

/// Where a ray meets a triangle: its distance and the barycentric coordinates of the
/// point, `P = b_A A + b_B B + b_C C` with `b_A = 1 - b_B - b_C`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    /// Distance along the ray.
    pub t: Real,
    /// Weight `b_B` of the second vertex.
    pub beta: Real,
    /// Weight `b_C` of the third vertex.
    pub gamma: Real,
}

/// Which ray-triangle test a mesh uses. Both find the same hits, up to rounding;
/// they differ where rounding decides, on the edges shared by two triangles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TriangleTest {
    /// Moller and Trumbore's barycentric solve ([`intersect_triangle`]): the course's
    /// version, used by the session-5 stages. A ray through a shared edge can,
    /// rarely, miss both triangles.
    MollerTrumbore,
    /// Woop, Benthin and Wald's watertight test ([`crate::geometry::ShearedRay`]): no ray slips
    /// between two triangles that share an edge.
    #[default]
    Watertight,
}

// ANCHOR: intersect_triangle
/// Where `ray` meets the triangle `(a, b, c)` at a distance in `(0, t_max)`, if it does.
///
/// The point `O + t d = A + b_B (B - A) + b_C (C - A)` is a 3x3 linear system in
/// `(t, b_B, b_C)`. With `e1 = B - A`, `e2 = C - A`, `w = O - A`, Cramer's rule
/// gives each unknown as a ratio of triple products; Moller and Trumbore compute
/// `h = d x e2` and `q = w x e1` once: `det = e1 . h`, `b_B = w . h / det`,
/// `b_C = d . q / det`, `t = e2 . q / det`. The point is inside when `b_B >= 0`,
/// `b_C >= 0` and `b_B + b_C <= 1`. A ray parallel to the plane has `det = 0` and
/// misses. (The hit calls `b_B` and `b_C` `beta` and `gamma`.)
///
/// Exercise s5.1, the ray-triangle test: book session 5, "A mesh".
#[inline]
pub fn intersect_triangle(
    ray: &Ray,
    a: Vec3,
    b: Vec3,
    c: Vec3,
    t_max: Real,
) -> Option<TriangleHit> {
    let e1 = b - a;
    let e2 = c - a;
    let h = ray.direction.cross(e2);
    let det = e1.dot(h);
    if det == 0.0 {
        return None;
    }
    let inv_det = 1.0 / det;
    let w = ray.origin - a;
    let beta = w.dot(h) * inv_det;
    if !(0.0..=1.0).contains(&beta) {
        return None;
    }
    let q = w.cross(e1);
    let gamma = ray.direction.dot(q) * inv_det;
    if gamma < 0.0 || beta + gamma > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inv_det;
    (t > 0.0 && t < t_max).then_some(TriangleHit { t, beta, gamma })
}
// ANCHOR_END: intersect_triangle

#[cfg(test)]
mod tests {
    use super::*;

    const A: Vec3 = Vec3::new(0.0, 0.0, 0.0);
    const B: Vec3 = Vec3::new(1.0, 0.0, 0.0);
    const C: Vec3 = Vec3::new(0.0, 1.0, 0.0);

    #[test]
    fn hit_distance_and_barycentrics() {
        let ray = Ray::new(Vec3::new(0.25, 0.5, 3.0), -Vec3::Z);
        let hit = intersect_triangle(&ray, A, B, C, Real::INFINITY).unwrap();
        assert_eq!((hit.t, hit.beta, hit.gamma), (3.0, 0.25, 0.5));
        let p = (1.0 - hit.beta - hit.gamma) * A + hit.beta * B + hit.gamma * C;
        assert_eq!(p, ray.at(hit.t));
    }

    #[test]
    fn both_sides_are_hit_and_misses_are_missed() {
        let below = Ray::new(Vec3::new(0.25, 0.25, -1.0), Vec3::Z);
        assert_eq!(intersect_triangle(&below, A, B, C, 10.0).unwrap().t, 1.0);
        let outside = Ray::new(Vec3::new(0.75, 0.75, 1.0), -Vec3::Z);
        assert!(intersect_triangle(&outside, A, B, C, 10.0).is_none());
        let behind = Ray::new(Vec3::new(0.25, 0.25, 1.0), Vec3::Z);
        assert!(intersect_triangle(&behind, A, B, C, 10.0).is_none());
        let parallel = Ray::new(Vec3::new(0.25, 0.25, 1.0), Vec3::X);
        assert!(intersect_triangle(&parallel, A, B, C, 10.0).is_none());
        let too_far = Ray::new(Vec3::new(0.25, 0.25, 5.0), -Vec3::Z);
        assert!(intersect_triangle(&too_far, A, B, C, 4.0).is_none());
    }

    #[test]
    fn degenerate_triangles_are_never_hit() {
        let ray = Ray::new(Vec3::new(0.0, 0.0, 1.0), -Vec3::Z);
        assert!(intersect_triangle(&ray, A, A, A, 10.0).is_none());
        assert!(intersect_triangle(&ray, A, B, 2.0 * B, 10.0).is_none());
    }
}
