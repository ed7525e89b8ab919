//! Session 4's mistakes: the light's cone, its density, the lens's disk, the thin
//! lens.

use raycourse::camera::lens::sample_disk;
use raycourse::maths::{PI, Real, Vec3, uniform_pair};

use super::{Mistake, Right};
use crate::generated;

/// Session 4's mistakes.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        exercise: "s4.1",
        what: "sin(theta) from 1 - cos^2(theta)",
        run: || {
            generated::cone_sample(|cone, u1, u2| {
                let cos = 1.0 - u1 * cone.one_minus_cos_max;
                let sin = (1.0 - cos * cos).max(0.0).sqrt();
                let phi = 2.0 * PI * u2;
                Vec3::new(phi.cos() * sin, phi.sin() * sin, cos)
            })
        },
        rule: "rule-s4-1-sin-2-theta-1-cos",
    },
    Mistake {
        exercise: "s4.2",
        what: "1 - cos(theta_max) from the cosine",
        run: || {
            generated::cone_pdf(|cone, cos| {
                if cos >= cone.cos_max {
                    1.0 / (2.0 * PI * (1.0 - cone.cos_max))
                } else {
                    0.0
                }
            })
        },
        rule: "rule-s4-2-use-the-cone-s-one",
    },
    Mistake {
        exercise: "s4.3",
        what: "the concentric map's second half at pi/4 (a/b)",
        run: || {
            generated::disk(|u1, u2| {
                let (a, b) = (2.0 * u1 - 1.0, 2.0 * u2 - 1.0);
                if a == 0.0 && b == 0.0 {
                    return (0.0, 0.0);
                }
                let (r, phi) = if a.abs() > b.abs() {
                    (a, PI / 4.0 * (b / a))
                } else {
                    (b, PI / 4.0 * (a / b))
                };
                (r * phi.cos(), r * phi.sin())
            })
        },
        rule: "rule-s4-3-not-spread-as-the-density",
    },
    Mistake {
        exercise: "s4.4",
        what: "the pinhole ray taken from the origin, not the eye",
        run: || {
            generated::thin_lens(|lens, start, direction, rng| {
                let focus_point = direction * (lens.focus / -direction.z);
                let (u1, u2) = uniform_pair(rng);
                let (x, y) = sample_disk(u1, u2);
                let origin = start + Vec3::new(x, y, 0.0) * lens.aperture;
                (origin, focus_point - origin)
            })
        },
        rule: "rule-s4-4-starts-at-the-eye-start",
    },
    Mistake {
        exercise: "s4.4",
        what: "the lens's point at z = 0",
        run: || {
            generated::thin_lens(|lens, start, direction, rng| {
                let focus_point = start + direction * (lens.focus / -direction.z);
                let (u1, u2) = uniform_pair(rng);
                let (x, y) = sample_disk(u1, u2);
                let origin = Vec3::new(
                    start.x + x * lens.aperture,
                    start.y + y * lens.aperture,
                    0.0,
                );
                (origin, focus_point - origin)
            })
        },
        rule: "rule-s4-4-starts-in-the-eye-s",
    },
];

/// Session 4's right answers written otherwise than the course's.
pub const RIGHT: &[Right] = &[
    Right {
        exercise: "s4.1",
        what: "1 - cos(theta) = (1 - u1)(1 - cos_max)",
        run: || {
            generated::cone_sample(|cone, u1, u2| {
                let one_minus_cos = (1.0 - u1) * cone.one_minus_cos_max;
                let sin = (one_minus_cos * (2.0 - one_minus_cos)).sqrt();
                let phi = 2.0 * PI * u2;
                Vec3::new(phi.cos() * sin, phi.sin() * sin, 1.0 - one_minus_cos)
            })
        },
    },
    Right {
        exercise: "s4.3",
        what: "the polar map, r = sqrt(u1), phi = 2 pi u2",
        run: || generated::disk(polar),
    },
    Right {
        exercise: "s4.4",
        what: "the lens's point by the polar map",
        run: || {
            generated::thin_lens(|lens, start, direction, rng| {
                let focus_point = start + direction * (lens.focus / -direction.z);
                let (u1, u2) = uniform_pair(rng);
                let (x, y) = polar(u1, u2);
                let origin = start + lens.aperture * Vec3::new(x, y, 0.0);
                (origin, focus_point - origin)
            })
        },
    },
];

/// The polar map from the square to the unit disk: `r = sqrt(u1)`, `phi = 2 pi u2`.
fn polar(u1: Real, u2: Real) -> (Real, Real) {
    let (r, phi) = (u1.sqrt(), 2.0 * PI * u2);
    (r * phi.cos(), r * phi.sin())
}
