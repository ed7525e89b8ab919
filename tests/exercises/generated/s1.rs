//! Session 1 on generated inputs: the camera ray through a pixel, the ray-sphere
//! distance, the nearest hit, Lambert shading.

use proptest::prelude::*;
use raycourse::camera::Camera;
use raycourse::geometry::{Ray, Sphere};
use raycourse::lights::PointLight;
use raycourse::maths::{Colour, PI, Real, Vec3};

use super::{apart, differs, n, near, near_vec, on_generated, ulps, v};
use crate::known::Outcome;
use crate::say;

/// An image side: small and odd ones often (1, 3, 5 ... where `W/2` is not an
/// integer), large ones too.
fn side() -> impl Strategy<Value = u32> {
    prop_oneof![1u32..=9, (5u32..=400).prop_map(|s| s | 1), 2u32..=1200]
}

/// A pixel index below `size`: the borders often.
fn index(size: u32) -> impl Strategy<Value = u32> {
    prop_oneof![Just(0), Just(size - 1), 0..size]
}

/// A unit direction, with `-0` and axis-aligned ones among them.
pub fn direction() -> impl Strategy<Value = Vec3> {
    let axis = prop_oneof![
        Just(Vec3::new(0.0, 0.0, -1.0)),
        Just(Vec3::new(-0.0, 0.0, -1.0)),
        Just(Vec3::X),
        Just(Vec3::new(0.0, -1.0, -0.0)),
    ];
    let any = (-1.0..1.0 as Real, -1.0..1.0 as Real, -1.0..1.0 as Real)
        .prop_filter("not too short to normalise", |(x, y, z)| {
            x * x + y * y + z * z > 0.01
        })
        .prop_map(|(x, y, z)| Vec3::new(x, y, z).normalize());
    prop_oneof![1 => axis, 4 => any]
}

/// A length scale from `1e-4` to `1e4`, powers of ten among them.
pub fn scale() -> impl Strategy<Value = Real> {
    prop_oneof![
        (-4i32..=4).prop_map(|k| (10.0 as Real).powi(k)),
        (-4.0..4.0 as Real).prop_map(|e| (10.0 as Real).powf(e)),
    ]
}

/// How far objects stand from the origin, in their own sizes: up to `1e6` (`1e2`
/// in single precision, whose seven digits would leave nothing of the object).
#[cfg(feature = "s4")]
pub fn far() -> impl Strategy<Value = Real> {
    let most: Real = if std::mem::size_of::<Real>() == 8 {
        6.0
    } else {
        2.0
    };
    (0.0..most).prop_map(|e| (10.0 as Real).powf(e))
}

/// Exercise s1.1 on generated images: odd and non-square sizes, border pixels,
/// fields of view from 1 to 179 degrees. Any length is right, so the directions
/// are compared once scaled to the course's image plane.
pub fn pixel_direction(yours: impl Fn(&Camera, u32, u32) -> Vec3) -> Outcome {
    let inputs = (side(), side(), 1.0..179.0 as Real)
        .prop_flat_map(|(w, h, fov)| (Just(w), Just(h), Just(fov), index(h), index(w)));
    on_generated(
        "Camera::pixel_direction",
        inputs,
        |(w, h, degrees, row, column)| {
            let fov = degrees.to_radians();
            let camera = Camera::new(Vec3::ZERO, fov, w, h);
            let course = course::camera::Camera::new(Vec3::ZERO, fov, w, h);
            let gave = yours(&camera, row, column);
            let expected = course.pixel_direction(row, column);
            let scaled = gave * (expected.z / gave.z);
            if gave.z < 0.0 && near_vec(scaled, expected, ulps(64.0)) {
                return Ok(());
            }
            let case = say!(
                "generated-s1-w-h-alpha-degrees-pixel-row",
                value = n(degrees),
                w = w,
                h = h,
                row = row,
                column = column
            );
            let why = pixel_diagnosis(gave, expected, (w, h, fov), (row, column));
            Err(differs(&case, &v(gave), &v(expected), why))
        },
    )
}

