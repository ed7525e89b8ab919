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
        french: [
            "le test rayon-triangle",
            "séance 5, «\u{a0}Un maillage\u{a0}»",
        ],
    },
    Exercise {
        id: "s5.2",
        name: "s5_2_aabb_entry",
        shown_by: "mesh-bbox",
        needs: &[],
        check: slab,
        french: [
            "le test des tranches",
            "séance 5, «\u{a0}La boîte englobante\u{a0}»",
        ],
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
            [
                "straight down through (0.25, 0.5)",
                "descendant à la verticale par (0,25\u{a0}; 0,5)",
            ],
            Vec3::new(0.25, 0.5, 1.0),
            down,
            10.0,
            Some((1.0, 0.25, 0.5)),
        ),
        (
            [
                "straight up from below through (0.2, 0.2)",
                "montant à la verticale depuis le dessous par (0,2\u{a0}; 0,2)",
            ],
            Vec3::new(0.2, 0.2, -2.0),
            -down,
            10.0,
            Some((2.0, 0.2, 0.2)),
        ),
        (
            [
                "down through (0.6, 0.6), past the long edge",
                "descendant par (0,6\u{a0}; 0,6), au-delà du grand côté",
            ],
            Vec3::new(0.6, 0.6, 1.0),
            down,
            10.0,
            None,
        ),
        (
            [
                "down through (0.25, 0.5) with t_max = 0.5",
                "descendant par (0,25\u{a0}; 0,5) avec t_max = 0,5",
            ],
            Vec3::new(0.25, 0.5, 1.0),
            down,
            0.5,
            None,
        ),
        (
            [
                "parallel to the triangle's plane",
                "parallèle au plan du triangle",
            ],
            Vec3::new(-1.0, 0.2, 0.0),
            Vec3::X,
            10.0,
            None,
        ),
        (
            [
                "pointing away, up from above",
                "qui s'en éloigne, montant depuis le dessus",
            ],
            Vec3::new(0.25, 0.5, 1.0),
            -down,
            10.0,
            None,
        ),
    ];
    for ([what, quoi], origin, direction, t_max, expected) in cases {
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
                "the triangle {}, {}, {}, a ray {what}: gave {}, expected {}",
                "le triangle {}, {}, {}, un rayon {quoi}\u{a0}: obtenu {}, attendu {}",
                vec(a),
                vec(b),
                vec(c),
                show(gave.map(|h| (h.t, h.beta, h.gamma))),
                show(expected)
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
            [
                "from (0, 0, 5) along -z",
                "issu de (0\u{a0}; 0\u{a0}; 5) selon -z",
            ],
            Vec3::new(0.0, 0.0, 5.0),
            z,
            100.0,
            Some(4.0),
        ),
        (
            [
                "from (-5, 0.5, 0) along +x",
                "issu de (-5\u{a0}; 0,5\u{a0}; 0) selon +x",
            ],
            Vec3::new(-5.0, 0.5, 0.0),
            Vec3::X,
            100.0,
            Some(4.0),
        ),
        (
            [
                "from (5, 0, 0) along -x",
                "issu de (5\u{a0}; 0\u{a0}; 0) selon -x",
            ],
            Vec3::new(5.0, 0.0, 0.0),
            -Vec3::X,
            100.0,
            Some(4.0),
        ),
        (
            [
                "from inside, at (0.5, 0, 0), along -z",
                "issu de l'intérieur, en (0,5\u{a0}; 0\u{a0}; 0), selon -z",
            ],
            Vec3::new(0.5, 0.0, 0.0),
            z,
            100.0,
            Some(0.0),
        ),
        (
            [
                "from (3, 0, 5) along -z, beside the box",
                "issu de (3\u{a0}; 0\u{a0}; 5) selon -z, à côté de la boîte",
            ],
            Vec3::new(3.0, 0.0, 5.0),
            z,
            100.0,
            None,
        ),
        (
            [
                "from (0, 0, 5) along +z, away from the box",
                "issu de (0\u{a0}; 0\u{a0}; 5) selon +z, qui s'éloigne de la boîte",
            ],
            Vec3::new(0.0, 0.0, 5.0),
            -z,
            100.0,
            None,
        ),
        (
            [
                "from (0, 0, 5) along -z with t_max = 3 (entered at t = 4, beyond t_max: missed, for the interval starts as [0, t_max])",
                "issu de (0\u{a0}; 0\u{a0}; 5) selon -z avec t_max = 3 (entré en t = 4, au-delà de t_max\u{a0}: manqué, car l'intervalle part de [0, t_max])",
            ],
            Vec3::new(0.0, 0.0, 5.0),
            z,
            3.0,
            None,
        ),
        (
            [
                "from (4, 4, 0) along (-1, -1, 0) / sqrt 2",
                "issu de (4\u{a0}; 4\u{a0}; 0) selon (-1\u{a0}; -1\u{a0}; 0) / sqrt 2",
            ],
            Vec3::new(4.0, 4.0, 0.0),
            Vec3::new(-1.0, -1.0, 0.0),
            100.0,
            Some(3.0 * (2.0 as Real).sqrt()),
        ),
        (
            [
                "lying in the face x = -1, from (-1, 0, 5) along (-0, 0, -1) (the chapter's box on NaN: 1 / -0 is -infinity, and 0 x infinity is NaN)",
                "couché dans la face x = -1, issu de (-1\u{a0}; 0\u{a0}; 5) selon (-0\u{a0}; 0\u{a0}; -1) (l'encadré du chapitre sur NaN\u{a0}: 1 / -0 vaut -l'infini, et 0 x l'infini vaut NaN)",
            ],
            Vec3::new(-1.0, 0.0, 5.0),
            Vec3::new(-0.0, 0.0, -1.0),
            100.0,
            Some(4.0),
        ),
    ];
    for ([what, quoi], origin, direction, t_max, expected) in cases {
        let ray = Ray::new(origin, direction);
        let gave = cube.entry(&ray, ray.direction.recip(), t_max);
        let right = same_distance(gave, expected, 1e-4);
        ensure(right, || {
            say!(
                "the box from {} to {}, a ray {what} (d = {}): gave {}, expected {}",
                "la boîte de {} à {}, un rayon {quoi} (d = {})\u{a0}: obtenu {}, attendu {}",
                vec(cube.min),
                vec(cube.max),
                vec(ray.direction),
                maybe(gave),
                maybe(expected)
            )
        })?;
    }
    generated::slab(Aabb::entry)
}
