//! Session 5 on generated inputs: the ray-triangle test on triangles of every
//! size, far away, met from both sides, near their edges, grazed, parallel or
//! degenerate; the slab test on boxes flat or not, from inside, on a face, along
//! the axes with `-0`.

use proptest::prelude::*;
use raycourse::geometry::{Aabb, Ray, TriangleHit};
use raycourse::maths::{Real, Vec3};

use super::s1::{direction, far, scale};
use super::{differs, n, on_generated, ulps, v};
use crate::known::{Outcome, maybe};
use crate::say;

/// A generated triangle and ray: the corners, the ray, `t_max`, and the point's
/// weights `(b_B, b_C)` as the ray was aimed (where it meets the plane, to
/// rounding).
#[derive(Clone, Debug)]
pub struct TriangleCase {
    corners: [Vec3; 3],
    ray: Ray,
    t_max: Real,
    aimed: (Real, Real),
    /// The triangle's size: the scale its corners were drawn at.
    size: Real,
    /// How far from the triangle the ray starts: the distance to the hit.
    distance: Real,
    /// Whether every number of the case is exact (powers of two), so that a point
    /// on an edge is on it to the last bit and the answer is never in doubt.
    exact: bool,
}

/// Corners of a generated triangle of `size` around `place`: any triangle, one
/// lying in a plane `z = constant` (for rays parallel to it), or a degenerate
/// one (two corners the same).
fn corners() -> impl Strategy<Value = ([Vec3; 3], Real, Vec3)> {
    let shape = prop_oneof![
        4 => (direction(), direction(), direction()).prop_map(|(a, b, c)| [a, b, c]),
        1 => (-1.0..1.0 as Real, -1.0..1.0 as Real, -1.0..1.0 as Real, -1.0..1.0 as Real)
            .prop_map(|(x, y, p, q)| [Vec3::ZERO, Vec3::new(x, y, 0.0), Vec3::new(p, q, 0.0)]),
        1 => (direction(), direction()).prop_map(|(a, c)| [a, a, c]),
        1 => (direction(), direction()).prop_map(|(a, b)| [a, b, a]),
    ];
    (shape, scale(), far(), direction()).prop_map(|(shape, size, far, towards)| {
        let place = far * size * towards;
        (shape.map(|p| place + size * p), size, place)
    })
}

/// Generated triangle cases: rays aimed at weights from -0.2 to 1.2 (so near and
/// across every edge), from `1e-3` to `1e3` sizes away, along any direction or
/// parallel to a flat triangle's plane (`d_z = +-0`), with `t_max` unbounded or
/// a rounding before or after the hit; and rays exactly through a corner or an
/// edge.
fn triangle_cases() -> impl Strategy<Value = TriangleCase> {
    prop_oneof![4 => any_triangle_case(), 1 => edge_case()]
}

/// The triangle `(0, 0, 0), (s, 0, 0), (0, s, 0)` moved by whole sizes, `s` a
/// power of two, and a ray straight down or up through a corner, the middle of an
/// edge or a point inside, from a power of two away: every number is exact, so
/// a point on an edge has a weight of exactly 0, or weights summing to exactly 1,
/// and is a hit (`b_B >= 0`, `b_C >= 0`, `b_B + b_C <= 1`, edges included).
fn edge_case() -> impl Strategy<Value = TriangleCase> {
    let weights = prop_oneof![
        Just((0.0 as Real, 0.0 as Real)),
        Just((1.0, 0.0)),
        Just((0.0, 1.0)),
        Just((0.5, 0.0)),
        Just((0.0, 0.5)),
        Just((0.5, 0.5)),
        Just((0.25, 0.25)),
    ];
    let shift = (-4i32..4, -4i32..4, -4i32..4);
    (-10i32..10, shift, weights, -3i32..6, any::<bool>()).prop_map(
        |(k, (i, j, l), (beta, gamma), away, up)| {
            let size = (2.0 as Real).powi(k);
            let a = size * Vec3::new(i as Real, j as Real, l as Real);
            let corners = [a, a + size * Vec3::X, a + size * Vec3::Y];
            let point = a + size * Vec3::new(beta, gamma, 0.0);
            let distance = size * (2.0 as Real).powi(away);
            let d = if up { Vec3::Z } else { -Vec3::Z };
            TriangleCase {
                corners,
                ray: Ray::new(point - distance * d, d),
                t_max: Real::INFINITY,
                aimed: (beta, gamma),
                size,
                distance,
                exact: true,
            }
        },
    )
}