/// Which rule of the camera ray `gave` breaks, `expected` being the course's
/// direction through pixel (`row`, `column`) of a `w` x `h` image.
fn pixel_diagnosis(
    gave: Vec3,
    expected: Vec3,
    (w, h, fov): (u32, u32, Real),
    (row, column): (u32, u32),
) -> Option<String> {
    if gave.z >= 0.0 || gave.z.is_nan() {
        let wide = if fov > PI / 2.0 {
            say!("generated-s1-h-2-tan-alpha-would-change")
        } else {
            String::new()
        };
        return Some(say!(
            "generated-s1-the-camera-looks-down-z-the",
            wide = wide
        ));
    }
    let scaled = gave * (expected.z / gave.z);
    let (x, y) = (scaled.x, scaled.y);
    let tolerance = ulps(64.0) * expected.length();
    let x_right = (x - expected.x).abs() <= tolerance;
    let y_right = (y - expected.y).abs() <= tolerance;
    let i = h - 1 - row;
    let from_top = row as Real - h as Real / 2.0 + 0.5;
    let mut why = vec![];
    if !x_right {
        why.push(column_rule(x - expected.x, w, column, expected.x));
    }
    if !y_right {
        why.push(row_rule(
            y - expected.y,
            (y - from_top).abs() < 1e-6,
            h,
            i,
            expected.y,
        ));
    }
    // A half pixel or rows from the top explain the difference better than an
    // image plane at another distance, which any wrong x or y may look like.
    let half = |off: Real| (off.abs() - 0.5).abs() < 1e-6;
    let specific = (!x_right && half(x - expected.x))
        || (!y_right && (half(y - expected.y) || (y - from_top).abs() < 1e-6));
    if !specific && let Some(theirs) = plane_of(gave, expected) {
        return Some(plane_rule(theirs, -expected.z, (w, h, fov)));
    }
    (!why.is_empty()).then(|| why.join(&say!("generated-s1-message")))
}

/// The rule of a pixel's x, `x = j - W/2 + 1/2`, when yours is `off` from the
/// course's `x` in column `j` of an image `w` wide.
fn column_rule(off: Real, w: u32, j: u32, x: Real) -> String {
    if w % 2 == 1 && (off.abs() - 0.5).abs() < 1e-6 {
        say!(
            "generated-s1-the-centre-of-pixel-j-is",
            w2 = n(w as Real / 2.0),
            w = w
        )
    } else if (off.abs() - 0.5).abs() < 1e-6 {
        say!("generated-s1-the-centre-of-pixel-j-is-2")
    } else {
        say!(
            "generated-s1-the-centre-of-pixel-j-is-3",
            value = n(x),
            off = n(off),
            j = j
        )
    }
}

/// The rule of a pixel's y, `y = i - H/2 + 1/2` with `i = H - 1 - row`, when yours
/// is `off` from the course's `y` (`from_top`: yours counts rows from the top) in
/// row `i` of an image `h` high.
fn row_rule(off: Real, from_top: bool, h: u32, i: u32, y: Real) -> String {
    if from_top {
        say!("generated-s1-rows-count-from-the-top-of", i = i)
    } else if h % 2 == 1 && (off.abs() - 0.5).abs() < 1e-6 {
        say!(
            "generated-s1-the-centre-of-row-i-is",
            h2 = n(h as Real / 2.0),
            h = h
        )
    } else {
        say!(
            "generated-s1-the-centre-of-row-i-h",
            y = n(y),
            off = n(off),
            i = i
        )
    }
}

/// The rule of the image plane's distance, when `gave` puts it at `theirs` rather
/// than the course's `plane`.
fn plane_rule(theirs: Real, plane: Real, (w, h, fov): (u32, u32, Real)) -> String {
    let wrong_tangent = (h as Real) / (2.0 * fov.tan());
    let width = (w as Real) / (2.0 * (fov / 2.0).tan());
    let detail = if near(theirs, wrong_tangent, plane, 1e-3) {
        say!("generated-s1-yours-is-h-2-tan-alpha")
    } else if near(theirs, width, plane, 1e-3) && w != h {
        say!("generated-s1-yours-uses-w-the-field-of")
    } else {
        String::new()
    };
    say!(
        "generated-s1-the-image-plane-lies-at-h",
        plane = n(plane),
        theirs = n(theirs),
        detail = detail
    )
}

