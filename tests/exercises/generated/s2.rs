//! Session 2 on generated inputs: gamma, the offset origin of new rays, the shadow
//! ray, reflection and refraction.

use proptest::prelude::*;
use raycourse::geometry::{Hit, Ray};
use raycourse::maths::{Real, Vec3};

use super::s1::{direction, scale};
use super::{apart, differs, n, near_vec, on_generated, ulps, v};
use crate::known::Outcome;
use crate::say;

/// Exercise s2.1 on generated radiances, from black to far brighter than white,
/// negative, `-0`, infinite and NaN, under gammas from 0.5 to 4. A level is right
/// when it is `L^(1/gamma)` rounded to the nearest, or either neighbour at a tie.
pub fn display(yours: impl Fn(Real, Real) -> u8) -> Outcome {
    let radiance = prop_oneof![
        Just(0.0 as Real),
        Just(-0.0 as Real),
        Just(Real::INFINITY),
        Just(Real::NAN),
        -1e3..0.0 as Real,
        0.0..2.0 as Real,
        (0.0..6.0 as Real).prop_map(|e| (10.0 as Real).powf(e)),
    ];
    let gamma = prop_oneof![Just(1.0 as Real), Just(2.2 as Real), 0.5..4.0 as Real];
    on_generated("display", (radiance, gamma), |(radiance, gamma)| {
        let gave = yours(radiance, gamma);
        let expected = course::render::film::display(radiance, gamma);
        let exact = radiance.max(0.0).powf(1.0 / gamma).min(255.0);
        let tie = exact.is_finite() && ((exact.fract() - 0.5).abs() < 1e-6);
        if gave == expected || (tie && (gave as Real - exact).abs() <= 0.5 + 1e-6) {
            return Ok(());
        }
        let case = say!(
            "generated-s2-l-gamma",
            radiance = n(radiance),
            gamma = n(gamma)
        );
        let why = display_diagnosis(gave, radiance, gamma);
        Err(differs(
            &case,
            &gave.to_string(),
            &expected.to_string(),
            why,
        ))
    })
}

/// Which rule of the display level `gave` breaks.
fn display_diagnosis(gave: u8, radiance: Real, gamma: Real) -> Option<String> {
    if radiance.is_nan() || radiance < 0.0 {
        return Some(say!("generated-s2-a-negative-or-nan-radiance-shows"));
    }
    if radiance == Real::INFINITY {
        return Some(say!("generated-s2-an-infinite-radiance-is-the-brightest"));
    }
    let level = |x: Real| x.clamp(0.0, 255.0);
    let exact = level(radiance.powf(1.0 / gamma));
    let gave = gave as Real;
    // Several mistakes can give the same level: each that does is named.
    let rules = [
        (
            gave == exact.floor(),
            say!("generated-s2-the-level-is-l-1-gamma", exact = n(exact)),
        ),
        (
            gave == level(radiance.powf(1.0 / 2.2)).round() && gamma != 2.2,
            say!(
                "generated-s2-use-the-gamma-given-here-not",
                gamma = n(gamma)
            ),
        ),
        (
            gave == level(radiance.powf(gamma)).round(),
            say!("generated-s2-the-level-is-l-1-gamma-2"),
        ),
    ];
    let named: Vec<String> = rules
        .into_iter()
        .filter(|(holds, _)| *holds)
        .map(|(_, why)| why)
        .collect();
    (!named.is_empty()).then(|| named.join(&say!("generated-s2-or")))
}

/// How many powers of ten of its own size a generated object may lie from the
/// origin: 8 in double precision, 4 in single, whose 7 digits would keep too few
/// of its size beyond.
pub fn farthest_power() -> Real {
    if std::mem::size_of::<Real>() == 8 {
        8.0
    } else {
        4.0
    }
}

/// A hit on a sphere: its centre, radius and where a ray from outside or from
/// inside met it, at scales from `1e-4` to `1e4` and up to `1e8` away (`1e4` in
/// single precision), made by the course's own functions and turned to face the
/// ray, as a diffuse surface's is: from inside, its normal points in, away from its
/// offset, and only the new ray's direction against the offset decides its side.
fn hits() -> impl Strategy<Value = (Vec3, Real, course::geometry::Hit)> {
    (
        direction(),
        0.0..farthest_power(),
        scale(),
        direction(),
        direction(),
        any::<bool>(),
    )
        .prop_map(|(towards, exponent, radius, at, side, inside)| {
            let centre = (10.0 as Real).powf(exponent) * radius * towards;
            let ball = course::geometry::Sphere::white(centre, radius);
            let (start, aim) = if inside {
                (centre + 0.5 * radius * at, side)
            } else {
                let start = centre + 3.0 * radius * at;
                (start, centre + 0.5 * radius * side - start)
            };
            let ray = course::geometry::Ray::new(start, aim.normalize());
            let t = ball.intersect(&ray).unwrap_or(0.0);
            (centre, radius, ball.hit_at(&ray, t, 0).facing_the_ray())
        })
}