/// Generated triangle cases of any shape and place (see [`triangle_cases`]).
fn any_triangle_case() -> impl Strategy<Value = TriangleCase> {
    let weight = || prop_oneof![-0.2..1.2 as Real, Just(0.0 as Real), Just(0.5 as Real)];
    let parallel = (-1.0..1.0 as Real, -1.0..1.0 as Real, any::<bool>())
        .prop_map(|(x, y, negative)| Vec3::new(x, y, if negative { -0.0 } else { 0.0 }));
    let heading = prop_oneof![4 => direction(), 1 => parallel];
    let t_max = prop_oneof![Just(Real::INFINITY), 0.5..2.0 as Real, Just(1.0 as Real)];
    (
        corners(),
        weight(),
        weight(),
        heading,
        -3.0..3.0 as Real,
        t_max,
    )
        .prop_filter_map(
            "a direction to normalise",
            |((corners, size, _), beta, gamma, heading, away, t_max)| {
                let [a, b, c] = corners;
                let point = a + beta * (b - a) + gamma * (c - a);
                let distance = size * (10.0 as Real).powf(away);
                let d = heading.try_normalize()?;
                let ray = Ray::new(point - distance * d, d);
                Some(TriangleCase {
                    corners,
                    ray,
                    t_max: t_max * distance,
                    aimed: (beta, gamma),
                    size,
                    distance,
                    exact: false,
                })
            },
        )
}

/// The triangle test's tolerance for this case, in weights: 256 roundings of the
/// largest number in play (the triangle's distance from the origin and the
/// ray's from the triangle, in the triangle's sizes), divided by the cosine of
/// the ray with the plane, which magnifies them.
fn triangle_tolerance(case: &TriangleCase) -> Real {
    let [a, b, c] = case.corners;
    let normal = (b - a).cross(c - a).normalize_or_zero();
    let cosine = case.ray.direction.dot(normal).abs();
    let spread = 1.0 + (a.length() + case.distance) / case.size;
    ulps(256.0) * spread / cosine
}

/// Exercise s5.1 on generated triangles and rays, against the course's test: a
/// hit with the same `t`, `b_B`, `b_C` (to the tolerance) or no hit; where the
/// point is within the tolerance of an edge, or the hit of `t_max`, either.
/// Degenerate triangles and rays parallel to the plane miss.
pub fn intersect_triangle(
    yours: impl Fn(&Ray, Vec3, Vec3, Vec3, Real) -> Option<TriangleHit>,
) -> Outcome {
    on_generated("intersect_triangle", triangle_cases(), |case| {
        let [a, b, c] = case.corners;
        let gave = yours(&case.ray, a, b, c, case.t_max);
        let expected = course::geometry::intersect_triangle(
            &course::geometry::Ray {
                origin: case.ray.origin,
                direction: case.ray.direction,
            },
            a,
            b,
            c,
            case.t_max,
        );
        let expected = expected.map(|h| (h.t, h.beta, h.gamma));
        let gave_numbers = gave.map(|h| (h.t, h.beta, h.gamma));
        if triangle_agrees(&case, gave_numbers, expected) {
            return Ok(());
        }
        Err(differs(
            &triangle_text(&case),
            &hit_text(gave_numbers),
            &hit_text(expected),
            triangle_diagnosis(&case, gave_numbers, expected),
        ))
    })
}

/// Whether the student's answer may stand beside the course's.
fn triangle_agrees(
    case: &TriangleCase,
    gave: Option<(Real, Real, Real)>,
    expected: Option<(Real, Real, Real)>,
) -> bool {
    let tolerance = triangle_tolerance(case);
    let (beta, gamma) = case.aimed;
    let margin = beta.min(gamma).min(1.0 - beta - gamma);
    let undecided = !case.exact
        && (!tolerance.is_finite()
            || margin.abs() <= tolerance
            || (case.distance - case.t_max).abs() <= tolerance * case.distance);
    match (gave, expected) {
        (None, None) => true,
        (Some((t, b, g)), Some((te, be, ge))) => {
            (t - te).abs() <= tolerance * te.abs()
                && (b - be).abs() <= tolerance
                && (g - ge).abs() <= tolerance
        }
        _ => undecided && !degenerate(case),
    }
}

/// Whether the case's triangle has two corners the same, or the ray is parallel
/// to a flat triangle: `det = 0`, which the chapter's test reads as a miss.
fn degenerate(case: &TriangleCase) -> bool {
    let [a, b, c] = case.corners;
    a == b || a == c || (a.z == b.z && a.z == c.z && case.ray.direction.z == 0.0)
}

/// A triangle and ray as the book writes them.
fn triangle_text(case: &TriangleCase) -> String {
    let [a, b, c] = case.corners;
    say!(
        "generated-s5-the-triangle-a-b-c-the",
        a = v(a),
        b = v(b),
        c = v(c),
        ray_origin = v(case.ray.origin),
        ray_direction = v(case.ray.direction),
        case_t_max = n(case.t_max)
    )
}

