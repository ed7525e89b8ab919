//! Session 3 on generated inputs: the cosine-weighted direction and the Gaussian
//! filter by their distributions, the frame by what makes it a frame, the
//! indirect bounce in furnaces of every scale.

use proptest::prelude::*;
use raycourse::geometry::{Hit, Ray};
use raycourse::integrator::Tracer;
use raycourse::maths::frame::Frame;
use raycourse::maths::{Colour, Real, Vec3};

use super::s1::{direction, scale};
use super::sampling::{DRAWS, at, cell, describe, end_points, spread};
use super::{apart, differs, n, on_draws, on_generated, on_generated_cases, ulps, v};
use crate::known::Outcome;
use crate::s1::scene;
use crate::say;

/// The seed of the samplers' draws.
const DRAWS_SEED: u64 = 3;

/// A direction of the hemisphere must be a unit vector with `z >= 0`, to
/// `1024` roundings.
fn unit_above(w: Vec3, u1: Real, u2: Real) -> Result<(), String> {
    if w.is_finite() && (w.length() - 1.0).abs() <= ulps(1024.0) && w.z >= -ulps(64.0) {
        return Ok(());
    }
    let gave = say!(
        "generated-s3-gave-expected-a-unit-vector-with",
        u1_u2 = at(u1, u2),
        w = v(w)
    );
    if w.is_finite() {
        return Err(gave);
    }
    Err(say!("generated-s3-every-u-in-0-1-gives", gave = gave))
}

/// Exercise s3.1 by its distribution: at the end points a unit vector above the
/// surface; over 5,120 draws, `cos^2(theta) = z^2` is uniform on `[0, 1]` (the
/// density `cos(theta) / pi` makes `P(z^2 <= c) = c`) and the azimuth uniform,
/// which a chi-square over 64 cells tests.
pub fn cosine_direction(yours: impl Fn(Real, Real) -> Vec3) -> Outcome {
    on_draws("sample_cosine_hemisphere", || {
        for (u1, u2) in end_points() {
            unit_above(yours(u1, u2), u1, u2)?;
        }
        let place = |u1, u2| {
            let w = yours(u1, u2);
            unit_above(w, u1, u2)?;
            Ok(cell(w.z * w.z, w.y, w.x))
        };
        spread(DRAWS_SEED, place, |k| describe("cos^2(theta)", k))
    })
}

/// Normals of every direction, and near the poles on purpose: `(a, b, +-1)` with
/// `a`, `b` down to `1e-17`, `-0` among them, where a frame dividing by `1 + n_z`
/// loses its digits or divides by 0.
fn normals() -> impl Strategy<Value = Vec3> {
    let pole = (
        prop_oneof![Just(1.0 as Real), Just(-1.0 as Real)],
        1i32..=17,
        -1.0..1.0 as Real,
        -1.0..1.0 as Real,
    )
        .prop_map(|(z, k, a, b)| {
            let small = (10.0 as Real).powi(-k);
            Vec3::new(a * small, b * small, z).normalize()
        });
    let exact = prop_oneof![
        Just(Vec3::new(-0.0, 0.0, -1.0)),
        Just(Vec3::new(0.0, -0.0, 1.0)),
        Just(Vec3::new(0.0, 0.0, -1.0)),
    ];
    prop_oneof![2 => direction(), 2 => pole, 1 => exact]
}

/// The frame as the book writes it.
fn frame_text(t1: Vec3, t2: Vec3, axis: Vec3) -> String {
    format!("T1 = {}, T2 = {}, N = {}", v(t1), v(t2), v(axis))
}

/// Exercise s3.2 by what the chapter promises, not the course's bits (another
/// right frame is as good): `T1`, `T2` unit vectors at right angles to each other
/// and to `N`, `N` itself the third axis, right-handed (`T1 x T2 = N`), each to
/// 256 roundings, for every normal, the poles included.
pub fn frame(yours: impl Fn(Vec3) -> Frame) -> Outcome {
    on_generated("Frame::new", normals(), |normal| {
        let f = yours(normal);
        let Some(why) = frame_fault(&f, normal) else {
            return Ok(());
        };
        let course = course::maths::frame::Frame::new(normal);
        let case = say!("generated-s3-n", normal = v(normal));
        Err(differs(
            &case,
            &frame_text(f.t1, f.t2, f.n),
            &frame_text(course.t1, course.t2, course.n),
            Some(why),
        ))
    })
}