/// The student's copy of the course's hit.
fn student_hit(hit: &course::geometry::Hit) -> Hit {
    Hit {
        t: hit.t,
        point: hit.point,
        normal: hit.normal,
        error: hit.error,
        offset: hit.offset,
        material: raycourse::materials::Material::Diffuse {
            albedo: raycourse::maths::Colour::ONE,
        },
        emission: hit.emission,
        object: hit.object,
        from_outside: hit.from_outside,
    }
}

/// Exercise s2.2 on generated hits on spheres of every scale and far away, each
/// left by a ray going out and one going in. What the chapter promises is checked,
/// not the course's bits: the direction is kept; the ray going out does not meet
/// its sphere again; the ray going in meets it on the far side, not at `t` of
/// about 0; and the origin stays within a thousandth of the radius (or the
/// offset, where that is larger) of the hit point.
pub fn spawn(yours: impl Fn(&Hit, Vec3) -> Ray) -> Outcome {
    on_generated(
        "Hit::spawn",
        (hits(), direction()),
        |((centre, radius, hit), wander)| {
            let outward = hit.normal;
            let out = (outward + 0.9 * wander).normalize_or(outward);
            let out = if out.dot(outward) > 0.05 {
                out
            } else {
                outward
            };
            let ball = course::geometry::Sphere::white(centre, radius);
            for d in [out, -out] {
                let ray = yours(&student_hit(&hit), d);
                if let Some(why) = spawn_fault(&hit, &ball, &ray, d) {
                    let case = say!(
                        "generated-s2-the-hit-point-with-normal-on",
                        hit_point = v(hit.point),
                        hit_normal = v(hit.normal),
                        radius = n(radius),
                        centre = v(centre),
                        d = v(d)
                    );
                    return Err(say!(
                        "generated-s2-yours-starts-at",
                        ray_origin = v(ray.origin),
                        case = case,
                        why = why
                    ));
                }
            }
            Ok(())
        },
    )
}

/// What a new ray `ray` from `hit`, given the direction `d`, breaks of spawn's
/// promises on the sphere `ball`, if anything.
fn spawn_fault(
    hit: &course::geometry::Hit,
    ball: &course::geometry::Sphere,
    ray: &Ray,
    d: Vec3,
) -> Option<String> {
    // Outwards from the sphere, whichever way the hit's normal was turned.
    let (radius, outward) = (ball.radius, (hit.point - ball.centre).normalize());
    let going_out = d.dot(outward) > 0.0;
    let turned = hit.normal.dot(outward) < 0.0;
    let again = ball.intersect(&course::geometry::Ray::new(ray.origin, ray.direction));
    let chord = 2.0 * radius * d.dot(outward).abs();
    let reach = 1e-3 * radius + 4.0 * hit.offset.length();
    let moved = ray.origin.distance(hit.point);
    if !near_vec(ray.direction, d, ulps(8.0)) {
        Some(say!("generated-s2-the-new-ray-keeps-the-direction"))
    } else if turned && again.is_some_and(|t| going_out || t < 0.5 * chord) {
        Some(say!(
            "generated-s2-it-meets-its-sphere-at-t",
            going_in = if going_out {
                say!("generated-s2-leaving-outwards")
            } else {
                say!("generated-s2-going-in")
            },
            again = n(again.unwrap_or(0.0))
        ))
    } else if going_out && again.is_some() {
        Some(say!(
            "generated-s2-leaving-outwards-it-meets-its-own",
            again = n(again.unwrap_or(0.0))
        ))
    } else if !going_out && again.is_none_or(|t| t < 0.5 * chord) {
        Some(say!(
            "generated-s2-going-in-it-should-meet-the",
            chord = n(chord),
            s2_nothing = again.map_or(say!("generated-s2-nothing"), |t| format!("t = {}", n(t)))
        ))
    } else if moved > reach {
        Some(say!(
            "generated-s2-the-origin-moved-from-the-hit",
            moved = n(moved),
            radius = n(radius)
        ))
    } else {
        None
    }
}

