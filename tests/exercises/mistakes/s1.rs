//! Session 1's mistakes: the camera ray, the sphere tests, the nearest hit,
//! Lambert.

use raycourse::camera::Camera;
use raycourse::geometry::{Ray, Sphere};
use raycourse::lights::PointLight;
use raycourse::maths::{Colour, PI, Real, Vec3};
use raycourse::scene::Scene;

use super::{Mistake, Right};
use crate::generated;
use crate::known::Outcome;

/// Session 1's mistakes.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        exercise: "s1.1",
        what: "W/2 and H/2 in integers",
        run: || {
            generated::pixel_direction(|c, row, column| {
                let i = c.height - 1 - row;
                let half = |size: u32| (size / 2) as Real;
                Vec3::new(
                    column as Real - half(c.width) + 0.5,
                    i as Real - half(c.height) + 0.5,
                    plane(c),
                )
            })
        },
        rule: "rule-s1-1-an-integer-division-drops-the",
    },
    Mistake {
        exercise: "s1.1",
        what: "rows counted from the top",
        run: || {
            generated::pixel_direction(|c, row, column| {
                let (w, h) = (c.width as Real, c.height as Real);
                Vec3::new(
                    column as Real - w / 2.0 + 0.5,
                    row as Real - h / 2.0 + 0.5,
                    plane(c),
                )
            })
        },
        rule: "rule-s1-1-rows-count-from-the-top",
    },
    Mistake {
        exercise: "s1.1",
        what: "tan(alpha) for tan(alpha/2)",
        run: || {
            generated::pixel_direction(|c, row, column| {
                let d = c.pixel_direction(row, column);
                Vec3::new(d.x, d.y, -(c.height as Real) / (2.0 * c.fov.tan()))
            })
        },
        rule: "rule-s1-1-h-2-tan-alpha",
    },
    Mistake {
        exercise: "s1.2",
        what: "the far root from outside",
        run: || {
            generated::sphere_distance(&Sphere::intersect_textbook, &|s, r| {
                roots(s, r).1.filter(|&t| t > 0.0)
            })
        },
        rule: "rule-s1-2-yours-is-where-it-leaves",
    },
    Mistake {
        exercise: "s1.2",
        what: "the near root, even behind the origin",
        run: || generated::sphere_distance(&|s, r| roots(s, r).0, &Sphere::intersect),
        rule: "rule-s1-2-only-t-0-is-a",
    },
    Mistake {
        exercise: "s1.2",
        what: "t = 0 taken for a hit (t >= 0)",
        run: || {
            generated::sphere_distance(
                &|s, r| {
                    let (near, far) = roots(s, r);
                    near.filter(|&t| t >= 0.0).or(far.filter(|&t| t >= 0.0))
                },
                &Sphere::intersect,
            )
        },
        rule: "rule-s1-2-t-0-is-its-own",
    },
    Mistake {
        exercise: "s1.2",
        what: "the near root only, from inside too",
        run: || {
            generated::sphere_distance(
                &|s, r| roots(s, r).0.filter(|&t| t > 0.0),
                &Sphere::intersect,
            )
        },
        rule: "rule-s1-2-but-the-far-root-s",
    },
    Mistake {
        exercise: "s1.2",
        what: "the textbook discriminant in the renderer's test",
        run: || {
            generated::sphere_distance(&Sphere::intersect_textbook, &Sphere::intersect_textbook)
        },
        rule: "rule-s1-2-loses-r-2-in-the",
    },
    Mistake {
        exercise: "s1.3",
        what: "a tie won by the last sphere listed",
        run: || {
            generated::nearest_sphere(|scene, ray| {
                let mut nearest: Option<(Real, usize)> = None;
                for (i, sphere) in scene.spheres.iter().enumerate() {
                    if let Some(t) = sphere.intersect(ray)
                        && nearest.is_none_or(|(best, _)| t <= best)
                    {
                        nearest = Some((t, i));
                    }
                }
                nearest
            })
        },
        rule: "rule-s1-3-the-first-of-the-list",
    },
    Mistake {
        exercise: "s1.3",
        what: "the first sphere of the list that the ray meets",
        run: || {
            generated::nearest_sphere(|scene: &Scene, ray| {
                scene
                    .spheres
                    .iter()
                    .enumerate()
                    .find_map(|(i, s)| s.intersect(ray).map(|t| (t, i)))
            })
        },
        rule: "rule-s1-3-the-smallest-t-of-all",
    },
    Mistake {
        exercise: "s1.4",
        what: "no 1/pi",
        run: || {
            generated::lambert(|light, point, normal, albedo| {
                PI * light.lambert(point, normal, albedo)
            })
        },
        rule: "rule-s1-4-the-1-pi-is-missing",
    },
    Mistake {
        exercise: "s1.4",
        what: "the cosine not clamped",
        run: || lambert_with_cosine(|normal, to_light| normal.dot(to_light.normalize())),
        rule: "rule-s1-4-it-gets-no-light-max",
    },
    Mistake {
        exercise: "s1.4",
        what: "l from the origin to the light, the light's position normalised",
        run: || {
            generated::lambert(|light: &PointLight, point, normal, albedo: Colour| {
                let d2 = light.position.distance_squared(point);
                let cos = normal.dot(light.position.normalize()).max(0.0);
                light.intensity / (4.0 * PI * d2) * cos * albedo / PI
            })
        },
        rule: "rule-s1-4-not-p-light-p-light",
    },
    Mistake {
        exercise: "s1.4",
        what: "l not normalised",
        run: || lambert_with_cosine(|normal, to_light| normal.dot(to_light).max(0.0)),
        rule: "rule-s1-4-l-is-the-unit-vector",
    },
];

/// Session 1's right answers written otherwise than the course's.
pub const RIGHT: &[Right] = &[Right {
    exercise: "s1.1",
    what: "the row measured down from the top, y = H/2 - (row + 1/2)",
    run: || {
        generated::pixel_direction(|c, row, column| {
            let (w, h) = (c.width as Real, c.height as Real);
            Vec3::new(
                column as Real + 0.5 - w / 2.0,
                h / 2.0 - (row as Real + 0.5),
                plane(c),
            )
        })
    },
}];

/// The image plane's `z` of the course's camera: `-H / (2 tan(alpha/2))`.
fn plane(camera: &Camera) -> Real {
    -(camera.height as Real) / (2.0 * (camera.fov / 2.0).tan())
}

/// Lambert's shading, `I / (4 pi d^2) cos albedo / pi`, with the cosine a
/// mistake computes from the normal and the vector to the light, run through its
/// generated check.
fn lambert_with_cosine(cosine: fn(Vec3, Vec3) -> Real) -> Outcome {
    generated::lambert(|light: &PointLight, point, normal, albedo: Colour| {
        let to_light = light.position - point;
        let d2 = to_light.length_squared();
        light.intensity / (4.0 * PI * d2) * cosine(normal, to_light) * albedo / PI
    })
}

/// Both roots of the textbook's quadratic, near and far, if the line meets the
/// sphere.
fn roots(sphere: &Sphere, ray: &Ray) -> (Option<Real>, Option<Real>) {
    let s = ray.origin - sphere.centre;
    let sd = s.dot(ray.direction);
    let delta = sd * sd - (s.length_squared() - sphere.radius * sphere.radius);
    if delta < 0.0 {
        return (None, None);
    }
    (Some(-sd - delta.sqrt()), Some(-sd + delta.sqrt()))
}