/// The first rule of a frame that `f`, built for `normal`, breaks; near `-z`,
/// where the rule broken is one of size or angle, with why it goes wrong there.
fn frame_fault(f: &Frame, normal: Vec3) -> Option<String> {
    if (f.n - normal).length() > ulps(256.0) {
        return Some(say!("generated-s3-n-itself-is-the-frame-s"));
    }
    if let Some(why) = measure_fault(f, normal) {
        return Some(why + &pole_hint(normal));
    }
    (f.t1.cross(f.t2).dot(normal) < 0.0).then(|| say!("generated-s3-t1-x-t2-n-the-frame"))
}

/// The first rule of lengths and angles that the frame `f` of `normal` breaks, to
/// 256 roundings.
fn measure_fault(f: &Frame, normal: Vec3) -> Option<String> {
    let tolerance = ulps(256.0);
    if !(f.t1.is_finite() && f.t2.is_finite() && f.n.is_finite()) {
        return Some(say!("generated-s3-the-frame-has-a-nan-or"));
    }
    for (name, t) in [("T1", f.t1), ("T2", f.t2)] {
        if (t.length() - 1.0).abs() > tolerance {
            return Some(say!(
                "generated-s3-has-the-length-the-tangents-are",
                length = apart(t.length(), 1.0).0,
                name = name
            ));
        }
    }
    for (name, dot) in [
        ("T1 . N", f.t1.dot(normal)),
        ("T2 . N", f.t2.dot(normal)),
        ("T1 . T2", f.t1.dot(f.t2)),
    ] {
        if dot.abs() > tolerance {
            return Some(say!(
                "generated-s3-the-three-axes-are-at-right",
                dot = n(dot),
                name = name
            ));
        }
    }
    None
}

/// Near `N = -z`, why a frame dividing by `1 + n_z` goes wrong.
fn pole_hint(normal: Vec3) -> String {
    if normal.z > -0.99 {
        return String::new();
    }
    say!("generated-s3-near-n-z-1-n-z")
}

/// The draws of each generated bounce.
const BOUNCES_DRAWN: u32 = 2048;

/// A furnace: a sphere of radius `R` around `centre`, wall albedo `a`, and a point
/// light at the centre of power `Phi = 4 pi^2 R^2 / a`, so that by direct light
/// alone the wall glows with radiance `Phi / (4 pi R^2) a / pi = 1` everywhere.
fn furnace(centre: Vec3, radius: Real, wall: Real) -> raycourse::scene::Scene {
    let power = 4.0 * raycourse::maths::PI.powi(2) * radius * radius / wall;
    let [x, y, z] = centre.to_array();
    scene(&format!(
        "[render]\nwidth = 8\nheight = 8\nbounces = 1\nindirect = true\ngamma = 2.2\n\
         [camera]\nposition = [{x:?}, {y:?}, {z:?}]\nfov = 60\n\
         [light]\nposition = [{x:?}, {y:?}, {z:?}]\nintensity = {power:?}\n\
         [[spheres]]\ncentre = [{x:?}, {y:?}, {z:?}]\nradius = {radius:?}\n\
         material = {{ diffuse = [{wall:?}, {wall:?}, {wall:?}] }}\n"
    ))
}

/// A generated furnace: its centre (up to `1e8` radii away, `1e4` in single
/// precision), radius (`1e-4` to `1e4`), wall albedo, the floor's direction from
/// the centre, the floor's albedo (each channel its own) and the bounces allowed.
fn furnaces() -> impl Strategy<Value = (Vec3, Real, Real, Vec3, Colour, u32)> {
    let far: Real = if std::mem::size_of::<Real>() == 8 {
        8.0
    } else {
        4.0
    };
    let channel = || 0.05..0.95 as Real;
    (
        (direction(), 0.0..far),
        scale(),
        0.2..0.8 as Real,
        direction(),
        (channel(), channel(), channel()),
        1u32..=3,
    )
        .prop_map(|((towards, e), radius, wall, down, (r, g, b), bounces)| {
            let centre = (10.0 as Real).powf(e) * radius * towards;
            (centre, radius, wall, down, Colour::new(r, g, b), bounces)
        })
}

