//! Session 4 on generated inputs: the light's cone from the hemisphere down to a
//! light seen under `1e-6` radians, its density at the edge, the lens's disk, and
//! thin lenses of every size, off the eye and along any direction.

use proptest::prelude::*;
use raycourse::camera::ThinLens;
use raycourse::lights::Cone;
use raycourse::maths::{PI, Real, Vec3, pixel_rng};

use super::s1::{direction, far, scale};
use super::sampling::{at, cell, describe, end_points, spread};
use super::{apart, differs, n, on_draws, on_generated, on_generated_cases, ulps, v};
use crate::known::Outcome;
use crate::say;

/// The seed of the samplers' draws.
const DRAWS_SEED: u64 = 4;

/// `sin^2(theta_max)` of generated cones: the hemisphere (1), wide cones, and
/// lights far away down to `1e-12` (`1e-6` in single precision), where
/// `cos(theta_max)` rounds to 1.
fn sin2s() -> impl Strategy<Value = Real> {
    let least: Real = if std::mem::size_of::<Real>() == 8 {
        12.0
    } else {
        6.0
    };
    prop_oneof![
        Just(1.0 as Real),
        Just(0.25 as Real),
        (0.0..least).prop_map(|e| (10.0 as Real).powf(-e)),
    ]
}

/// `1 - z` of a unit vector without cancellation: `(x^2 + y^2) / (1 + z)`.
fn one_minus_z(w: Vec3) -> Real {
    (w.x * w.x + w.y * w.y) / (1.0 + w.z)
}

/// Exercise s4.1 by its distribution, on generated cones: a unit vector inside the
/// cone at the end points and every draw, and over 5,120 draws `(1 - cos(theta))
/// / (1 - cos(theta_max))` uniform on `[0, 1]` (uniform per solid angle) and the
/// azimuth uniform, by a chi-square over 64 cells. `1 - cos(theta)` is measured as
/// `(x^2 + y^2) / (1 + z)`, so a light seen under `1e-6` radians is measured to
/// its last digits.
pub fn cone_sample(yours: impl Fn(&Cone, Real, Real) -> Vec3) -> Outcome {
    on_generated_cases("Cone::sample", 32, sin2s(), |sin2| {
        let cone = Cone::from_sin2(sin2);
        let inside = |u1, u2| {
            let w: Vec3 = yours(&cone, u1, u2);
            let unit = (w.length() - 1.0).abs() <= ulps(1024.0);
            let ratio = one_minus_z(w) / cone.one_minus_cos_max;
            if w.is_finite() && unit && w.z >= -ulps(64.0) && ratio <= 1.0 + ulps(1024.0) {
                return Ok((ratio, w));
            }
            Err(say!(
                "generated-s4-the-cone-of-sin-2-theta",
                sin2 = n(sin2),
                cone_one_minus_cos_max = n(cone.one_minus_cos_max),
                u1_u2 = at(u1, u2),
                w = v(w)
            ) + &small_cone_hint(&cone))
        };
        for (u1, u2) in end_points() {
            inside(u1, u2)?;
        }
        let place = |u1, u2| inside(u1, u2).map(|(ratio, w)| cell(ratio, w.y, w.x));
        spread(DRAWS_SEED, place, |k| {
            describe("(1 - cos(theta)) / (1 - cos(theta_max))", k)
        })
        .map_err(|why| {
            say!(
                "generated-s4-the-cone-of-sin-2-theta-2",
                sin2 = n(sin2),
                why = why
            ) + &small_cone_hint(&cone)
        })
    })
}

/// For a cone so narrow that `cos(theta_max)` is 1 to rounding, why an answer
/// computed from the cosine goes wrong.
fn small_cone_hint(cone: &Cone) -> String {
    if cone.one_minus_cos_max > 1e-3 {
        return String::new();
    }
    say!("generated-s4-for-so-small-a-cone-1")
}

/// Cosines to ask a cone's density at: its edge itself and a few roundings either
/// side of it, inside, outside, and straight along the axis.
fn cosines(cone: Cone) -> impl Strategy<Value = Real> {
    let edge = cone.cos_max;
    prop_oneof![
        Just(1.0 as Real),
        Just(edge),
        (-8.0..8.0 as Real).prop_map(move |k| edge + k * ulps(1.0)),
        (0.0..1.0 as Real).prop_map(move |u| 1.0 - u * cone.one_minus_cos_max),
        -1.0..1.0 as Real,
    ]
}

