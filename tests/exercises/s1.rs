//! Session 1: the camera ray, the ray-sphere distance, the nearest hit, Lambert.

use std::path::Path;

use raycourse::camera::Camera;
use raycourse::geometry::{Ray, Sphere};
use raycourse::lights::PointLight;
use raycourse::maths::{Colour, PI, Real, Vec3};
use raycourse::scene::Scene;
use raycourse::{Overrides, parse_scene};

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, close_vec, ensure, maybe, nearest, same_distance, vec};
use crate::say;
use crate::words::decimal;

/// Session 1's exercises, in the book's order.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "s1.1",
        name: "s1_1_camera_pixel_direction",
        shown_by: "white-disk",
        needs: &[],
        check: pixel_direction,
    },
    Exercise {
        id: "s1.2",
        name: "s1_2_sphere_intersect",
        shown_by: "white-disk",
        needs: &[],
        check: sphere_distance,
    },
    Exercise {
        id: "s1.3",
        name: "s1_3_scene_nearest_sphere",
        shown_by: "spheres",
        needs: &["s1.2"],
        check: nearest_sphere,
    },
    Exercise {
        id: "s1.4",
        name: "s1_4_point_light_lambert",
        shown_by: "shading",
        needs: &[],
        check: lambert,
    },
];

/// A 4 x 2 image with a 90-degree field of view: the image plane lies at
/// `H / (2 tan 45) = 1` in front of the eye, and pixel centres sit half a pixel in.
/// Top left (row 0, column 0): `i = H - 1 - 0 = 1`, so `(0 - 2 + 0.5, 1 - 1 + 0.5, -1)`.
fn pixel_direction() -> Outcome {
    let camera = Camera::new(Vec3::ZERO, PI / 2.0, 4, 2);
    let cases = [
        (
            (0, 0),
            Vec3::new(-1.5, 0.5, -1.0),
            say!("s1-case-the-top-left"),
        ),
        (
            (1, 3),
            Vec3::new(1.5, -0.5, -1.0),
            say!("s1-case-the-bottom-right"),
        ),
        (
            (0, 2),
            Vec3::new(0.5, 0.5, -1.0),
            say!("s1-case-the-top-right-of-the-centre"),
        ),
    ];
    for ((row, column), expected, place) in cases {
        let gave = camera.pixel_direction(row, column);
        ensure(gave.length() > 0.0 && gave.is_finite(), || {
            say!(
                "s1-pixel-row-column-gave-the-direction",
                vec_gave = vec(gave),
                row = row,
                column = column
            )
        })?;
        // Any length is right: only the direction matters.
        close_vec(
            &say!(
                "s1-the-direction-through-pixel-row-column",
                row = row,
                column = column,
                place = place
            ),
            gave.normalize(),
            expected.normalize(),
            1e-5,
        )?;
    }
    in_pixel_units()?;
    generated::pixel_direction(Camera::pixel_direction)
}

/// Session 3 adds its antialiasing jitter, in pixels, to this direction, so the
/// direction is in pixel units: one pixel to the right is one unit along x, one
/// down one unit along -y, whatever the image's size and field of view (here 8 x 4
/// and 60 degrees, whose image plane lies at `4 / (2 tan 30) = 3.46`).
fn in_pixel_units() -> Outcome {
    let camera = Camera::new(Vec3::ZERO, PI / 3.0, 8, 4);
    let corner = camera.pixel_direction(0, 0);
    let steps = [
        ((0, 1), Vec3::X, say!("s1-case-one-pixel-to-the-right")),
        ((1, 0), -Vec3::Y, say!("s1-case-one-pixel-down")),
    ];
    for ((row, column), expected, step) in steps {
        close_vec(
            &say!(
                "s1-pixel-direction-pixel-direction-0-0",
                row = row,
                column = column,
                step = step
            ),
            camera.pixel_direction(row, column) - corner,
            expected,
            1e-5,
        )?;
    }
    Ok(())
}

/// Rays from the origin: a sphere of radius 1 at distance 5 is met at `t = 5 - 1`;
/// from the centre of a sphere of radius 2 the ray leaves at `t = 2`; a sphere behind
/// the ray, or 2.24 away from its line, is missed; a sphere of radius 1 at
/// `(0, 3, -4)`, 5 away along the ray, at `t = 4` again.
fn sphere_distance() -> Outcome {
    let z = Vec3::new(0.0, 0.0, -1.0);
    let cases = [
        (
            say!("s1-case-in-front"),
            Vec3::new(0.0, 0.0, -5.0),
            1.0,
            z,
            Some(4.0),
        ),
        (
            say!("s1-case-around-the-eye"),
            Vec3::ZERO,
            2.0,
            z,
            Some(2.0),
        ),
        (
            say!("s1-case-behind-the-eye"),
            Vec3::new(0.0, 0.0, 5.0),
            1.0,
            z,
            None,
        ),
        (
            say!("s1-case-beside-the-ray-2-24-from"),
            Vec3::new(0.0, 0.0, -5.0),
            1.0,
            Vec3::new(0.0, 0.5, -1.0),
            None,
        ),
        (
            say!("s1-case-on-an-oblique-ray"),
            Vec3::new(0.0, 3.0, -4.0),
            1.0,
            Vec3::new(0.0, 0.6, -0.8),
            Some(4.0),
        ),
    ];
    // Both tests the exercise marks: the textbook's and the renderer's.
    let tests: [(&str, RaySphere); 2] = [
        ("Sphere::intersect_textbook", Sphere::intersect_textbook),
        ("Sphere::intersect", Sphere::intersect),
    ];
    for (test, intersect) in tests {
        for (what, centre, radius, direction, expected) in cases.clone() {
            let ray = Ray::new(Vec3::ZERO, direction);
            let gave = intersect(&Sphere::white(centre, radius), &ray);
            let right = same_distance(gave, expected, 1e-4);
            ensure(right, || {
                let radius = decimal(radius.to_string());
                say!(
                    "s1-a-sphere-of-radius-at-the",
                    vec_centre = vec(centre),
                    vec = vec(Vec3::ZERO),
                    ray_direction = vec(ray.direction),
                    maybe_gave = maybe(gave),
                    maybe_expected = maybe(expected),
                    test = test,
                    radius = radius,
                    what = what
                )
            })?;
        }
    }
    far_sphere()?;
    generated::sphere_distance(&Sphere::intersect_textbook, &Sphere::intersect)
}