/// The distance of the image plane that `gave` implies, when it is the course's
/// `expected` but for that distance: `gave = k (x, y, -d)` with the course's `x`
/// and `y`, `d` another distance. `None` when `x` and `y` are wrong, or right.
fn plane_of(gave: Vec3, expected: Vec3) -> Option<Real> {
    let (ex, ey) = (expected.x, expected.y);
    let k = if ex.abs() >= ey.abs() {
        gave.x / ex
    } else {
        gave.y / ey
    };
    let tolerance = ulps(256.0) * expected.length();
    let same_xy = (gave.x - k * ex).abs() <= tolerance * k.abs()
        && (gave.y - k * ey).abs() <= tolerance * k.abs();
    let theirs = -gave.z / k;
    let other = !near(theirs, -expected.z, expected.z, ulps(256.0));
    (k.is_finite() && k > 0.0 && same_xy && other).then_some(theirs)
}

/// Where a generated ray starts, seen from the sphere: its distance from the
/// centre and from the ray's line, in radii.
#[derive(Clone, Copy, Debug)]
enum Place {
    /// In front of the sphere, `distance` radii from its centre, the line passing
    /// `miss` radii from it (below 1: a hit; just below or above 1: grazing).
    Outside { distance: Real, miss: Real },
    /// Inside, `depth` radii from the centre.
    Inside { depth: Real },
    /// Behind the sphere, moving away.
    Behind { distance: Real },
    /// On the sphere itself (`|s| = R` exactly), moving inwards or not: a ray
    /// leaving a surface, whose own start is the root `t = 0`.
    Surface,
}

/// A ray and a sphere: `(centre, radius, origin, direction, place)`.
type RaySphereCase = (Vec3, Real, Vec3, Vec3, Place);

/// Rays and spheres at every scale from `1e-4` to `1e4`, in front, grazing (the
/// line a thousandth of a radius inside or outside), from inside and behind;
/// with `far`, spheres up to `1e8` radii away (`1e4` in single precision).
fn ray_sphere(far: bool) -> impl Strategy<Value = RaySphereCase> {
    let reach: Real = match (far, std::mem::size_of::<Real>()) {
        (true, 8) => 1e8,
        (true, _) => 1e4,
        (false, _) => 1e3,
    };
    let grazing = prop_oneof![Just(0.999 as Real), Just(1.001 as Real)];
    let place = prop_oneof![
        (
            1.5..reach.log10(),
            prop_oneof![0.0..0.99 as Real, grazing.clone(), 1.01..3.0 as Real]
        )
            .prop_map(|(e, miss)| Place::Outside {
                distance: (10.0 as Real).powf(e),
                miss
            }),
        (1.5..reach.log10(), grazing).prop_map(|(e, miss)| Place::Outside {
            distance: (10.0 as Real).powf(e),
            miss
        }),
        (0.0..0.99 as Real).prop_map(|depth| Place::Inside { depth }),
        (1.5..100.0 as Real).prop_map(|distance| Place::Behind { distance }),
        Just(Place::Surface),
    ];
    let centre = (scale(), direction());
    (centre, scale(), direction(), direction(), place).prop_map(
        |((far_off, towards), radius, d, side, place)| {
            let centre = far_off * towards;
            let across = (side - side.dot(d) * d).normalize_or(d.any_orthonormal_vector());
            let origin = match place {
                Place::Outside { distance, miss } => {
                    let along = (distance * distance - miss * miss).max(0.0).sqrt();
                    centre - radius * along * d + radius * miss * across
                }
                Place::Inside { depth } => centre + radius * depth * across,
                Place::Behind { distance } => centre + radius * distance * d,
                Place::Surface => return on_surface(radius, side, d),
            };
            (centre, radius, origin, d, place)
        },
    )
}

/// A ray starting exactly on a sphere of `radius` around the origin, at the pole
/// of `side`'s largest axis (so that `|s|^2 - R^2` is exactly 0), along `d`.
fn on_surface(radius: Real, side: Vec3, d: Vec3) -> RaySphereCase {
    let axis = side.abs().max_position();
    let mut origin = Vec3::ZERO;
    origin[axis] = radius.copysign(side[axis]);
    (Vec3::ZERO, radius, origin, d, Place::Surface)
}

/// A ray-sphere test of the student's crate.
type Intersect<'a> = &'a dyn Fn(&Sphere, &Ray) -> Option<Real>;

