//! Session 3's mistakes: the frame, the indirect bounce, the Gaussian filter.

use raycourse::geometry::Ray;
use raycourse::maths::frame::Frame;
use raycourse::maths::sampling::sample_gaussian;
use raycourse::maths::{PI, Real, Vec3, uniform_pair};

use super::{Mistake, Right};
use crate::generated;

/// Session 3's mistakes.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        exercise: "s3.1",
        what: "theta through tan^2(theta) = (1 - u2) / u2, undefined at u2 = 0",
        run: || {
            generated::cosine_direction(|u1, u2| {
                let tan2 = (1.0 - u2) / u2;
                let (r, phi) = ((tan2 / (1.0 + tan2)).sqrt(), 2.0 * PI * u1);
                Vec3::new(r * phi.cos(), r * phi.sin(), (1.0 / (1.0 + tan2)).sqrt())
            })
        },
        rule: "rule-s3-1-0-included",
    },
    Mistake {
        exercise: "s3.2",
        what: "a left-handed frame, T1 and T2 exchanged",
        run: || {
            generated::frame(|n| {
                let f = Frame::new(n);
                Frame {
                    t1: f.t2,
                    t2: f.t1,
                    n,
                }
            })
        },
        rule: "rule-s3-2-the-frame-is-left-handed",
    },
    Mistake {
        exercise: "s3.2",
        what: "Frisvad's frame, dividing by 1 + n_z, with -z alone set apart",
        run: || generated::frame(frisvad),
        rule: "rule-s3-2-near-n-z-1-n",
    },
    Mistake {
        exercise: "s3.3",
        what: "the bounce's ray pushed off by a fixed 1e-9 along N",
        run: || {
            generated::indirect_light(|tracer, hit, albedo, bounces| {
                tracer.bounce(bounces, |tracer, next| {
                    let direction = tracer.cosine_direction(hit);
                    let ray = Ray::new(hit.point + 1e-9 * hit.normal, direction);
                    albedo * tracer.radiance(&ray, next)
                })
            })
        },
        rule: "rule-s3-3-hit-spawn-direction",
    },
    Mistake {
        exercise: "s3.4",
        what: "sigma fixed at the stage's 0.5",
        run: || generated::gaussian(|u1, u2, _| sample_gaussian(u1, u2, 0.5)),
        rule: "rule-s3-4-with-the-sigma-given",
    },
];

/// Frisvad's frame (2012): `a = 1 / (1 + n_z)`, `b = -n_x n_y a`,
/// `T1 = (1 - n_x^2 a, b, -n_x)`, `T2 = (b, 1 - n_y^2 a, -n_y)`, and the frame
/// `(0, -1, 0), (-1, 0, 0)` below `n_z = -0.9999999`: right at the poles, off by
/// `1e-9` and more just above its threshold.
fn frisvad(n: Vec3) -> Frame {
    if n.z < -0.999_999_9 {
        return Frame {
            t1: Vec3::new(0.0, -1.0, 0.0),
            t2: Vec3::new(-1.0, 0.0, 0.0),
            n,
        };
    }
    let a: Real = 1.0 / (1.0 + n.z);
    let b = -n.x * n.y * a;
    Frame {
        t1: Vec3::new(1.0 - n.x * n.x * a, b, -n.x),
        t2: Vec3::new(b, 1.0 - n.y * n.y * a, -n.y),
        n,
    }
}

/// Session 3's right answers written otherwise than the course's.
pub const RIGHT: &[Right] = &[
    Right {
        exercise: "s3.1",
        what: "z from u1 and the azimuth from u2",
        run: || {
            generated::cosine_direction(|u1, u2| {
                let (r, phi) = ((1.0 - u1).sqrt(), 2.0 * PI * u2);
                Vec3::new(r * phi.cos(), r * phi.sin(), u1.sqrt())
            })
        },
    },
    Right {
        exercise: "s3.2",
        what: "Hughes and Möller's frame",
        run: || {
            generated::frame(|n| {
                let t1 = if n.x.abs() > n.z.abs() {
                    Vec3::new(-n.y, n.x, 0.0)
                } else {
                    Vec3::new(0.0, -n.z, n.y)
                }
                .normalize();
                Frame {
                    t1,
                    t2: n.cross(t1),
                    n,
                }
            })
        },
    },
    Right {
        exercise: "s3.2",
        what: "Gram-Schmidt from the axis least along N",
        run: || {
            generated::frame(|n| {
                let axis = if n.x.abs() < 0.6 { Vec3::X } else { Vec3::Y };
                let t1 = (axis - axis.dot(n) * n).normalize();
                Frame {
                    t1,
                    t2: n.cross(t1),
                    n,
                }
            })
        },
    },
    Right {
        exercise: "s3.3",
        what: "a uniform direction weighted by 2 cos(theta)",
        run: || {
            generated::indirect_light(|tracer, hit, albedo, bounces| {
                tracer.bounce(bounces, |tracer, next| {
                    let (u1, u2) = uniform_pair(&mut tracer.rng);
                    let (r, phi) = ((1.0 - u1 * u1).sqrt(), 2.0 * PI * u2);
                    let local = Vec3::new(r * phi.cos(), r * phi.sin(), u1);
                    let direction = Frame::new(hit.normal).to_world(local);
                    2.0 * u1 * albedo * tracer.radiance(&hit.spawn(direction), next)
                })
            })
        },
    },
    Right {
        exercise: "s3.4",
        what: "the radius from u2 and the angle from u1",
        run: || generated::gaussian(|u1, u2, sigma| sample_gaussian(u2, u1, sigma)),
    },
];
