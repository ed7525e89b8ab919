//! Session 2: gamma, the offset of new rays, the shadow ray, reflection, refraction.

use raycourse::geometry::{Hit, Ray, Sphere};
use raycourse::materials::optics::{reflect, refract};
use raycourse::maths::{Real, Vec3};
use raycourse::render::film::display;

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, close, close_vec, ensure, maybe, vec};
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
    },
    Exercise {
        id: "s2.2",
        name: "s2_2_hit_spawn",
        shown_by: "shadows",
        needs: &[],
        check: spawn,
    },
    Exercise {
        id: "s2.3",
        name: "s2_3_hit_spawn_towards",
        shown_by: "shadows",
        needs: &["s2.2"],
        check: spawn_towards,
    },
    Exercise {
        id: "s2.4",
        name: "s2_4_reflect",
        shown_by: "mirror",
        needs: &[],
        check: mirror,
    },
    Exercise {
        id: "s2.5",
        name: "s2_5_refract",
        shown_by: "glass",
        needs: &[],
        check: glass,
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
                "s2-radiance-with-gamma-gave-expected",
                radiance = radiance,
                gamma = gamma,
                gave = gave,
                expected = expected
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
        let ball = Sphere::white(centre, radius);
        let ray = Ray::new(Vec3::ZERO, direction);
        let t = ball
            .intersect(&ray)
            .expect("the checks' rays hit their spheres");
        let at = vec(centre);
        let what = if radius > 100.0 {
            say!("s2-on-a-wall-a-sphere-of", radius = radius, at = at)
        } else {
            say!("s2-on-a-sphere-of-radius-at", radius = radius, at = at)
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
        for (way, ray) in [(say!("s2-case-out"), out), (say!("s2-case-in"), inward)] {
            ensure(ray.origin.distance(hit.point) < 1e-3, || {
                say!(
                    "s2-the-ray-going-starts-at-from",
                    ray_origin = vec(ray.origin),
                    hit_point = decimal(ray.origin.distance(hit.point).to_string()),
                    hit_point2 = vec(hit.point),
                    what = what,
                    way = way
                )
            })?;
        }
        let again = ball.intersect(&out);
        ensure(again.is_none(), || {
            say!(
                "s2-a-ray-leaving-outwards-from-the",
                maybe_again = maybe(again),
                maybe = maybe(None),
                what = what
            )
        })?;
        let through = ball.intersect(&inward);
        ensure(through.is_some_and(|t| t > 1e-3), || {
            say!(
                "s2-a-ray-going-into-the-sphere",
                maybe_through = maybe(through),
                ball_radius = decimal((2.0 * ball.radius).to_string()),
                what = what
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
                "s2-the-direction-towards-a-light-13",
                vec_new = vec(Vec3::new(3.0, 4.0, 12.0)),
                what = what
            ),
            ray.direction,
            Vec3::new(3.0, 4.0, 12.0) / 13.0,
            1e-4,
        )?;
        close(
            &say!("s2-the-distance-to-that-light", what = what),
            distance,
            13.0,
            1e-3,
        )?;
        ensure(ray.origin.distance(hit.point) < 1e-3, || {
            say!(
                "s2-the-shadow-ray-starts-at-not",
                ray_origin = vec(ray.origin),
                hit_point = vec(hit.point),
                what = what
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
            &say!("s2-d-reflected-about-n", vec_d = vec(d), vec = vec(n)),
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
            say!("s2-case-30-degrees-air-into-glass"),
            at(30.0),
            1.0 / 1.5,
            Some(Vec3::new(third, -(8.0 as Real / 9.0).sqrt(), 0.0)),
        ),
        (
            say!("s2-case-straight-in"),
            at(0.0),
            1.0 / 1.5,
            Some(Vec3::new(0.0, -1.0, 0.0)),
        ),
        (
            say!("s2-case-45-degrees-glass-into-air"),
            at(45.0),
            1.5,
            None,
        ),
        (
            say!("s2-case-40-degrees-glass-into-air"),
            at(40.0),
            1.5,
            Some(at((1.5 * (40.0 as Real).to_radians().sin())
                .asin()
                .to_degrees())),
        ),
    ];
    for (what, d, eta, expected) in cases {
        let gave = refract(d, n, eta);
        let right = match (gave, expected) {
            (Some(g), Some(e)) => (g - e).abs().max_element() < 1e-4,
            (None, None) => true,
            _ => false,
        };
        let show = |v: Option<Vec3>| v.map_or(say!("s2-none-total-internal-reflection"), vec);
        ensure(right, || {
            let eta = decimal(eta.to_string());
            say!(
                "s2-d-n-eta-n1-n2-gave",
                vec_d = vec(d),
                vec = vec(n),
                show_gave = show(gave),
                show_expected = show(expected),
                what = what,
                eta = eta
            )
        })?;
    }
    generated::refract(refract)
}
