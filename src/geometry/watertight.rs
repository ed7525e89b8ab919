//! The watertight ray-triangle test of Woop, Benthin and Wald (JCGT 2013).
//!
//! The course's test ([`crate::geometry::intersect_triangle`]) computes each barycentric
//! coordinate from the triangle's own edge vectors, so two triangles sharing an edge
//! round that edge differently: a ray through the edge can slip between them. Here
//! every vertex is first moved into the ray's own frame, where the ray is the `z`
//! axis; whether the ray passes left or right of an edge is then the sign of a 2D
//! cross product of the edge's two transformed vertices. Both triangles of a shared
//! edge compute that product from the same two numbers, so they always agree.

use crate::geometry::Ray;
use crate::geometry::TriangleHit;
use crate::maths::{Real, Vec3};

/// A ray in its own frame: translated to its origin, axes permuted so that the
/// largest component of the direction is `z`, then sheared so that the direction
/// becomes `(0, 0, 1)`: `x' = x + s_x z`, `y' = y + s_y z`, `z' = s_z z`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShearedRay {
    /// The ray's origin, which becomes the frame's origin.
    pub(crate) origin: Vec3,
    /// The axes that become `x`, `y` and `z`: `z` is the direction's largest.
    pub(crate) axes: [usize; 3],
    /// The shear factors `s_x`, `s_y` and the scale `s_z`.
    pub(crate) shear: Vec3,
}

// ANCHOR: ray_space
impl ShearedRay {
    /// The frame of `ray`. Dividing by the largest direction component keeps the
    /// shear factors within `[-1, 1]`. The largest axis becomes `z`: `x` if it is
    /// at least as large as the other two, else `y` if it is at least as large as
    /// `z`, else `z`. That choice is computed without a branch: for rays going every
    /// way, as diffuse bounces do, a branch would be guessed wrong half of the
    /// time, and the processor would throw its work away each time.
    pub fn new(ray: &Ray) -> Self {
        let size = ray.direction.abs();
        let x_largest = (size.x >= size.y) & (size.x >= size.z);
        let y_at_least_z = size.y >= size.z;
        let kz = usize::from(!x_largest) * (1 + usize::from(!y_at_least_z));
        let kx = (kz + 1) % 3;
        let ky = (kx + 1) % 3;
        let d = ray.direction.to_array();
        let sz = 1.0 / d[kz];
        Self {
            origin: ray.origin,
            axes: [kx, ky, kz],
            shear: Vec3::new(-d[kx] * sz, -d[ky] * sz, sz),
        }
    }

    /// `p` in the ray's frame, its `z` still unscaled (scaled only for a hit).
    #[inline]
    fn transform(&self, p: Vec3) -> Vec3 {
        let q = self.permute(p - self.origin);
        Vec3::new(q.x + self.shear.x * q.z, q.y + self.shear.y * q.z, q.z)
    }

    /// `q`'s coordinates along the axes that become `x`, `y` and `z`: a rotation of
    /// the three (`z` is the direction's largest axis, `x` and `y` the next two).
    #[inline]
    fn permute(&self, q: Vec3) -> Vec3 {
        match self.axes[2] {
            0 => Vec3::new(q.y, q.z, q.x),
            1 => Vec3::new(q.z, q.x, q.y),
            _ => q,
        }
    }
    // ANCHOR_END: ray_space