/// Exercise s2.3 on generated hits and lights, from a hundredth of the radius away
/// to ten thousand radii: the direction is the unit vector from the hit point to
/// the light, and the distance is measured from the ray's own origin (which
/// `spawn` moved), within a few roundings.
pub fn spawn_towards(yours: impl Fn(&Hit, Vec3) -> (Ray, Real)) -> Outcome {
    let lights = (direction(), -2.0..4.0 as Real);
    on_generated(
        "Hit::spawn_towards",
        (hits(), lights),
        |((_, radius, hit), (way, exponent))| {
            let way = if way.dot(hit.normal) > 0.05 {
                way
            } else {
                hit.normal
            };
            let light = hit.point + (10.0 as Real).powf(exponent) * radius * way;
            let (ray, distance) = yours(&student_hit(&hit), light);
            let towards = (light - hit.point).normalize();
            let from_origin = ray.origin.distance(light);
            let direction_right = near_vec(ray.direction, towards, ulps(64.0));
            let distance_right = (distance - from_origin).abs() <= ulps(64.0) * from_origin;
            if direction_right && distance_right {
                return Ok(());
            }
            let from_point = hit.point.distance(light);
            let why = towards_rule(ray.direction, towards, (distance, from_origin, from_point));
            let case = say!(
                "generated-s2-the-hit-point-with-normal-a",
                hit_point = v(hit.point),
                hit_normal = v(hit.normal),
                light = v(light)
            );
            let (gave, expected) = apart(distance, from_origin);
            let gave = say!(
                "generated-s2-the-direction-at-distance",
                ray_direction = v(ray.direction),
                gave = gave
            );
            let expected = say!(
                "generated-s2-the-direction-at-distance-2",
                towards = v(towards),
                expected = expected
            );
            Err(differs(&case, &gave, &expected, Some(why)))
        },
    )
}

/// The rule a shadow ray breaks: its `direction` is not the unit vector `towards`
/// the light, or its `distance` is not `from_origin`, the light's distance from the
/// ray's origin (`from_point`: from the hit point).
fn towards_rule(
    direction: Vec3,
    towards: Vec3,
    (distance, from_origin, from_point): (Real, Real, Real),
) -> String {
    let direction_right = near_vec(direction, towards, ulps(64.0));
    if !direction_right && near_vec(direction.normalize(), towards, ulps(64.0)) {
        say!("generated-s2-the-direction-is-a-unit-vector")
    } else if !direction_right {
        say!("generated-s2-the-direction-is-the-unit-vector")
    } else if (distance - from_point).abs() <= ulps(64.0) * from_origin {
        say!("generated-s2-the-distance-is-the-light-s")
    } else {
        say!("generated-s2-the-distance-is-light-origin-the")
    }
}

/// A unit normal and a unit direction meeting it from its side, grazing ones
/// (`cos(theta)` of `1e-6`, and from `1e-5` to `1e-3`, beyond single precision's
/// rounding) and those along the normal among them.
fn towards_surface() -> impl Strategy<Value = (Vec3, Vec3)> {
    (
        direction(),
        direction(),
        prop_oneof![
            Just(1.0 as Real),
            Just(1e-6 as Real),
            1e-5..1e-3 as Real,
            0.0..1.0 as Real
        ],
    )
        .prop_map(|(normal, across, cos)| {
            let tangent = (across - across.dot(normal) * normal)
                .normalize_or(normal.any_orthonormal_vector());
            let sin = (1.0 - cos * cos).max(0.0).sqrt();
            (normal, (sin * tangent - cos * normal).normalize())
        })
}

/// Exercise s2.4 on generated directions and normals, grazing and head-on among
/// them: `r = d - 2 (d . N) N`, within a few roundings.
pub fn reflect(yours: impl Fn(Vec3, Vec3) -> Vec3) -> Outcome {
    on_generated("reflect", towards_surface(), |(normal, d)| {
        let gave = yours(d, normal);
        let expected = course::materials::optics::reflect(d, normal);
        if near_vec(gave, expected, ulps(64.0)) {
            return Ok(());
        }
        let along = d.dot(normal);
        let why = if near_vec(gave, -expected, ulps(64.0)) {
            say!("generated-s2-yours-points-the-other-way-r")
        } else if gave == d {
            say!("generated-s2-yours-leaves-d-as-it-is", along = n(along))
        } else if near_vec(gave, d - along * normal, ulps(64.0)) {
            say!("generated-s2-yours-removes-the-normal-part-subtracted")
        } else if near_vec(gave, d + 2.0 * along * normal, ulps(64.0)) {
            say!("generated-s2-the-sign-r-d-2-d")
        } else {
            say!("generated-s2-r-d-2-d-n-n")
        };
        let case = say!("generated-s2-d-n", d = v(d), normal = v(normal));
        Err(differs(&case, &v(gave), &v(expected), Some(why)))
    })
}