/// Exercise s4.2 on generated cones and cosines, against the course's density:
/// `1 / (2 pi (1 - cos(theta_max)))` inside, 0 outside, to 64 roundings; on the
/// edge itself, either.
pub fn cone_pdf(yours: impl Fn(&Cone, Real) -> Real) -> Outcome {
    let inputs = sin2s().prop_flat_map(|sin2| {
        let cone = Cone::from_sin2(sin2);
        (Just(sin2), cosines(cone))
    });
    on_generated("Cone::pdf", inputs, |(sin2, cos)| {
        let cone = Cone::from_sin2(sin2);
        let gave = yours(&cone, cos);
        let course = course::lights::Cone::from_sin2(sin2);
        let expected = course.pdf(cos);
        let inside = 1.0 / (2.0 * PI * course.one_minus_cos_max);
        let on_edge = cos == course.cos_max && (gave == 0.0 || gave == expected);
        if on_edge || (gave - expected).abs() <= ulps(64.0) * expected {
            return Ok(());
        }
        let case = say!(
            "generated-s4-the-cone-of-sin-2-theta-3",
            sin2 = n(sin2),
            cone_cos_max = n(cone.cos_max),
            cone_cos_max2 = apart(cos, cone.cos_max).0
        );
        let why = pdf_diagnosis(gave, expected, inside, &cone);
        let (gave, expected) = apart(gave, expected);
        Err(differs(&case, &gave, &expected, why))
    })
}

/// Which rule of the cone's density `gave` breaks.
fn pdf_diagnosis(gave: Real, expected: Real, inside: Real, cone: &Cone) -> Option<String> {
    if expected == 0.0 {
        return Some(say!("generated-s4-outside-the-cone-cos-theta-cos"));
    }
    if gave == 0.0 {
        return Some(say!("generated-s4-this-direction-is-inside-the-cone"));
    }
    let from_cosine = 1.0 / (2.0 * PI * (1.0 - cone.cos_max));
    if (gave - inside).abs() > (from_cosine - inside).abs() * 0.5 && cone.one_minus_cos_max < 1e-3 {
        return Some(say!("generated-s4-1-cos-theta-max-taken-from"));
    }
    Some(say!(
        "generated-s4-the-density-is-one-over-the",
        inside = n(inside)
    ))
}

/// Exercise s4.3 by its distribution: at the end points and every draw a point of
/// the unit disk, and over 5,120 draws `r^2` uniform on `[0, 1]` (uniform per
/// unit area) and the azimuth uniform, by a chi-square over 64 cells.
pub fn disk(yours: impl Fn(Real, Real) -> (Real, Real)) -> Outcome {
    on_draws("sample_disk", || {
        let on_disk = |u1, u2| {
            let (x, y) = yours(u1, u2);
            let r2 = x * x + y * y;
            if r2.is_finite() && r2 <= 1.0 + ulps(64.0) {
                return Ok((r2, y, x));
            }
            Err(say!(
                "generated-s4-gave-expected-a-point-of-the",
                u1_u2 = at(u1, u2),
                value = n(x),
                y = n(y)
            ))
        };
        for (u1, u2) in end_points() {
            on_disk(u1, u2)?;
        }
        let place = |u1, u2| on_disk(u1, u2).map(|(r2, y, x)| cell(r2, y, x));
        spread(DRAWS_SEED, place, |k| describe("r^2", k))
    })
}

/// A generated thin lens and pinhole ray: the aperture (`1e-4` to `1e4`), the
/// focus distance (from a tenth to ten times as far), the eye (off the origin, up
/// to `1e6` apertures away, `1e2` in single precision),
/// and a direction towards `-z` of any length from `1e-3` to `1e3`.
fn lenses() -> impl Strategy<Value = (ThinLens, Vec3, Vec3)> {
    let ahead = direction().prop_filter("looking ahead, along -z", |d| d.z < -0.05);
    (
        scale(),
        -1.0..1.0 as Real,
        far(),
        direction(),
        ahead,
        -3.0..3.0 as Real,
    )
        .prop_map(|(aperture, focus, eye, towards, d, length)| {
            let lens = ThinLens {
                aperture,
                focus: aperture * (10.0 as Real).powf(focus) * 10.0,
            };
            (
                lens,
                aperture * eye * towards,
                d * (10.0 as Real).powf(length),
            )
        })
}

