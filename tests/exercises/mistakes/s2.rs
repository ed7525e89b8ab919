//! Session 2's mistakes: gamma, spawning rays, reflection and refraction.

use raycourse::geometry::Ray;

use super::{Mistake, Right};
use crate::generated;

/// Session 2's mistakes.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        exercise: "s2.1",
        what: "levels rounded down",
        run: || {
            generated::display(|radiance, gamma| {
                radiance.max(0.0).powf(1.0 / gamma).min(255.0) as u8
            })
        },
        rule: "rule-s2-1-rounded-to-the-nearest-not",
    },
    Mistake {
        exercise: "s2.1",
        what: "gamma fixed at 2.2",
        run: || generated::display(|radiance, _| raycourse::render::film::display(radiance, 2.2)),
        rule: "rule-s2-1-use-the-gamma-given",
    },
    Mistake {
        exercise: "s2.1",
        what: "every radiance that is not finite shown black",
        run: || {
            generated::display(|radiance, gamma| {
                let v = radiance.max(0.0).powf(1.0 / gamma).min(255.0);
                if radiance.is_finite() {
                    v.round() as u8
                } else {
                    0
                }
            })
        },
        rule: "rule-s2-1-an-infinite-radiance-is-the",
    },
    Mistake {
        exercise: "s2.2",
        what: "a fixed epsilon of 1e-4",
        run: || generated::spawn(|hit, direction| hit.spawn_with_epsilon(direction, 1e-4)),
        rule: "rule-s2-2-not-a-fixed-epsilon",
    },
    Mistake {
        exercise: "s2.2",
        what: "the origin always pushed outwards",
        run: || {
            generated::spawn(|hit, direction| Ray::new(hit.spawn(hit.normal).origin, direction))
        },
        rule: "rule-s2-2-here-inwards-n",
    },
    Mistake {
        exercise: "s2.2",
        what: "the side taken from the hit's normal, turned towards the ray, not from the offset",
        run: || {
            generated::spawn(|hit, direction| {
                let side = if direction.dot(hit.normal) < 0.0 {
                    -1.0
                } else {
                    1.0
                };
                Ray {
                    origin: hit.point + side * hit.offset,
                    direction,
                }
            })
        },
        rule: "rule-s2-2-not-against-n",
    },
    Mistake {
        exercise: "s2.3",
        what: "the distance from the hit point",
        run: || {
            generated::spawn_towards(|hit, light| {
                (
                    hit.spawn((light - hit.point).normalize()),
                    hit.point.distance(light),
                )
            })
        },
        rule: "rule-s2-3-not-from-the-hit-point",
    },
    Mistake {
        exercise: "s2.3",
        what: "the direction not normalised",
        run: || {
            generated::spawn_towards(|hit, light| {
                let ray = hit.spawn((light - hit.point).normalize());
                (
                    Ray {
                        origin: ray.origin,
                        direction: light - hit.point,
                    },
                    ray.origin.distance(light),
                )
            })
        },
        rule: "rule-s2-3-divide-the-vector-to-the",
    },
    Mistake {
        exercise: "s2.4",
        what: "the normal part subtracted once",
        run: || generated::reflect(|d, normal| d - d.dot(normal) * normal),
        rule: "rule-s2-4-subtracted-twice-it-turns-around",
    },
    Mistake {
        exercise: "s2.4",
        what: "a ray within 1e-4 of grazing left as it is (a fixed epsilon)",
        run: || {
            generated::reflect(|d, normal| {
                if d.dot(normal).abs() < 1e-4 {
                    d
                } else {
                    raycourse::materials::optics::reflect(d, normal)
                }
            })
        },
        rule: "rule-s2-4-even-a-grazing-one",
    },
    Mistake {
        exercise: "s2.5",
        what: "eta upside down",
        run: || {
            generated::refract(|d, normal, eta| {
                raycourse::materials::optics::refract(d, normal, 1.0 / eta)
            })
        },
        rule: "rule-s2-5-eta-is-n1-n2",
    },
    Mistake {
        exercise: "s2.5",
        what: "no total internal reflection",
        run: || {
            generated::refract(|d, normal, eta| {
                let parallel = d - d.dot(normal) * normal;
                let cos_t = (1.0 - eta * eta * parallel.length_squared()).abs().sqrt();
                Some(eta * parallel - cos_t * normal)
            })
        },
        rule: "rule-s2-5-total-internal-reflection-eta-2",
    },
    Mistake {
        exercise: "s2.5",
        what: "total internal reflection from eta^2 sin^2 > 0.999 (a fixed epsilon)",
        run: || {
            generated::refract(|d, normal, eta| {
                let parallel = d - d.dot(normal) * normal;
                let sin2_t = eta * eta * parallel.length_squared();
                (sin2_t <= 0.999).then(|| eta * parallel - (1.0 - sin2_t).sqrt() * normal)
            })
        },
        rule: "rule-s2-5-1-the-ray-refracts",
    },
];

/// Session 2's right answers written otherwise than the course's.
pub const RIGHT: &[Right] = &[
    Right {
        exercise: "s2.4",
        what: "d + 2 cos(theta) N, with cos(theta) = -d . N",
        run: || {
            generated::reflect(|d, normal| {
                let cos = -d.dot(normal);
                d + 2.0 * cos * normal
            })
        },
    },
    Right {
        exercise: "s2.5",
        what: "the textbook's eta d + (eta cos_i - sqrt(k)) N, k = 1 - eta^2 (1 - cos_i^2)",
        run: || {
            generated::refract(|d, normal, eta| {
                let cos_i = -d.dot(normal);
                let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
                (k >= 0.0).then(|| eta * d + (eta * cos_i - k.sqrt()) * normal)
            })
        },
    },
];