/// A triangle hit as the book writes it: `t = 2, b_B = 0.25, b_C = 0.5`, or no hit.
fn hit_text(hit: Option<(Real, Real, Real)>) -> String {
    match hit {
        None => maybe(None),
        Some((t, b, g)) => {
            let s = crate::words::separator();
            format!("t = {}{s}b_B = {}{s}b_C = {}", n(t), n(b), n(g))
        }
    }
}

/// Which rule of the triangle test the student's answer breaks.
fn triangle_diagnosis(
    case: &TriangleCase,
    gave: Option<(Real, Real, Real)>,
    expected: Option<(Real, Real, Real)>,
) -> Option<String> {
    let [a, b, c] = case.corners;
    let det = (b - a).dot(case.ray.direction.cross(c - a));
    match (gave, expected) {
        (Some(_), None) if degenerate(case) => Some(say!("generated-s5-det-0-the-ray-is-parallel")),
        (Some((t, _, _)), None) if t >= case.t_max => {
            Some(say!("generated-s5-a-hit-at-or-beyond-t"))
        }
        (Some(_), None) => Some(say!("generated-s5-the-point-is-outside-the-triangle")),
        (None, Some((t, _, _))) => Some(missed_rule(t, det, case)),
        (Some((_, gb, gg)), Some((_, eb, eg))) if (gb - eg).abs() + (gg - eb).abs() < 1e-6 => {
            Some(say!("generated-s5-b-b-and-b-c-are"))
        }
        _ => None,
    }
}

/// Why the student's test missed a hit of the course's at distance `t`, with
/// the determinant `det`.
fn missed_rule(t: Real, det: Real, case: &TriangleCase) -> String {
    let (beta, gamma) = case.aimed;
    if case.exact && beta.min(gamma).min(1.0 - beta - gamma) == 0.0 {
        return say!(
            "generated-s5-the-point-is-on-the-triangle",
            beta = n(beta),
            gamma = n(gamma)
        );
    }
    // Several mistakes can miss the same hit: each that could is named.
    let rules = [
        (
            det < 0.0,
            say!("generated-s5-the-ray-meets-the-triangle-from", det = n(det)),
        ),
        (
            t < 1e-3,
            say!("generated-s5-a-hit-at-t-nearer-than", value = n(t)),
        ),
        (
            det.abs() < 1e-3 && case.size < 1e-1,
            say!("generated-s5-for-a-triangle-this-small-det", det = n(det)),
        ),
    ];
    let named: Vec<String> = rules
        .into_iter()
        .filter(|(holds, _)| *holds)
        .map(|(_, why)| why)
        .collect();
    if named.is_empty() {
        return say!("generated-s5-the-point-is-inside-the-triangle");
    }
    named.join(&say!("generated-s5-or"))
}

/// A generated box and ray: the box, the ray, `t_max`.
#[derive(Clone, Debug)]
pub struct SlabCase {
    bounds: (Vec3, Vec3),
    ray: Ray,
    t_max: Real,
}