/// Exercise s1.2 on generated rays and spheres: both tests the exercise marks, the
/// textbook's within the scales where its discriminant keeps its digits (a sphere
/// at most 1000 radii away), the renderer's up to `1e8` radii away. Distances
/// agree within the rounding of `|s| + R`, and of `|s|^2 / R` for the textbook's.
pub fn sphere_distance(textbook: Intersect, robust: Intersect) -> Outcome {
    on_generated("Sphere::intersect_textbook", ray_sphere(false), |case| {
        compare_distance(
            textbook,
            case,
            course::geometry::Sphere::intersect_textbook,
            true,
        )
    })?;
    on_generated("Sphere::intersect", ray_sphere(true), |case| {
        compare_distance(robust, case, course::geometry::Sphere::intersect, false)
    })
}

/// The student's distance against the course's on one case.
fn compare_distance(
    yours: Intersect,
    (centre, radius, origin, direction, place): RaySphereCase,
    course: fn(&course::geometry::Sphere, &course::geometry::Ray) -> Option<Real>,
    textbook: bool,
) -> Result<(), String> {
    let gave = yours(&Sphere::white(centre, radius), &Ray::new(origin, direction));
    let expected = course(
        &course::geometry::Sphere::white(centre, radius),
        &course::geometry::Ray::new(origin, direction),
    );
    let s = (origin - centre).length();
    let mut tolerance = ulps(256.0) * (s + radius);
    if textbook {
        tolerance += ulps(64.0) * s * s / radius;
    }
    let same = match (gave, expected) {
        (None, None) => true,
        (Some(t), Some(e)) => (t - e).abs() <= tolerance,
        _ => false,
    };
    if same {
        return Ok(());
    }
    let case = say!(
        "generated-s1-a-sphere-of-radius-at-the",
        radius = n(radius),
        centre = v(centre),
        origin = v(origin),
        direction = v(direction)
    );
    let (gave_t, expected_t) = apart(gave.unwrap_or(0.0), expected.unwrap_or(0.0));
    let show = |t: Option<Real>, text: String| {
        t.map_or(say!("generated-s1-no-hit"), |_| format!("t = {text}"))
    };
    let why = distance_diagnosis(
        gave,
        expected,
        (centre, radius, origin, direction),
        place,
        textbook,
    );
    Err(differs(
        &case,
        &show(gave, gave_t),
        &show(expected, expected_t),
        why,
    ))
}

/// Which rule of the ray-sphere distance `gave` breaks.
fn distance_diagnosis(
    gave: Option<Real>,
    expected: Option<Real>,
    (centre, radius, origin, direction): (Vec3, Real, Vec3, Vec3),
    place: Place,
    textbook: bool,
) -> Option<String> {
    let s = origin - centre;
    let sd = s.dot(direction);
    let chord = (s - sd * direction).length();
    let root = (radius * radius - chord * chord).max(0.0).sqrt();
    let (near_root, far_root) = (-sd - root, -sd + root);
    let textbook_gives = course::geometry::Sphere::intersect_textbook(
        &course::geometry::Sphere::white(centre, radius),
        &course::geometry::Ray::new(origin, direction),
    );
    let close = |t: Real, r: Real| (t - r).abs() <= 1e-3 * radius + ulps(1024.0) * s.length();
    Some(match (gave, expected, place) {
        (_, _, Place::Outside { distance, .. }) if !textbook && gave == textbook_gives => say!(
            "generated-s1-the-sphere-is-radii-away-the",
            distance = n(distance)
        ),
        (Some(t), _, Place::Behind { .. })
            if t < 0.0 || close(t, near_root) || close(t, far_root) =>
        {
            say!("generated-s1-the-sphere-is-behind-the-ray")
        }
        (Some(t), _, Place::Surface) if t <= 0.0 => {
            say!("generated-s1-the-ray-starts-on-the-sphere")
        }
        (Some(t), _, _) if t <= 0.0 => say!("generated-s1-only-t-0-is-a-hit"),
        (Some(t), Some(_), Place::Inside { .. }) if close(t, near_root) => {
            say!("generated-s1-from-inside-the-sphere-the-near")
        }
        (Some(t), Some(_), Place::Outside { .. }) if close(t, far_root) => {
            say!("generated-s1-from-outside-the-hit-is-the")
        }
        (None, Some(_), Place::Surface) => say!("generated-s1-the-ray-starts-on-the-sphere-2"),
        (None, Some(_), Place::Inside { .. }) => {
            say!("generated-s1-from-inside-the-sphere-the-near-2")
        }
        (_, _, Place::Outside { miss, .. }) if (miss - 1.0).abs() < 0.01 => {
            say!("generated-s1-the-ray-grazes-the-sphere-its", miss = n(miss))
        }
        _ => return None,
    })
}

