//! Session 2 on generated inputs: gamma, the offset origin of new rays, the shadow
//! ray, reflection and refraction.

use proptest::prelude::*;
use raycourse::geometry::{Hit, Ray};
use raycourse::maths::{Real, Vec3};

use super::s1::{course_sphere, direction, scale};
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
            "L = {}, gamma = {}",
            "L = {}, gamma = {}",
            n(radiance),
            n(gamma)
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
        return Some(say!(
            "a negative or NaN radiance shows as black, 0: clamp it at 0 before the power",
            "une luminance négative ou NaN s'affiche en noir, 0\u{a0}: ramenez-la à 0 avant la puissance"
        ));
    }
    if radiance == Real::INFINITY {
        return Some(say!(
            "an infinite radiance is the brightest there is: min(255, L^(1/gamma)) = 255",
            "une luminance infinie est la plus claire qui soit\u{a0}: min(255, L^(1/gamma)) = 255"
        ));
    }
    let level = |x: Real| x.clamp(0.0, 255.0);
    let exact = level(radiance.powf(1.0 / gamma));
    let gave = gave as Real;
    // Several mistakes can give the same level: each that does is named.
    let rules = [
        (
            gave == exact.floor(),
            say!(
                "the level is L^(1/gamma) = {} rounded to the nearest, not down",
                "le niveau est L^(1/gamma) = {} arrondi au plus proche, pas par défaut",
                n(exact)
            ),
        ),
        (
            gave == level(radiance.powf(1.0 / 2.2)).round() && gamma != 2.2,
            say!(
                "use the gamma given, here {}, not 2.2",
                "utilisez le gamma donné, ici {}, et non 2,2",
                n(gamma)
            ),
        ),
        (
            gave == level(radiance.powf(gamma)).round(),
            say!(
                "the level is L^(1/gamma): the exponent is 1/gamma, not gamma",
                "le niveau est L^(1/gamma)\u{a0}: l'exposant est 1/gamma, pas gamma"
            ),
        ),
    ];
    let named: Vec<String> = rules
        .into_iter()
        .filter(|(holds, _)| *holds)
        .map(|(_, why)| why)
        .collect();
    (!named.is_empty()).then(|| named.join(&say!("; or ", "\u{a0}; ou ")))
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
            let ball = course_sphere(centre, radius);
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
            let ball = course_sphere(centre, radius);
            for d in [out, -out] {
                let ray = yours(&student_hit(&hit), d);
                if let Some(why) = spawn_fault(&hit, &ball, &ray, d) {
                    let case = say!(
                        "the hit point {} with normal {} on a sphere of radius {} at {}, the new ray along {}",
                        "le point d'intersection {} de normale {} sur une sphère de rayon {} en {}, le nouveau rayon selon {}",
                        v(hit.point),
                        v(hit.normal),
                        n(radius),
                        v(centre),
                        v(d)
                    );
                    return Err(say!(
                        "{case}: yours starts at {}; {why}",
                        "{case}\u{a0}: le vôtre part de {}\u{a0}; {why}",
                        v(ray.origin)
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
        Some(say!(
            "the new ray keeps the direction it is given",
            "le nouveau rayon garde la direction donnée"
        ))
    } else if turned && again.is_some_and(|t| going_out || t < 0.5 * chord) {
        Some(say!(
            "{} it meets its sphere at t = {}: the hit's normal N was turned to face the ray, so it points into the sphere here; the side a new ray starts on is the side its direction takes against the offset (from the geometric normal), not against N",
            "{} il rencontre sa sphère en t = {}\u{a0}: la normale N de l'intersection a été tournée vers le rayon, elle pointe donc ici dans la sphère\u{a0}; le côté d'où part un nouveau rayon est celui que prend sa direction par rapport au décalage (tiré de la normale géométrique), pas par rapport à N",
            if going_out {
                say!("Leaving outwards", "En sortant")
            } else {
                say!("Going in", "En entrant")
            },
            n(again.unwrap_or(0.0))
        ))
    } else if going_out && again.is_some() {
        Some(say!(
            "leaving outwards it meets its own sphere again at t = {} (shadow acne): push the origin off the surface by the error bound, along N on the side it leaves by",
            "en sortant il rencontre de nouveau sa propre sphère en t = {} (acné d'ombre)\u{a0}: décalez l'origine hors de la surface de la borne d'erreur, selon N du côté où il part",
            n(again.unwrap_or(0.0))
        ))
    } else if !going_out && again.is_none_or(|t| t < 0.5 * chord) {
        Some(say!(
            "going in it should meet the far side, about {} away, and meets {}: the origin must be pushed to the side the ray leaves by, here inwards (-N)",
            "en entrant il devrait rencontrer le côté opposé, à environ {}, et rencontre {}\u{a0}: l'origine doit être décalée du côté où part le rayon, ici vers l'intérieur (-N)",
            n(chord),
            again.map_or(say!("nothing", "rien"), |t| format!("t = {}", n(t)))
        ))
    } else if moved > reach {
        Some(say!(
            "the origin moved {} from the hit point, more than a thousandth of the radius {}: the offset follows the point's error bound, not a fixed epsilon",
            "l'origine s'est éloignée de {} du point d'intersection, plus d'un millième du rayon {}\u{a0}: le décalage suit la borne d'erreur du point, pas un epsilon fixe",
            n(moved),
            n(radius)
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
                "the hit point {} with normal {}, a light at {}",
                "le point d'intersection {} de normale {}, une source en {}",
                v(hit.point),
                v(hit.normal),
                v(light)
            );
            let (gave, expected) = apart(distance, from_origin);
            let gave = say!(
                "the direction {} at distance {gave}",
                "la direction {} à la distance {gave}",
                v(ray.direction)
            );
            let expected = say!(
                "the direction {} at distance {expected}",
                "la direction {} à la distance {expected}",
                v(towards)
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
        say!(
            "the direction is a unit vector: divide the vector to the light by its length",
            "la direction est un vecteur unitaire\u{a0}: divisez le vecteur vers la source par sa longueur"
        )
    } else if !direction_right {
        say!(
            "the direction is the unit vector from the hit point to the light",
            "la direction est le vecteur unitaire du point d'intersection vers la source"
        )
    } else if (distance - from_point).abs() <= ulps(64.0) * from_origin {
        say!(
            "the distance is the light's from the ray's own origin, which the offset moved, not from the hit point",
            "la distance est celle de la source depuis l'origine du rayon, que le décalage a déplacée, pas depuis le point d'intersection"
        )
    } else {
        say!(
            "the distance is |light - origin|, the length from the ray's origin to the light",
            "la distance est |source - origine|, la longueur de l'origine du rayon à la source"
        )
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
            say!(
                "yours points the other way: r = d - 2 (d . N) N",
                "le vôtre pointe dans l'autre sens\u{a0}: r = d - 2 (d . N) N"
            )
        } else if gave == d {
            say!(
                "yours leaves d as it is; every ray the mirror meets turns, even a grazing one, here d . N = {}: r = d - 2 (d . N) N",
                "le vôtre laisse d tel quel\u{a0}; tout rayon qui touche le miroir repart, même rasant, ici d . N = {}\u{a0}: r = d - 2 (d . N) N",
                n(along)
            )
        } else if near_vec(gave, d - along * normal, ulps(64.0)) {
            say!(
                "yours removes the normal part; subtracted twice, it turns around: r = d - 2 (d . N) N",
                "le vôtre retire la partie normale\u{a0}; retranchée deux fois, elle se retourne\u{a0}: r = d - 2 (d . N) N"
            )
        } else if near_vec(gave, d + 2.0 * along * normal, ulps(64.0)) {
            say!(
                "the sign: r = d - 2 (d . N) N",
                "le signe\u{a0}: r = d - 2 (d . N) N"
            )
        } else {
            say!("r = d - 2 (d . N) N", "r = d - 2 (d . N) N")
        };
        let case = say!("d = {}, N = {}", "d = {}, N = {}", v(d), v(normal));
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
        let show = |t: Option<Vec3>| {
            t.map_or(
                say!(
                    "none (total internal reflection)",
                    "aucune direction (réflexion totale interne)"
                ),
                v,
            )
        };
        let case = say!(
            "d = {}, N = {}, eta = {}",
            "d = {}, N = {}, eta = {}",
            v(d),
            v(normal),
            n(eta)
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
        _ if same_refraction(gave, inverse) => say!(
            "eta is n1 / n2, the index the ray leaves over the index it enters; yours used n2 / n1",
            "eta vaut n1 / n2, l'indice que le rayon quitte sur celui où il entre\u{a0}; le vôtre a pris n2 / n1"
        ),
        (Some(_), None) => say!(
            "total internal reflection: eta^2 sin^2(theta_1) = {} > 1, so there is no refracted ray",
            "réflexion totale interne\u{a0}: eta^2 sin^2(theta_1) = {} > 1, donc pas de rayon réfracté",
            n(sin2)
        ),
        (None, Some(_)) => say!(
            "eta^2 sin^2(theta_1) = {} <= 1: the ray refracts",
            "eta^2 sin^2(theta_1) = {} <= 1\u{a0}: le rayon est réfracté",
            n(sin2)
        ),
        (Some(g), Some(e)) if (g.dot(normal) + e.dot(normal)).abs() <= Real::EPSILON.sqrt() => {
            say!(
                "the refracted ray goes on through the surface: its normal part is -cos(theta_2) N",
                "le rayon réfracté traverse la surface\u{a0}: sa partie normale vaut -cos(theta_2) N"
            )
        }
        _ => say!(
            "t = eta (d - (d . N) N) - sqrt(1 - eta^2 sin^2(theta_1)) N",
            "t = eta (d - (d . N) N) - sqrt(1 - eta^2 sin^2(theta_1)) N"
        ),
    }
}
