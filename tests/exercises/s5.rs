//! Session 5: the ray-triangle test and the slab test.

use raycourse::geometry::{Aabb, Ray, intersect_triangle};
use raycourse::maths::{Real, Vec3};

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, ensure, maybe, num, same_distance, vec};
use crate::say;
use crate::words::separator;

/// Session 5's exercises, in the book's order.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "s5.1",
        name: "s5_1_intersect_triangle",
        shown_by: "mesh",
        needs: &[],
        check: triangle,
    },
    Exercise {
        id: "s5.2",
        name: "s5_2_aabb_entry",
        shown_by: "mesh-bbox",
        needs: &[],
        check: slab,
    },
];

/// The triangle `A = (0, 0, 0)`, `B = (1, 0, 0)`, `C = (0, 1, 0)`: a ray straight
/// down through `(0.25, 0.5)` from height 1 meets it at `t = 1` with the weights
/// `b_B = 0.25` (of `B`, along `x`) and `b_C = 0.5` (of `C`, along `y`); from below
/// it is met too (both sides); past `b_B + b_C = 1`, beyond `t_max`, parallel to
/// the plane or pointing away, it is missed.
fn triangle() -> Outcome {
    let (a, b, c) = (Vec3::ZERO, Vec3::X, Vec3::Y);
    let down = Vec3::new(0.0, 0.0, -1.0);
    let cases = [
        (
            say!("s5-case-straight-down-through-0-25-0"),
            Vec3::new(0.25, 0.5, 1.0),
            down,
            10.0,
            Some((1.0, 0.25, 0.5)),
        ),
        (
            say!("s5-case-straight-up-from-below-through-0"),
            Vec3::new(0.2, 0.2, -2.0),
            -down,
            10.0,
            Some((2.0, 0.2, 0.2)),
        ),
        (
            say!("s5-case-down-through-0-6-0-6"),
            Vec3::new(0.6, 0.6, 1.0),
            down,
            10.0,
            None,
        ),
        (
            say!("s5-case-down-through-0-25-0-5"),
            Vec3::new(0.25, 0.5, 1.0),
            down,
            0.5,
            None,
        ),
        (
            say!("s5-case-parallel-to-the-triangle-s-plane"),
            Vec3::new(-1.0, 0.2, 0.0),
            Vec3::X,
            10.0,
            None,
        ),
        (
            say!("s5-case-pointing-away-up-from-above"),
            Vec3::new(0.25, 0.5, 1.0),
            -down,
            10.0,
            None,
        ),
    ];
    for (what, origin, direction, t_max, expected) in cases {
        let gave = intersect_triangle(&Ray::new(origin, direction), a, b, c, t_max);
        let right = match (gave, expected) {
            (Some(h), Some((t, beta, gamma))) => {
                (h.t - t).abs() < 1e-5
                    && (h.beta - beta).abs() < 1e-5
                    && (h.gamma - gamma).abs() < 1e-5
            }
            (None, None) => true,
            _ => false,
        };
        let show = |h: Option<(Real, Real, Real)>| {
            h.map_or(maybe(None), |(t, b, g)| {
                let (t, b, g, s) = (num(t), num(b), num(g), separator());
                format!("t = {t}{s}b_B = {b}{s}b_C = {g}")
            })
        };
        ensure(right, || {
            say!(
                "s5-the-triangle-a-ray-gave-expected",
                vec_a = vec(a),
                vec_b = vec(b),
                vec_c = vec(c),
                h_gamma = show(gave.map(|h| (h.t, h.beta, h.gamma))),
                show_expected = show(expected),
                what = what
            )
        })?;
    }
    generated::intersect_triangle(intersect_triangle)
}

/// The box `[-1, 1]^3`: from `(0, 0, 5)` down `-z` the ray enters at `t = 4`; from
/// `(-5, 0.5, 0)` along `+x`, at 4 too (the zero components of the direction give
/// infinite `1 / d`, which must still work); from inside, at once (0); beside the
/// box, behind the ray, or entering beyond `t_max`, never; lying in a face with a
/// direction component of `-0`, at 4 (the chapter's box on NaN).
fn slab() -> Outcome {
    let cube = Aabb {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    };
    let z = Vec3::new(0.0, 0.0, -1.0);
    let cases = [
        (
            say!("s5-case-from-0-0-5-along-z"),
            Vec3::new(0.0, 0.0, 5.0),
            z,
            100.0,
            Some(4.0),
        ),
        (
            say!("s5-case-from-5-0-5-0-along"),
            Vec3::new(-5.0, 0.5, 0.0),
            Vec3::X,
            100.0,
            Some(4.0),
        ),
        (
            say!("s5-case-from-5-0-0-along-x"),
            Vec3::new(5.0, 0.0, 0.0),
            -Vec3::X,
            100.0,
            Some(4.0),
        ),
        (
            say!("s5-case-from-inside-at-0-5-0"),
            Vec3::new(0.5, 0.0, 0.0),
            z,
            100.0,
            Some(0.0),
        ),
        (
            say!("s5-case-from-3-0-5-along-z"),
            Vec3::new(3.0, 0.0, 5.0),
            z,
            100.0,
            None,
        ),
        (
            say!("s5-case-from-0-0-5-along-z-2"),
            Vec3::new(0.0, 0.0, 5.0),
            -z,
            100.0,
            None,
        ),
        (
            say!("s5-case-from-0-0-5-along-z-3"),
            Vec3::new(0.0, 0.0, 5.0),
            z,
            3.0,
            None,
        ),
        (
            say!("s5-case-from-4-4-0-along-1"),
            Vec3::new(4.0, 4.0, 0.0),
            Vec3::new(-1.0, -1.0, 0.0),
            100.0,
            Some(3.0 * (2.0 as Real).sqrt()),
        ),
        (
            say!("s5-case-lying-in-the-face-x-1"),
            Vec3::new(-1.0, 0.0, 5.0),
            Vec3::new(-0.0, 0.0, -1.0),
            100.0,
            Some(4.0),
        ),
    ];
    for (what, origin, direction, t_max, expected) in cases {
        let ray = Ray::new(origin, direction);
        let gave = cube.entry(&ray, ray.direction.recip(), t_max);
        let right = same_distance(gave, expected, 1e-4);
        ensure(right, || {
            say!(
                "s5-the-box-from-to-a-ray",
                vec_cube = vec(cube.min),
                vec_cube2 = vec(cube.max),
                ray_direction = vec(ray.direction),
                maybe_gave = maybe(gave),
                maybe_expected = maybe(expected),
                what = what
            )
        })?;
    }
    generated::slab(Aabb::entry)
}
