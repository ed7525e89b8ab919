//! Session 2: gamma, the offset of new rays, the shadow ray, reflection, refraction.

use raycourse::geometry::{Hit, Ray};
use raycourse::materials::optics::{reflect, refract};
use raycourse::maths::{Real, Vec3};
use raycourse::render::film::display;

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, close, close_vec, ensure, maybe, vec};
use crate::s1::sphere;
use crate::say;
use crate::words::decimal;

/// Session 2's exercises, in the book's order.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "s2.1",
        name: "s2_1_display",
        shown_by: "gamma",
        needs: &[],
        check: gamma,
        french: ["le gamma", "séance 2, «\u{a0}Correction gamma\u{a0}»"],
    },
    Exercise {
        id: "s2.2",
        name: "s2_2_hit_spawn",
        shown_by: "shadows",
        needs: &[],
        check: spawn,
        french: [
            "l'origine décalée d'un nouveau rayon",
            "séance 2, «\u{a0}Ombres portées\u{a0}»",
        ],
    },
    Exercise {
        id: "s2.3",
        name: "s2_3_hit_spawn_towards",
        shown_by: "shadows",
        needs: &["s2.2"],
        check: spawn_towards,
        french: [
            "le rayon d'ombre vers la source",
            "séance 2, «\u{a0}Ombres portées\u{a0}»",
        ],
    },
    Exercise {
        id: "s2.4",
        name: "s2_4_reflect",
        shown_by: "mirror",
        needs: &[],
        check: mirror,
        french: ["la direction réfléchie", "séance 2, «\u{a0}Miroirs\u{a0}»"],
    },
    Exercise {
        id: "s2.5",
        name: "s2_5_refract",
        shown_by: "glass",
        needs: &[],
        check: glass,
        french: [
            "la réfraction et la réflexion totale interne",
            "séance 2, «\u{a0}Verre\u{a0}»",
        ],
    },
];

/// `min(255, L^(1/gamma))`, rounded: `255^2.2` shows as 255, `64` with gamma 2 as
/// 8, `2^2.2` as 2; anything brighter than white as 255; black, negative and NaN as 0.
fn gamma() -> Outcome {
    let white = (255.0 as Real).powf(2.2);
    let cases = [
        (0.0, 2.2, 0),
        (white, 2.2, 255),
        (1e9, 2.2, 255),
        (64.0, 2.0, 8),
        ((2.0 as Real).powf(2.2), 2.2, 2),
        (100.0, 1.0, 100),
        (-3.0, 2.2, 0),
        (Real::NAN, 2.2, 0),
    ];
    for (radiance, gamma, expected) in cases {
        let gave = display(radiance, gamma);
        ensure(gave == expected, || {
            let (radiance, gamma) = (decimal(radiance.to_string()), decimal(gamma.to_string()));
            say!(
                "radiance {radiance} with gamma {gamma}: gave {gave}, expected {expected}",
                "luminance {radiance} avec un gamma de {gamma}\u{a0}: obtenu {gave}, attendu {expected}"
            )
        })?;
    }
    generated::display(display)
}

/// The hit of a ray from the eye on a sphere of radius 1 at distance 5, and of a
/// wall-sized sphere (radius 990, 10 away) like the rooms' walls, with where it is
/// in words: `on a sphere of radius 1 at (0, 0, -5)`.
fn hits() -> Vec<(
    String,
    raycourse::geometry::Sphere,
    raycourse::geometry::Hit,
)> {
    [
        (Vec3::new(0.0, 0.0, -5.0), 1.0, Vec3::new(0.05, 0.1, -1.0)),
        (
            Vec3::new(0.0, 0.0, -1000.0),
            990.0,
            Vec3::new(0.3, -0.2, -1.0),
        ),
    ]
    .into_iter()
    .map(|(centre, radius, direction)| {
        let ball = sphere(centre, radius);
        let ray = Ray::new(Vec3::ZERO, direction);
        let t = ball
            .intersect(&ray)
            .expect("the checks' rays hit their spheres");
        let at = vec(centre);
        let what = if radius > 100.0 {
            say!(
                "on a wall, a sphere of radius {radius} at {at}",
                "sur un mur, une sphère de rayon {radius} en {at}"
            )
        } else {
            say!(
                "on a sphere of radius {radius} at {at}",
                "sur une sphère de rayon {radius} en {at}"
            )
        };
        (what, ball, ball.hit_at(&ray, t, 0))
    })
    .collect()
}

/// A ray leaving a hit point starts close to it (within 1e-3) on the side it
/// leaves by: going out it does not meet its own sphere again; going in it meets
/// it only on the far side, not at `t` of about 0 (shadow acne).
fn spawn() -> Outcome {
    for (what, ball, hit) in hits() {
        let outward = (hit.point - ball.centre).normalize();
        let out = hit.spawn((outward + Vec3::new(0.0, 0.0, 0.5)).normalize());
        let inward = hit.spawn(-outward);
        for ([way, sens], ray) in [(["out", "sortant"], out), (["in", "entrant"], inward)] {
            ensure(ray.origin.distance(hit.point) < 1e-3, || {
                say!(
                    "{what}, the ray going {way} starts at {}, {} from the hit point {}: expected a start within 1e-3",
                    "{what}, le rayon {sens} part de {}, à {} du point d'intersection {}\u{a0}: attendu un départ à moins de 1e-3",
                    vec(ray.origin),
                    decimal(ray.origin.distance(hit.point).to_string()),
                    vec(hit.point)
                )
            })?;
        }
        let again = ball.intersect(&out);
        ensure(again.is_none(), || {
            say!(
                "{what}, a ray leaving outwards from the hit point meets the sphere again at {}: expected {} (its origin must be pushed off the surface, outwards)",
                "{what}, un rayon qui quitte le point d'intersection vers l'extérieur rencontre de nouveau la sphère en {}\u{a0}: attendu {} (son origine doit être décalée hors de la surface, vers l'extérieur)",
                maybe(again),
                maybe(None)
            )
        })?;
        let through = ball.intersect(&inward);
        ensure(through.is_some_and(|t| t > 1e-3), || {
            say!(
                "{what}, a ray going into the sphere from the hit point gave {}: expected the far side, about {} away (its origin must be pushed off the surface, inwards)",
                "{what}, un rayon qui entre dans la sphère depuis le point d'intersection donne {}, au lieu du côté opposé, à environ {} (son origine doit être décalée hors de la surface, vers l'intérieur)",
                maybe(through),
                decimal((2.0 * ball.radius).to_string())
            )
        })?;
    }
    generated::spawn(Hit::spawn)
}