/// The draws of each generated lens.
const LENS_DRAWS: u64 = 256;

/// Exercise s4.4 by what the chapter promises, on generated lenses: every ray
/// starts on the lens, in the eye's plane `z = start.z` within `aperture` of the
/// eye, and passes through the point where the pinhole ray meets the focus plane,
/// `start + focus / -d_z * d` (to 1024 roundings of the scene's size); over 256
/// draws, the starts cover the lens, `E[|o - start|^2] = aperture^2 / 2` within
/// 10%.
pub fn thin_lens(
    yours: impl Fn(&ThinLens, Vec3, Vec3, &mut raycourse::maths::PixelRng) -> (Vec3, Vec3),
) -> Outcome {
    on_generated_cases("ThinLens::refocus", 64, lenses(), |(lens, start, d)| {
        let focus_point = start + d * (lens.focus / -d.z);
        let size = start.length() + lens.focus / -d.z * d.length() + lens.aperture;
        let mut spread = 0.0;
        for k in 0..LENS_DRAWS {
            let (origin, direction) = yours(&lens, start, d, &mut pixel_rng(DRAWS_SEED, k));
            lens_fault(&lens, start, d, origin, direction, focus_point, size)?;
            spread += (origin - start).length_squared() / (lens.aperture * lens.aperture);
        }
        let mean = spread / LENS_DRAWS as Real;
        if (mean - 0.5).abs() <= 0.05 {
            return Ok(());
        }
        Err(say!(
            "generated-s4-the-mean-of-o-start-2",
            start_d = lens_case(&lens, start, d),
            mean = n(mean),
            of_new = if (mean - 1.0 / 3.0).abs() < 0.05 {
                say!("generated-s4-1-3-is-the-mean-of")
            } else {
                String::new()
            },
            LENS_DRAWS = LENS_DRAWS
        ))
    })
}

/// The lens and pinhole ray as the book writes them.
fn lens_case(lens: &ThinLens, start: Vec3, d: Vec3) -> String {
    say!(
        "generated-s4-the-lens-of-radius-focused-at",
        lens_aperture = n(lens.aperture),
        lens_focus = n(lens.focus),
        start = v(start),
        d = v(d)
    )
}

/// The first promise of the chapter that the ray `(origin, direction)` through the
/// lens breaks, with why.
fn lens_fault(
    lens: &ThinLens,
    start: Vec3,
    d: Vec3,
    origin: Vec3,
    direction: Vec3,
    focus_point: Vec3,
    size: Real,
) -> Result<(), String> {
    let tolerance = ulps(1024.0) * size;
    let case = lens_case(lens, start, d);
    let shown = say!(
        "generated-s4-the-ray-from-along",
        origin = v(origin),
        direction = v(direction)
    );
    let lateral = (origin - start).truncate().length();
    if !((origin.z - start.z).abs() <= tolerance && lateral <= lens.aperture + tolerance) {
        return Err(say!(
            "generated-s4-starts-off-the-lens-a-ray",
            start_z = n(start.z),
            lens_aperture = n(lens.aperture),
            case = case,
            shown = shown
        ));
    }
    let along = (focus_point - origin).dot(direction) / direction.length_squared();
    let miss = (origin + along * direction - focus_point).length();
    if along > 0.0 && miss <= tolerance {
        return Ok(());
    }
    Err(say!(
        "generated-s4-misses-the-point-where-the-pinhole",
        focus_point = v(focus_point),
        miss = n(miss),
        origin_direction = focus_rule(start, d, lens, origin, direction),
        case = case,
        shown = shown
    ))
}

/// Which rule about the focus point a ray through the lens breaks.
fn focus_rule(start: Vec3, d: Vec3, lens: &ThinLens, origin: Vec3, direction: Vec3) -> String {
    let passes = |p: Vec3| {
        let along = (p - origin).dot(direction) / direction.length_squared();
        (origin + along * direction - p).length() <= 1e-3 * (p - origin).length()
    };
    if passes(start + d.normalize() * lens.focus) {
        return say!("generated-s4-the-focus-plane-lies-at-the");
    }
    if passes(d * (lens.focus / -d.z)) {
        return say!("generated-s4-the-pinhole-ray-starts-at-the");
    }
    say!("generated-s4-every-ray-through-the-lens-passes")
}