    // ANCHOR: watertight
    /// Where the ray meets the triangle `(a, b, c)` at a distance in `(0, t_max)`.
    ///
    /// In the ray's frame, the edge functions `e0 = b_x c_y - b_y c_x` (edge `bc`),
    /// `e1 = c_x a_y - c_y a_x` and `e2 = a_x b_y - a_y b_x` are twice the signed
    /// areas of the triangles the ray's axis makes with each edge. The ray meets the
    /// triangle when they share a sign (either side is hit); they are the
    /// barycentric weights of `a`, `b` and `c` once divided by their sum (each is
    /// recomputed with its exact sign when it rounds to 0, so that two triangles
    /// sharing an edge decide it alike). The distance is
    /// `t = (e0 a_z + e1 b_z + e2 c_z) s_z / (e0 + e1 + e2)`. pbrt-v4 refuses any `t`
    /// below a bound on its own rounding error, so that a ray spawned from a
    /// triangle cannot meet it again; but that bound grows without limit for a
    /// triangle seen nearly edge-on, whose hits it would then refuse far from the
    /// origin, and rays would slip through between its neighbours. Here the same
    /// bound sets how far from the triangle's plane a spawned ray starts instead
    /// (its clearance, `meshes::clearance`, added to [`crate::geometry::Hit::offset`]).
    #[inline]
    pub fn intersect(&self, a: Vec3, b: Vec3, c: Vec3, t_max: Real) -> Option<TriangleHit> {
        let (a, b, c) = (self.transform(a), self.transform(b), self.transform(c));
        let (e0, e1, e2) = (edge(b, c), edge(c, a), edge(a, b));
        if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0) {
            return None;
        }
        let det = e0 + e1 + e2;
        if det == 0.0 {
            return None;
        }
        let sz = self.shear.z;
        let (az, bz, cz) = (a.z * sz, b.z * sz, c.z * sz);
        let inv_det = 1.0 / det;
        let t = (e0 * az + e1 * bz + e2 * cz) * inv_det;
        (t > 0.0 && t < t_max).then_some(TriangleHit {
            t,
            beta: e1 * inv_det,
            gamma: e2 * inv_det,
        })
    }
    // ANCHOR_END: watertight
}

/// The edge function of the edge from `p` to `q` in the ray's frame,
/// `p_x q_y - p_y q_x`: on which side of the edge the ray passes. The triangle on the
/// other side of the edge computes `q_x p_y - q_y p_x`, exactly the negation, since
/// products commute and rounding is symmetric: the two never disagree. A value that
/// rounds to exactly 0 (the ray through the edge, or nearly) is recomputed with
/// its true sign; the neighbour, seeing the same 0, does the same. Woop et al.
/// recompute all three edges when any one is 0, which can decide the *other* edges
/// differently from the neighbours that share them: rays aimed at vertices slip
/// through. Deciding edge by edge keeps every shared edge consistent.
#[inline]
fn edge(p: Vec3, q: Vec3) -> Real {
    let e = p.x * q.y - p.y * q.x;
    if e == 0.0 {
        exact_difference_of_products(p.x, q.y, p.y, q.x)
    } else {
        e
    }
}

/// `a b - c d` with its sign exactly right (0 only when it is exactly 0), by
/// Kahan's algorithm: the rounding error of `c d` is recovered exactly with a fused
/// multiply-add and added back; the result is within 2 ulps (Jeannerod, Louvet and
/// Muller 2013).
#[cfg(not(feature = "f32"))]
fn exact_difference_of_products(a: Real, b: Real, c: Real, d: Real) -> Real {
    let cd = c * d;
    let error = (-c).mul_add(d, cd);
    a.mul_add(b, -cd) + error
}