/// A ray-sphere test: the distance at which the ray meets the sphere, if it does.
type RaySphere = fn(&Sphere, &Ray) -> Option<Real>;

/// The case the chapter warns of, for the renderer's test alone: a sphere of radius
/// 1 far along the ray (`10^8` away in double precision, `10^4` in single), the ray
/// passing 0.5 from its centre, meets it at `t = far - sqrt(0.75)`. The textbook
/// discriminant `(s.d)^2 - (|s|^2 - R^2)` subtracts two numbers near `far^2`, whose
/// rounding is larger than the 0.75 sought, and finds `far` or nothing.
fn far_sphere() -> Outcome {
    let far: Real = if std::mem::size_of::<Real>() == 4 {
        1e4
    } else {
        1e8
    };
    let centre = Vec3::new(0.5, 0.0, -far);
    let ray = Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0));
    let gave = Sphere::white(centre, 1.0).intersect(&ray);
    let expected = far - (0.75 as Real).sqrt();
    ensure(same_distance(gave, Some(expected), 0.05), || {
        say!(
            "s1-sphere-intersect-a-sphere-of-radius",
            maybe_gave = maybe(gave),
            maybe_expected = maybe(Some(expected)),
            far = far
        )
    })
}

/// A scene of spheres read from TOML text, as a stage's scene file is read.
pub fn scene(toml: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("sessions/checks.toml");
    parse_scene(toml, &path, &Overrides::default()).expect("the checks' scenes are valid")
}

/// Three spheres along the ray, listed far one first: the nearest is number 1 at
/// `t = 4`, not the first of the list that the ray meets (`t = 9`); the one behind
/// the eye does not count.
fn nearest_sphere() -> Outcome {
    let room = scene(
        "[render]\nwidth = 8\nheight = 8\n[camera]\nposition = [0, 0, 0]\nfov = 60\n\
         [light]\nposition = [0, 10, 0]\nintensity = 1\n\
         [[spheres]]\ncentre = [0, 0, -10]\nradius = 1\nmaterial = { diffuse = [1, 1, 1] }\n\
         [[spheres]]\ncentre = [0, 0, -5]\nradius = 1\nmaterial = { diffuse = [1, 1, 1] }\n\
         [[spheres]]\ncentre = [0, 0, 3]\nradius = 1\nmaterial = { diffuse = [1, 1, 1] }\n",
    );
    let ray = Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0));
    let gave = room.nearest_sphere(&ray);
    ensure(
        gave.is_some_and(|(t, i)| i == 1 && (t - 4.0).abs() < 1e-4),
        || {
            say!(
                "s1-spheres-at-z-10-5-and",
                nearest_gave = nearest(gave),
                nearest = nearest(Some((4.0, 1)))
            )
        },
    )?;
    let up = Ray::new(Vec3::ZERO, Vec3::new(0.0, 1.0, 0.0));
    let gave = room.nearest_sphere(&up);
    ensure(gave.is_none(), || {
        say!(
            "s1-the-same-spheres-the-ray-along",
            nearest_gave = nearest(gave),
            nearest = nearest(None)
        )
    })?;
    generated::nearest_sphere(Scene::nearest_sphere)
}

/// A light of power `Phi = 400 pi^2` 10 above the point: `Phi / (4 pi r^2) = pi`,
/// so facing it the radiance is `pi * 1 * albedo / pi = albedo`; tilted by 45
/// degrees, `albedo / sqrt 2`; 20 away, a quarter; facing away, black.
fn lambert() -> Outcome {
    let light = PointLight {
        position: Vec3::new(0.0, 10.0, 0.0),
        intensity: 400.0 * PI * PI,
    };
    let albedo = Colour::new(0.5, 0.25, 1.0);
    let up = Vec3::new(0.0, 1.0, 0.0);
    let cases = [
        (
            say!("s1-case-facing-the-light-10-away"),
            Vec3::ZERO,
            up,
            albedo,
        ),
        (
            say!("s1-case-tilted-by-45-degrees"),
            Vec3::ZERO,
            Vec3::new(1.0, 1.0, 0.0).normalize(),
            albedo / (2.0 as Real).sqrt(),
        ),
        (
            say!("s1-case-facing-the-light-20-away"),
            Vec3::new(0.0, -10.0, 0.0),
            up,
            albedo / 4.0,
        ),
        (say!("s1-case-facing-away"), Vec3::ZERO, -up, Colour::ZERO),
    ];
    for (what, point, normal, expected) in cases {
        close_vec(
            &say!(
                "s1-albedo-at-normal-under-a-light",
                vec_albedo = vec(albedo),
                vec_point = vec(point),
                vec_normal = vec(normal),
                light_position = vec(light.position),
                what = what
            ),
            light.lambert(point, normal, albedo),
            expected,
            1e-4,
        )?;
    }
    generated::lambert(PointLight::lambert)
}