/// Exercise s2.5 on generated directions, normals and index ratios from 0.3 to
/// 3, grazing and head-on among them, and on purpose near the critical angle,
/// from either side. Where `eta^2 sin^2(theta_1)` lies within `sqrt(epsilon)` of 1
/// the two answers may rightly disagree on total internal reflection, so such
/// cases are left out; elsewhere the directions agree within `sqrt(epsilon)`.
pub fn refract(yours: impl Fn(Vec3, Vec3, Real) -> Option<Vec3>) -> Outcome {
    let eta = prop_oneof![
        Just(1.0 as Real),
        Just(1.0 / 1.5),
        Just(1.5 as Real),
        0.3..3.0 as Real
    ];
    let inputs = prop_oneof![3 => (towards_surface(), eta), 1 => near_critical()].prop_filter(
        "not at the critical angle",
        |((normal, d), eta)| {
            (sin2_transmitted(*d, *normal, *eta) - 1.0).abs() > Real::EPSILON.sqrt()
        },
    );
    on_generated("refract", inputs, |((normal, d), eta)| {
        let gave = yours(d, normal, eta);
        let expected = course::materials::optics::refract(d, normal, eta);
        if same_refraction(gave, expected) {
            return Ok(());
        }
        let show =
            |t: Option<Vec3>| t.map_or(say!("generated-s2-none-total-internal-reflection"), v);
        let case = say!(
            "generated-s2-d-n-eta",
            d = v(d),
            normal = v(normal),
            eta = n(eta)
        );
        let why = refract_rule((d, normal, eta), gave, expected);
        Err(differs(&case, &show(gave), &show(expected), Some(why)))
    })
}

/// A ray leaving a denser medium (`eta` from 1.05 to 3) at an angle whose
/// `eta^2 sin^2(theta_1)` is `1 -+ 10^-k`, `k` from 1 to 7: just before the
/// critical angle, where it still refracts, and just past it.
fn near_critical() -> impl Strategy<Value = ((Vec3, Vec3), Real)> {
    (
        direction(),
        direction(),
        1.05..3.0 as Real,
        1i32..=7,
        any::<bool>(),
    )
        .prop_map(|(normal, across, eta, k, past)| {
            let step = (10.0 as Real).powi(-k);
            let sin2 = (if past { 1.0 + step } else { 1.0 - step }) / (eta * eta);
            let tangent = (across - across.dot(normal) * normal)
                .normalize_or(normal.any_orthonormal_vector());
            let d = sin2.sqrt() * tangent - (1.0 - sin2).sqrt() * normal;
            ((normal, d.normalize()), eta)
        })
}

/// `eta^2 sin^2(theta_1)`, which is `sin^2(theta_2)` where the ray refracts.
fn sin2_transmitted(d: Vec3, normal: Vec3, eta: Real) -> Real {
    eta * eta * (1.0 - d.dot(normal).powi(2))
}

/// Whether two refracted directions agree: both absent (total internal
/// reflection), or within `sqrt(epsilon)`.
fn same_refraction(a: Option<Vec3>, b: Option<Vec3>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => (a - b).length() <= Real::EPSILON.sqrt(),
        _ => false,
    }
}

/// The rule of refraction that `gave` breaks, `expected` being the course's.
fn refract_rule(
    (d, normal, eta): (Vec3, Vec3, Real),
    gave: Option<Vec3>,
    expected: Option<Vec3>,
) -> String {
    let sin2 = sin2_transmitted(d, normal, eta);
    let inverse = course::materials::optics::refract(d, normal, 1.0 / eta);
    match (gave, expected) {
        _ if same_refraction(gave, inverse) => say!("generated-s2-eta-is-n1-n2-the-index"),
        (Some(_), None) => say!(
            "generated-s2-total-internal-reflection-eta-2-sin",
            sin2 = n(sin2)
        ),
        (None, Some(_)) => say!("generated-s2-eta-2-sin-2-theta-1", sin2 = n(sin2)),
        (Some(g), Some(e)) if (g.dot(normal) + e.dot(normal)).abs() <= Real::EPSILON.sqrt() => {
            say!("generated-s2-the-refracted-ray-goes-on-through")
        }
        _ => say!("generated-s2-t-eta-d-d-n-n"),
    }
}