/// Exercise s1.3 on generated rows of spheres along a ray: some behind, some
/// missed, some at exactly the same distance (the same sphere listed twice, where
/// the first of the list wins, as the chapter says).
pub fn nearest_sphere(
    yours: impl Fn(&raycourse::scene::Scene, &Ray) -> Option<(Real, usize)>,
) -> Outcome {
    let one = (
        -20.0..20.0 as Real,
        0.0..3.0 as Real,
        0.1..2.0 as Real,
        0u8..4,
    );
    let inputs = (direction(), prop::collection::vec(one, 1..6), scale());
    on_generated("Scene::nearest_sphere", inputs, |(d, spheres, size)| {
        let list = along_the_ray(d, &spheres, size);
        let scene = scene(list.iter().map(|&(c, r)| Sphere::white(c, r)).collect());
        let gave = yours(&scene, &Ray::new(Vec3::ZERO, d));
        let expected = course_nearest(&list, d);
        let same = match (gave, expected) {
            (None, None) => true,
            (Some((t, i)), Some((e, j))) => {
                i == j && (t - e).abs() <= ulps(256.0) * (e + size * 40.0)
            }
            _ => false,
        };
        if same {
            return Ok(());
        }
        Err(nearest_differs(&list, d, gave, expected))
    })
}

/// Spheres `(centre, radius)` placed `along` the ray from the origin along `d` and
/// `off` it, in units of `size`; a `twin` of 0 lists the same sphere twice.
fn along_the_ray(d: Vec3, spheres: &[(Real, Real, Real, u8)], size: Real) -> Vec<(Vec3, Real)> {
    let across = d.any_orthonormal_vector();
    let mut list = vec![];
    for &(along, off, radius, twin) in spheres {
        let sphere = (size * (along * d + off * across), size * radius);
        list.push(sphere);
        if twin == 0 {
            list.push(sphere);
        }
    }
    list
}

/// The course's nearest hit among `list` along `d` from the origin.
fn course_nearest(list: &[(Vec3, Real)], d: Vec3) -> Option<(Real, usize)> {
    let scene = course::scene::Scene::new(
        course::camera::Camera::new(Vec3::ZERO, 1.0, 1, 1),
        list.iter()
            .map(|&(c, r)| course::geometry::Sphere::white(c, r))
            .collect(),
        None,
        course::scene::Settings::default(),
    );
    scene.nearest_sphere(&course::geometry::Ray::new(Vec3::ZERO, d))
}

/// The message of a nearest hit that differs: the spheres, both hits and the rule.
fn nearest_differs(
    list: &[(Vec3, Real)],
    d: Vec3,
    gave: Option<(Real, usize)>,
    expected: Option<(Real, usize)>,
) -> String {
    let listed: Vec<String> = list
        .iter()
        .enumerate()
        .map(|(i, (c, r))| say!("generated-s1-radius-at", r = n(*r), c = v(*c), i = i))
        .collect();
    let case = say!(
        "generated-s1-spheres-the-ray-from-the-origin",
        s1_message = listed.join(&say!("generated-s1-message")),
        d = v(d)
    );
    let show = |hit: Option<(Real, usize)>| {
        hit.map_or(say!("generated-s1-no-hit"), |(t, i)| {
            say!("generated-s1-sphere-at-t", value = n(t), i = i)
        })
    };
    let why = match (gave, expected) {
        (Some((t, i)), Some((e, j)))
            if i > j && list[i] == list[j] && (t - e).abs() <= 1e-9 * e.abs() =>
        {
            Some(say!(
                "generated-s1-spheres-and-are-met-at-the",
                j = j,
                i = i
            ))
        }
        (Some((t, _)), Some((e, _))) if t > e => {
            Some(say!("generated-s1-the-nearest-hit-is-the-smallest"))
        }
        _ => None,
    };
    differs(&case, &show(gave), &show(expected), why)
}