/// Exercise s3.3 in generated furnaces. Every point of a furnace's wall sees the
/// same wall, so with `k` bounces left it sends `L_k = 1 + a L_(k-1)`, `L_0 = 1`,
/// and a bounce from the floor with `b` bounces allowed brings back
/// `albedo L_(b-1)` whichever direction it draws; the mean of 2,048 bounces must
/// be within 12% of it in each channel (a right answer that draws its directions
/// otherwise, uniformly with the weight `2 cos(theta)`, is within 4 standard
/// deviations of it).
pub fn indirect_light(yours: impl Fn(&mut Tracer, &Hit, Colour, u32) -> Colour) -> Outcome {
    on_generated_cases(
        "Tracer::indirect_light",
        48,
        furnaces(),
        |(centre, radius, wall, down, albedo, bounces)| {
            let furnace = furnace(centre, radius, wall);
            let mut tracer = Tracer::new(&furnace);
            let Some(floor) = tracer.trace(&Ray::new(centre, down)) else {
                return Ok(());
            };
            let floor = floor.facing_the_ray();
            let mean = (0..BOUNCES_DRAWN)
                .map(|_| yours(&mut tracer, &floor, albedo, bounces))
                .sum::<Colour>()
                / BOUNCES_DRAWN as Real;
            let seen: Real = (0..bounces).map(|k| wall.powi(k as i32)).sum();
            let expected = albedo * seen;
            let ratio = mean / expected;
            if (ratio - Colour::ONE).abs().max_element() <= 0.12 {
                return Ok(());
            }
            let case = say!(
                "generated-s3-the-furnace-of-radius-around-wall",
                radius = n(radius),
                centre = v(centre),
                wall = n(wall),
                point = v(floor.point),
                albedo = v(albedo),
                bounces = bounces,
                value = BOUNCES_DRAWN
            );
            let why = bounce_diagnosis(ratio, wall, bounces);
            Err(differs(&case, &v(mean), &v(expected), why))
        },
    )
}

/// Which rule a bounce bringing back `ratio` times the right light (per channel)
/// breaks, in a furnace of wall albedo `wall` with `bounces` allowed.
fn bounce_diagnosis(ratio: Colour, wall: Real, bounces: u32) -> Option<String> {
    if ratio.max_element() < 0.05 {
        return Some(say!("generated-s3-it-brought-back-nothing-the-bounce"));
    }
    if ratio.max_element() - ratio.min_element() > 0.2 {
        return Some(say!(
            "generated-s3-the-channels-are-off-by-different",
            ratio = v(ratio)
        ));
    }
    let mean = ratio.element_sum() / 3.0;
    let seen = |k: u32| -> Real { (0..k).map(|i| wall.powi(i as i32)).sum() };
    if bounces > 1 && (mean * seen(bounces) / seen(bounces - 1) - 1.0).abs() < 0.05 {
        return Some(say!("generated-s3-it-is-what-one-bounce-fewer"));
    }
    let hint = crate::s3::weight_hint(mean);
    (!hint.is_empty()).then(|| hint.trim_start_matches(['\u{a0}', ';', ' ']).to_owned())
}

/// Exercise s3.4 by its distribution, for generated `sigma` from `1e-4` to `1e4`:
/// finite at the end points, and over 5,120 draws `exp(-r^2 / (2 sigma^2))`
/// uniform on `[0, 1]` (the Gaussian's radius has `P(r > s) = exp(-s^2 / (2
/// sigma^2))`) and the azimuth uniform, tested by a chi-square over 64 cells.
pub fn gaussian(yours: impl Fn(Real, Real, Real) -> (Real, Real)) -> Outcome {
    on_generated_cases("sample_gaussian", 24, scale(), |sigma| {
        for (u1, u2) in end_points() {
            let (x, y) = yours(u1, u2, sigma);
            if !(x.is_finite() && y.is_finite()) {
                return Err(say!(
                    "generated-s3-sigma-gave-expected-finite-numbers-the",
                    sigma = n(sigma),
                    u1_u2 = at(u1, u2),
                    value = n(x),
                    y = n(y)
                ));
            }
        }
        gaussian_spread(&yours, sigma)
    })
}

/// The chi-square of [`gaussian`] at one `sigma`, with the spread the draws have
/// when it fails.
fn gaussian_spread(
    yours: &impl Fn(Real, Real, Real) -> (Real, Real),
    sigma: Real,
) -> Result<(), String> {
    let mut squares = 0.0;
    let place = |u1, u2| {
        let (x, y) = yours(u1, u2, sigma);
        let r2 = x * x + y * y;
        squares += r2;
        Ok(cell((-r2 / (2.0 * sigma * sigma)).exp(), y, x))
    };
    let describe = |k| describe("exp(-r^2 / (2 sigma^2))", k);
    let outcome = spread(DRAWS_SEED, place, describe);
    outcome.map_err(|why| {
        let measured = (squares / (2.0 * DRAWS as Real)).sqrt();
        say!(
            "generated-s3-sigma-the-offsets-spread-as-sigma",
            sigma = n(sigma),
            measured = n(measured),
            why = why
        )
    })
}