/// Extents of a generated box: each side from `1e-4` to `1e4`, or 0 (a flat box,
/// the box of a triangle lying in a plane `x = constant`).
fn extents() -> impl Strategy<Value = Vec3> {
    let side = || prop_oneof![4 => scale(), 1 => Just(0.0 as Real)];
    (side(), side(), side()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// A direction along an axis, signed, with `+0` or `-0` for the other two.
fn axis_direction() -> impl Strategy<Value = Vec3> {
    (0usize..3, any::<bool>(), any::<bool>()).prop_map(|(axis, negative, zero_sign)| {
        let zero = if zero_sign { -0.0 } else { 0.0 };
        let mut d = Vec3::splat(zero);
        d[axis] = if negative { -1.0 } else { 1.0 };
        d
    })
}

/// Generated slab cases: boxes of every size, far from the origin, some flat;
/// rays from outside aimed at a point in or near the box, from inside, or lying
/// in a face, along any direction or an axis; `t_max` unbounded or near the box.
fn slab_cases() -> impl Strategy<Value = SlabCase> {
    let heading = prop_oneof![3 => direction(), 2 => axis_direction()];
    let aim = (-1.2..1.2 as Real, -1.2..1.2 as Real, -1.2..1.2 as Real);
    let start = prop_oneof![3 => -3.0..3.0 as Real, 1 => Just(0.0 as Real), 1 => Just(1.0 as Real)];
    let t_max = prop_oneof![Just(Real::INFINITY), 0.0..4.0 as Real];
    (
        extents(),
        far(),
        direction(),
        aim,
        heading,
        start,
        t_max,
        0usize..3,
    )
        .prop_map(|(extent, far, towards, (x, y, z), d, start, t_max, face)| {
            let size = extent.max_element().max(1e-4);
            let centre = far * size * towards;
            let mut target = centre + 0.5 * extent * Vec3::new(x, y, z);
            if start == 1.0 {
                target[face] = centre[face] - 0.5 * extent[face];
            }
            let length = (extent.length() + size) * start.max(0.0);
            SlabCase {
                bounds: (centre - 0.5 * extent, centre + 0.5 * extent),
                ray: Ray::new(target - length * d, d),
                t_max: if t_max.is_finite() {
                    t_max * (length + extent.length())
                } else {
                    t_max
                },
            }
        })
}

/// The course's entry into the box from `min` to `max`, with `t_max` scaled by
/// `reach`.
fn course_entry(case: &SlabCase, (min, max): (Vec3, Vec3), reach: Real) -> Option<Real> {
    let ray = course::geometry::Ray {
        origin: case.ray.origin,
        direction: case.ray.direction,
    };
    let bounds = course::geometry::Aabb { min, max };
    bounds.entry(&ray, ray.direction.recip(), case.t_max * reach)
}

/// Boxes within `by` of the case's that the ray may miss though it meets the box
/// itself: shrunk on every side (never past flat), and moved by `by` along each
/// axis either way (a box flat along two axes, a segment, cannot shrink away from
/// a ray that rounding alone makes meet it).
fn nearby_boxes(case: &SlabCase, by: Real) -> Vec<(Vec3, Vec3)> {
    let (min, max) = case.bounds;
    let step = (0.5 * (max - min)).min(Vec3::splat(by));
    let mut boxes = vec![(min + step, max - step)];
    for axis in 0..3 {
        for sign in [-1.0, 1.0] {
            let mut shift = Vec3::ZERO;
            shift[axis] = sign * by;
            boxes.push((min + shift, max + shift));
        }
    }
    boxes
}

/// Exercise s5.2 on generated boxes and rays, against the course's slab test: the
/// same entry distance, or no hit, wherever moving the box's faces or `t_max` by
/// 64 roundings of the scene's size leaves the course's answer as it is; in
/// between, either, within those distances.
pub fn slab(yours: impl Fn(&Aabb, &Ray, Vec3, Real) -> Option<Real>) -> Outcome {
    on_generated("Aabb::entry", slab_cases(), |case| {
        let (min, max) = case.bounds;
        let gave = yours(
            &Aabb { min, max },
            &case.ray,
            case.ray.direction.recip(),
            case.t_max,
        );
        let by = ulps(64.0) * (case.ray.origin.length() + max.length() + min.length());
        let expected = course_entry(&case, case.bounds, 1.0);
        let grown = (min - Vec3::splat(by), max + Vec3::splat(by));
        let outer = course_entry(&case, grown, 1.0 + ulps(64.0));
        let may_miss = nearby_boxes(&case, by)
            .into_iter()
            .any(|bounds| course_entry(&case, bounds, 1.0 - ulps(64.0)).is_none());
        let right = match (gave, outer) {
            (Some(t), Some(low)) => t >= low - by && t <= expected.unwrap_or(t) + by,
            (Some(_), None) => false,
            (None, _) => expected.is_none() || may_miss,
        };
        if right {
            return Ok(());
        }
        Err(differs(
            &slab_text(&case),
            &maybe(gave),
            &maybe(expected),
            slab_diagnosis(&case, gave, expected),
        ))
    })
}

/// A box and ray as the book writes them.
fn slab_text(case: &SlabCase) -> String {
    say!(
        "generated-s5-the-box-from-to-the-ray",
        case_bounds = v(case.bounds.0),
        case_bounds2 = v(case.bounds.1),
        ray_origin = v(case.ray.origin),
        ray_direction = v(case.ray.direction),
        case_t_max = n(case.t_max)
    )
}

/// Which rule of the slab test the student's answer breaks.
fn slab_diagnosis(case: &SlabCase, gave: Option<Real>, expected: Option<Real>) -> Option<String> {
    let (min, max) = case.bounds;
    let flat = (max - min).min_element() == 0.0;
    let inside = case.ray.origin.cmpge(min).all() && case.ray.origin.cmple(max).all();
    match (gave, expected) {
        (None, Some(_)) if flat => Some(say!("generated-s5-a-flat-box-no-thickness-along")),
        (Some(t), Some(_)) if inside && t != 0.0 => {
            Some(say!("generated-s5-from-inside-the-box-the-ray"))
        }
        (Some(t), None) if t >= case.t_max => Some(say!("generated-s5-an-entry-at-or-beyond-t")),
        _ if case.ray.direction.to_array().contains(&0.0) => {
            Some(say!("generated-s5-a-zero-component-of-the-direction"))
        }
        _ => None,
    }
}
