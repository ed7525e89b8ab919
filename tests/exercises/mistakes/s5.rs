//! Session 5's mistakes: the ray-triangle test and the slab test.

use raycourse::geometry::{Aabb, Ray, TriangleHit};
use raycourse::maths::{Real, Vec3};

use super::{Mistake, Right};
use crate::generated;

/// Session 5's mistakes.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        exercise: "s5.1",
        what: "parallel when |det| < 1e-8",
        run: || {
            generated::intersect_triangle(|ray, a, b, c, t_max| {
                moller_trumbore(ray, [a, b, c], t_max, 1e-8, 0.0)
            })
        },
        rule: "rule-s5-1-only-det-0-means-parallel",
    },
    Mistake {
        exercise: "s5.1",
        what: "a hit only beyond t = 1e-4",
        run: || {
            generated::intersect_triangle(|ray, a, b, c, t_max| {
                moller_trumbore(ray, [a, b, c], t_max, 0.0, 1e-4)
            })
        },
        rule: "rule-s5-1-only-t-0-decides",
    },
    Mistake {
        exercise: "s5.1",
        what: "edges and corners left out (strict inequalities)",
        run: || {
            generated::intersect_triangle(|ray, a, b, c, t_max| {
                moller_trumbore(ray, [a, b, c], t_max, 0.0, 0.0)
                    .filter(|h| h.beta > 0.0 && h.gamma > 0.0 && h.beta + h.gamma < 1.0)
            })
        },
        rule: "rule-s5-1-edges-belong-to-the-triangle",
    },
    Mistake {
        exercise: "s5.2",
        what: "a miss when near >= far",
        run: || generated::slab(|bounds, ray, inv, t_max| slab(bounds, ray, inv, t_max, true)),
        rule: "rule-s5-2-miss-only-when-near-far",
    },
];

/// Session 5's right answers written otherwise than the course's.
pub const RIGHT: &[Right] = &[
    Right {
        exercise: "s5.1",
        what: "the plane first, then the weights from dot products",
        run: || generated::intersect_triangle(plane_first),
    },
    Right {
        exercise: "s5.2",
        what: "the chapter's simple way, without the widened exit",
        run: || generated::slab(|bounds, ray, inv, t_max| slab(bounds, ray, inv, t_max, false)),
    },
];

/// The Möller-Trumbore test of the chapter with two thresholds a student might
/// add: `|det| <= det_limit` read as parallel, and hits only beyond `t_min`.
fn moller_trumbore(
    ray: &Ray,
    [a, b, c]: [Vec3; 3],
    t_max: Real,
    det_limit: Real,
    t_min: Real,
) -> Option<TriangleHit> {
    let (e1, e2) = (b - a, c - a);
    let h = ray.direction.cross(e2);
    let det = e1.dot(h);
    if det.abs() <= det_limit {
        return None;
    }
    let w = ray.origin - a;
    let beta = w.dot(h) / det;
    let q = w.cross(e1);
    let gamma = ray.direction.dot(q) / det;
    let t = e2.dot(q) / det;
    let inside = beta >= 0.0 && gamma >= 0.0 && beta + gamma <= 1.0;
    (inside && t > t_min && t < t_max).then_some(TriangleHit { t, beta, gamma })
}

/// The triangle test the other way round: the plane's hit `t = (A - O) . n /
/// (d . n)` first, then the point's weights from the dot products of `P - A` with
/// the edges (Cramer's rule on the 2 x 2 system).
fn plane_first(ray: &Ray, a: Vec3, b: Vec3, c: Vec3, t_max: Real) -> Option<TriangleHit> {
    let (e1, e2) = (b - a, c - a);
    let normal = e1.cross(e2);
    let across = ray.direction.dot(normal);
    if across == 0.0 {
        return None;
    }
    let t = (a - ray.origin).dot(normal) / across;
    let p = ray.origin + t * ray.direction - a;
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (p1, p2) = (p.dot(e1), p.dot(e2));
    let area = d11 * d22 - d12 * d12;
    let beta = (d22 * p1 - d12 * p2) / area;
    let gamma = (d11 * p2 - d12 * p1) / area;
    let inside = beta >= 0.0 && gamma >= 0.0 && beta + gamma <= 1.0;
    (inside && t > 0.0 && t < t_max).then_some(TriangleHit { t, beta, gamma })
}

/// The slab test as the chapter gives it, without its widened exit, and, when
/// `touching_misses`, with the mistake of reading `near = far` as a miss.
fn slab(bounds: &Aabb, ray: &Ray, inv: Vec3, t_max: Real, touching_misses: bool) -> Option<Real> {
    let (mut near, mut far) = (0.0, t_max);
    for axis in 0..3 {
        let (first, second) = if inv[axis].is_sign_negative() {
            (bounds.max[axis], bounds.min[axis])
        } else {
            (bounds.min[axis], bounds.max[axis])
        };
        let enter = (first - ray.origin[axis]) * inv[axis];
        let leave = (second - ray.origin[axis]) * inv[axis];
        if enter > near {
            near = enter;
        }
        if leave < far {
            far = leave;
        }
        if near > far || (touching_misses && near == far) {
            return None;
        }
    }
    Some(near)
}