/// A scene of `spheres` in the student's crate, with no light.
fn scene(spheres: Vec<Sphere>) -> raycourse::scene::Scene {
    raycourse::scene::Scene::new(
        Camera::new(Vec3::ZERO, 1.0, 1, 1),
        spheres,
        None,
        raycourse::scene::Settings::default(),
    )
}

/// Exercise s1.4 on generated lights and points, at scales from `1e-4` to `1e4`,
/// with normals facing the light, grazing and facing away. Components agree within
/// a few roundings of the radiance.
pub fn lambert(yours: impl Fn(&PointLight, Vec3, Vec3, Colour) -> Colour) -> Outcome {
    let albedo = (0.0..1.0 as Real, 0.0..1.0 as Real, 0.0..1.0 as Real)
        .prop_map(|(r, g, b)| Colour::new(r, g, b));
    let inputs = (
        direction(),
        scale(),
        direction(),
        direction(),
        1e-3..1e6 as Real,
        albedo,
    );
    on_generated(
        "PointLight::lambert",
        inputs,
        |(towards, distance, normal, spread, intensity, albedo)| {
            let point = spread * distance * 0.5;
            let light = PointLight {
                position: point + distance * towards,
                intensity,
            };
            let course = course::lights::PointLight {
                position: light.position,
                intensity,
            };
            let gave = yours(&light, point, normal, albedo);
            let expected = course.lambert(point, normal, albedo);
            // The radiance facing the light: a cosine near 0 is rounded alike whatever
            // the formula, so the tolerance follows the light's full strength.
            let full = intensity / (4.0 * PI * distance * distance) / PI;
            if (gave - expected).abs().max_element() <= ulps(64.0) * full {
                return Ok(());
            }
            let case = say!(
                "generated-s1-a-light-of-power-at-the",
                intensity = n(intensity),
                light_position = v(light.position),
                point = v(point),
                normal = v(normal),
                albedo = v(albedo)
            );
            let why = lambert_diagnosis(gave, expected, normal.dot(towards), distance)
                .or_else(|| lit_from_the_origin(gave, (&course, point, normal, albedo)));
            Err(differs(&case, &v(gave), &v(expected), why))
        },
    )
}

/// Which rule of Lambert's shading `gave` breaks: `cos` is `<N, l>`, `d` the
/// distance to the light.
fn lambert_diagnosis(gave: Colour, expected: Colour, cos: Real, d: Real) -> Option<String> {
    if cos <= 0.0 {
        return Some(say!(
            "generated-s1-the-surface-faces-away-from-the",
            cos = n(cos)
        ));
    }
    let channel = expected.abs().max_position();
    let ratio = gave[channel] / expected[channel];
    let rules = lambert_rules(cos, d);
    rules
        .into_iter()
        .find(|(r, _)| (ratio / r - 1.0).abs() < 1e-4)
        .map(|(_, why)| why)
}

/// Whether `gave` is Lambert's shading with `l` taken from the origin to the light,
/// the light's position normalised, rather than from the shaded point: the two
/// agree only for a point on the line from the origin to the light.
fn lit_from_the_origin(
    gave: Colour,
    (light, point, normal, albedo): (&course::lights::PointLight, Vec3, Vec3, Colour),
) -> Option<String> {
    let d2 = light.position.distance_squared(point);
    let cos = normal.dot(light.position.normalize()).max(0.0);
    let origin = light.intensity / (4.0 * PI * d2) * cos * albedo / PI;
    let full = light.intensity / (4.0 * PI * d2) / PI;
    ((gave - origin).abs().max_element() <= ulps(64.0) * full)
        .then(|| say!("generated-s1-l-points-from-the-shaded-point"))
}

/// The ratios of a wrong Lambert shading to the right one that name a mistake,
/// with the rule each breaks: `cos` is `<N, l>`, `d` the distance to the light.
fn lambert_rules(cos: Real, d: Real) -> [(Real, String); 6] {
    [
        (PI, say!("generated-s1-the-diffuse-brdf-is-albedo-pi")),
        (4.0 * PI, say!("generated-s1-a-point-light-of-power-i")),
        (d, say!("generated-s1-yours-is-d-times-the-course")),
        (d * d, say!("generated-s1-the-light-falls-off-as-1")),
        (1.0 / cos, say!("generated-s1-lambert-s-cosine-n-l-is")),
        (1.0 / PI, say!("generated-s1-1-pi-is-counted-twice")),
    ]
}