/// `a b - c d` with its sign exactly right: in double precision the products of two
/// single-precision numbers are exact, so the one rounding of the difference
/// keeps its sign.
#[cfg(feature = "f32")]
fn exact_difference_of_products(a: Real, b: Real, c: Real, d: Real) -> Real {
    (f64::from(a) * f64::from(b) - f64::from(c) * f64::from(d)) as Real
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::triangle::intersect_triangle;

    const A: Vec3 = Vec3::new(0.0, 0.0, 0.0);
    const B: Vec3 = Vec3::new(1.0, 0.0, 0.0);
    const C: Vec3 = Vec3::new(0.0, 1.0, 0.0);

    fn hit(ray: &Ray, a: Vec3, b: Vec3, c: Vec3, t_max: Real) -> Option<TriangleHit> {
        ShearedRay::new(ray).intersect(a, b, c, t_max)
    }

    /// The ray's `z` axis is its direction's largest component, whatever its sign;
    /// on a tie `x` wins over `y` and `z`, and `y` over `z`, as the frame's
    /// branch-free choice promises; `x` and `y` follow it in cyclic order.
    #[test]
    fn the_largest_direction_component_becomes_z() {
        let cases = [
            (Vec3::new(3.0, -1.0, 2.0), [1, 2, 0]),
            (Vec3::new(1.0, -3.0, 2.0), [2, 0, 1]),
            (Vec3::new(1.0, 2.0, -3.0), [0, 1, 2]),
            (Vec3::new(-2.0, 2.0, 2.0), [1, 2, 0]),
            (Vec3::new(1.0, -2.0, 2.0), [2, 0, 1]),
        ];
        for (direction, axes) in cases {
            let ray = Ray::new(Vec3::ZERO, direction);
            assert_eq!(ShearedRay::new(&ray).axes, axes, "{direction}");
        }
    }

    #[test]
    fn agrees_with_the_course_test_inside_the_triangle() {
        let ray = Ray::new(Vec3::new(0.25, 0.5, 3.0), -Vec3::Z);
        let h = hit(&ray, A, B, C, Real::INFINITY).unwrap();
        assert_eq!((h.t, h.beta, h.gamma), (3.0, 0.25, 0.5));
        let oblique = Ray::new(Vec3::new(-1.0, 2.0, 3.0), Vec3::new(1.3, -1.5, -3.0));
        let (w, m) = (
            hit(&oblique, A, B, C, 10.0).unwrap(),
            intersect_triangle(&oblique, A, B, C, 10.0).unwrap(),
        );
        for (x, y) in [(w.t, m.t), (w.beta, m.beta), (w.gamma, m.gamma)] {
            assert!((x - y).abs() < 16.0 * Real::EPSILON, "{x} vs {y}");
        }
    }

    #[test]
    fn both_sides_are_hit_and_misses_are_missed() {
        let below = Ray::new(Vec3::new(0.25, 0.25, -1.0), Vec3::Z);
        assert_eq!(hit(&below, A, B, C, 10.0).unwrap().t, 1.0);
        let outside = Ray::new(Vec3::new(0.75, 0.75, 1.0), -Vec3::Z);
        assert!(hit(&outside, A, B, C, 10.0).is_none());
        let behind = Ray::new(Vec3::new(0.25, 0.25, 1.0), Vec3::Z);
        assert!(hit(&behind, A, B, C, 10.0).is_none());
        let parallel = Ray::new(Vec3::new(0.25, 0.25, 1.0), Vec3::X);
        assert!(hit(&parallel, A, B, C, 10.0).is_none());
        let too_far = Ray::new(Vec3::new(0.25, 0.25, 5.0), -Vec3::Z);
        assert!(hit(&too_far, A, B, C, 4.0).is_none());
    }

    #[test]
    fn degenerate_triangles_are_never_hit() {
        let ray = Ray::new(Vec3::new(0.0, 0.0, 1.0), -Vec3::Z);
        assert!(hit(&ray, A, A, A, 10.0).is_none());
        assert!(hit(&ray, A, B, 2.0 * B, 10.0).is_none());
    }

    #[test]
    fn a_ray_through_a_shared_edge_hits_one_side_or_both() {
        // Two triangles sharing the diagonal from (0, 0) to (1, 1) of the unit square:
        // every ray through the diagonal, ends excluded, is claimed by one of them.
        let (p, q) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0));
        let (left, right) = (Vec3::new(0.0, 1.0, 0.0), Vec3::new(1.0, 0.0, 0.0));
        for k in 1..1000 {
            let s = k as Real / 1000.0;
            let through = Vec3::new(s, s, 0.0);
            let origin = Vec3::new(0.3, -0.7, 2.0);
            let ray = Ray::new(origin, through - origin);
            let hits = [hit(&ray, p, q, left, 10.0), hit(&ray, q, p, right, 10.0)];
            assert!(hits.iter().any(Option::is_some), "leaked at s = {s}");
        }
    }

    #[test]
    fn the_exact_difference_has_the_true_sign() {
        // 0.1 * 0.3 and 0.3 * 0.1 round identically; (1 + eps) (1 - eps) < 1 exactly
        // although the rounded product is 1.
        assert_eq!(exact_difference_of_products(0.1, 0.3, 0.3, 0.1), 0.0);
        let e = Real::EPSILON;
        assert_eq!((1.0 + e) * (1.0 - e) - 1.0, 0.0);
        assert!(exact_difference_of_products(1.0 + e, 1.0 - e, 1.0, 1.0) < 0.0);
    }

    #[test]
    fn a_ray_starting_on_the_triangle_does_not_hit_it() {
        // The origin lies exactly in the triangle's plane: t is 0, never above its
        // error bound, whichever way the ray leaves.
        let (a, b, c) = (A + 1e4, B + 1e4, C + 1e4);
        let on = Vec3::new(1e4 + 0.25, 1e4 + 0.25, 1e4);
        for direction in [
            Vec3::Z,
            -Vec3::Z,
            Vec3::new(0.1, 0.2, 1.0),
            Vec3::new(-0.3, 0.1, -1.0),
        ] {
            assert!(hit(&Ray::new(on, direction), a, b, c, Real::INFINITY).is_none());
        }
    }
}