/// The shadow ray towards a point: unit direction towards it, and the distance
/// from the ray's origin to it, which the shadow test compares hits with.
fn spawn_towards() -> Outcome {
    for (what, _, hit) in hits() {
        let light = hit.point + Vec3::new(3.0, 4.0, 12.0);
        let (ray, distance) = hit.spawn_towards(light);
        close_vec(
            &say!(
                "{what}, the direction towards a light 13 away along {}",
                "{what}, la direction vers une source à une distance de 13 selon {}",
                vec(Vec3::new(3.0, 4.0, 12.0))
            ),
            ray.direction,
            Vec3::new(3.0, 4.0, 12.0) / 13.0,
            1e-4,
        )?;
        close(
            &say!(
                "{what}, the distance to that light",
                "{what}, la distance à cette source"
            ),
            distance,
            13.0,
            1e-3,
        )?;
        ensure(ray.origin.distance(hit.point) < 1e-3, || {
            say!(
                "{what}, the shadow ray starts at {}, not near the hit point {}",
                "{what}, le rayon d'ombre part de {}, et non près du point d'intersection {}",
                vec(ray.origin),
                vec(hit.point)
            )
        })?;
    }
    generated::spawn_towards(Hit::spawn_towards)
}

/// `d - 2 (d . N) N`: off a floor, the vertical part changes sign; head-on, the
/// ray comes straight back.
fn mirror() -> Outcome {
    let up = Vec3::new(0.0, 1.0, 0.0);
    let cases = [
        (Vec3::new(0.48, -0.6, 0.64), up, Vec3::new(0.48, 0.6, 0.64)),
        (
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(0.0, 0.0, 1.0),
        ),
        (
            Vec3::new(1.0, -1.0, 0.0).normalize(),
            Vec3::new(-1.0, 1.0, 0.0).normalize(),
            Vec3::new(-1.0, 1.0, 0.0).normalize(),
        ),
    ];
    for (d, n, expected) in cases {
        close_vec(
            &say!(
                "d = {} reflected about N = {}",
                "d = {} réfléchi par rapport à N = {}",
                vec(d),
                vec(n)
            ),
            reflect(d, n),
            expected,
            1e-5,
        )?;
    }
    generated::reflect(reflect)
}

/// Snell-Descartes: 30 degrees from the normal in air into glass of index 1.5
/// gives `sin(theta_2) = 0.5 / 1.5 = 1/3`, `cos(theta_2) = sqrt(8/9)`; straight in,
/// straight on; from glass at 45 degrees, beyond the critical angle of 41.8 degrees,
/// no refraction (total internal reflection); at 40 degrees, `sin = 0.964`.
fn glass() -> Outcome {
    let n = Vec3::new(0.0, 1.0, 0.0);
    let at = |degrees: Real| {
        let a = degrees.to_radians();
        Vec3::new(a.sin(), -a.cos(), 0.0)
    };
    let third = 1.0 / 3.0;
    let cases = [
        (
            [
                "30 degrees, air into glass",
                "30 degrés, de l'air vers le verre",
            ],
            at(30.0),
            1.0 / 1.5,
            Some(Vec3::new(third, -(8.0 as Real / 9.0).sqrt(), 0.0)),
        ),
        (
            ["straight in", "en incidence normale"],
            at(0.0),
            1.0 / 1.5,
            Some(Vec3::new(0.0, -1.0, 0.0)),
        ),
        (
            [
                "45 degrees, glass into air",
                "45 degrés, du verre vers l'air",
            ],
            at(45.0),
            1.5,
            None,
        ),
        (
            [
                "40 degrees, glass into air",
                "40 degrés, du verre vers l'air",
            ],
            at(40.0),
            1.5,
            Some(at((1.5 * (40.0 as Real).to_radians().sin())
                .asin()
                .to_degrees())),
        ),
    ];
    for ([what, quoi], d, eta, expected) in cases {
        let gave = refract(d, n, eta);
        let right = match (gave, expected) {
            (Some(g), Some(e)) => (g - e).abs().max_element() < 1e-4,
            (None, None) => true,
            _ => false,
        };
        let show = |v: Option<Vec3>| {
            v.map_or(
                say!(
                    "none (total internal reflection)",
                    "aucune direction (réflexion totale interne)"
                ),
                vec,
            )
        };
        ensure(right, || {
            let eta = decimal(eta.to_string());
            say!(
                "{what}: d = {}, N = {}, eta = n1 / n2 = {eta}: gave {}, expected {}",
                "{quoi}\u{a0}: d = {}, N = {}, eta = n1 / n2 = {eta}\u{a0}: obtenu {}, attendu {}",
                vec(d),
                vec(n),
                show(gave),
                show(expected)
            )
        })?;
    }
    generated::refract(refract)
}
