//! Numbers at the extremes: intersections and optics where floating point is at its
//! limits. Each test asserts a bound, and where a naive formula is the reason for the
//! care taken, the test shows that formula failing the same bound. The suite runs in
//! both precisions (`--features f32`); where single precision cannot meet a bound
//! that double meets, the test asserts that it fails, and how.

use rand::{RngExt, SeedableRng};
use raycourse::geometry::{Ray, Sphere};
use raycourse::maths::{Real, Vec3};

/// Whether this build computes in double precision.
const DOUBLE: bool = cfg!(not(feature = "f32"));

/// The textbook root `(-b - sqrt(b^2 - 4c)) / 2` (with `a = 1`), kept as the
/// counter-example: `b^2` and `4c` cancel for small or distant spheres.
fn textbook_intersect(s: &Sphere, ray: &Ray) -> Option<Real> {
    let f = ray.origin - s.centre;
    let b = 2.0 * f.dot(ray.direction);
    let c = f.length_squared() - s.radius * s.radius;
    let disc = b * b - 4.0 * c;
    if disc < 0.0 {
        return None;
    }
    let t = (-b - disc.sqrt()) / 2.0;
    (t > 0.0).then_some(t)
}

/// How far `ray.at(t)` is from the sphere's surface, in units of
/// `eps * max(|p|, r)`.
fn surface_error(s: &Sphere, ray: &Ray, t: Real) -> Real {
    let p = ray.at(t);
    ((p - s.centre).length() - s.radius).abs() / (Real::EPSILON * p.length().max(s.radius))
}

/// What the survey of one kind of sphere found.
#[derive(Debug, Default)]
struct Survey {
    /// Rays aimed at the sphere.
    rays: usize,
    /// Worst surface error of the stable formula's hits, in `eps max(|p|, r)`.
    stable: Real,
    /// Rays the stable formula lost.
    stable_lost: usize,
    /// Worst surface error of the textbook formula's hits.
    textbook: Real,
    /// Rays the textbook formula lost.
    textbook_lost: usize,
}

/// SplitMix64's finaliser, which seeds the survey's generator as the renderer seeds
/// a pixel's (`pixel_rng(17, seed)` from session 3 on), in every session's build.
fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Rays, seeded by `seed`, from near the origin at a sphere of radius `radius` whose
/// centre is `distance` away, each aimed inside the disk the sphere shows.
fn survey(radius: Real, distance: Real, seed: u64) -> Survey {
    let mut result = Survey::default();
    let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(splitmix64(17 ^ splitmix64(seed)));
    for _ in 0..2000 {
        let mut u = || rng.random::<Real>();
        let axis = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5).normalize();
        let s = Sphere::white(axis * distance, radius);
        let origin = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5);
        // Aim inside the disk the sphere shows, up to 0.9 of its radius off-centre.
        let side = axis.cross(Vec3::new(u(), u(), u())).normalize();
        let ray = Ray::new(origin, s.centre + 0.9 * radius * u() * side - origin);
        result.rays += 1;
        match s.intersect(&ray) {
            Some(t) => result.stable = result.stable.max(surface_error(&s, &ray, t)),
            None => result.stable_lost += 1,
        }
        match textbook_intersect(&s, &ray) {
            Some(t) => result.textbook = result.textbook.max(surface_error(&s, &ray, t)),
            None => result.textbook_lost += 1,
        }
    }
    result
}

/// Small spheres far away and walls of radius 1e5, as (radius, distance).
const SPHERES: [(Real, Real); 6] = [
    (1e-3, 1e4),
    (1e-3, 1e6),
    (1.0, 1e7),
    (0.1, 1e5),
    (1e5, 1e5 + 10.0),
    (1e5, 1e5 + 1e3),
];

#[test]
fn stable_sphere_hits_lie_on_the_surface_and_the_textbook_ones_do_not() {
    let surveys: Vec<Survey> = (0..)
        .zip(SPHERES)
        .map(|(k, (r, d))| survey(r, d, k))
        .collect();
    for ((r, d), s) in SPHERES.iter().zip(&surveys) {
        eprintln!("radius {r:e} at {d:e}: {s:?}");
        // Every hit the stable formula finds lies within 4 eps max(|p|, r).
        assert!(s.stable <= 4.0, "stable formula, {r:e} at {d:e}: {s:?}");
    }
    let textbook_breaks = surveys
        .iter()
        .any(|s| s.textbook > 1e3 || s.textbook_lost > 0);
    assert!(
        textbook_breaks,
        "the textbook formula should break the bound"
    );
    let lost: Vec<(Real, Real)> = SPHERES
        .iter()
        .zip(&surveys)
        .filter(|(_, s)| s.stable_lost > 0)
        .map(|(&setup, _)| setup)
        .collect();
    if DOUBLE {
        assert!(lost.is_empty(), "the stable formula lost rays at {lost:?}");
    } else {
        // Single precision cannot even aim at a sphere whose radius is below the
        // spacing of numbers at its distance (1e-3 at 1e4 is 1 ulp).
        assert_eq!(
            lost,
            SPHERES[..3],
            "single precision loses the small far spheres"
        );
    }
}

#[cfg(feature = "s2")]
mod optics {
    use super::*;
    use raycourse::materials::Material;
    use raycourse::materials::optics::refract;
    use raycourse::maths::Colour;

    /// Whether rays `offset` radians either side of the critical angle of `index`
    /// refract (below) and are totally reflected (above), as they should.
    fn resolves_critical_angle(index: Real, offset: Real) -> bool {
        let critical = (1.0 / index).asin();
        let d = |a: Real| Vec3::new(a.sin(), -a.cos(), 0.0);
        refract(d(critical - offset), Vec3::Y, index).is_some()
            && refract(d(critical + offset), Vec3::Y, index).is_none()
    }

    #[test]
    fn refraction_switches_to_reflection_exactly_at_the_critical_angle() {
        for index in [1.33, 1.5, 2.4] {
            assert!(resolves_critical_angle(index, 1e-6), "{index}");
            // Double precision decides 1e-9 rad either side; single precision,
            // whose angles near 0.7 are 6e-8 apart, cannot tell them apart.
            assert_eq!(resolves_critical_angle(index, 1e-9), DOUBLE, "{index}");
        }
    }

    #[test]
    fn extreme_indices_stay_finite_and_unit() {
        let mut worst: Real = 0.0;
        for eta in [1e-6, 1e-3, 1.0, 1e3, 1e6] {
            for angle in [0.0, 1e-7, 1e-3, 0.5, 1.5] {
                let d = Vec3::new((angle as Real).sin(), -(angle as Real).cos(), 0.0);
                if let Some(t) = refract(d, Vec3::Y, eta) {
                    assert!(t.is_finite(), "{eta} {angle}");
                    worst = worst.max((t.length() - 1.0).abs() / Real::EPSILON);
                }
            }
        }
        eprintln!("refracted directions are unit within {worst} eps");
        assert!(worst <= 4.0, "{worst} eps");
    }

    #[test]
    fn index_one_lets_rays_pass_straight() {
        use raycourse::{Overrides, find_stage, render};
        let overrides = Overrides::sized(48, 48, 0);
        let mut glass = find_stage(2, "glass").unwrap().scene(&overrides).unwrap();
        glass.settings.shadows = false;
        glass.spheres[0].material = Material::Glass { index: 1.0 };
        let mut empty = glass.clone();
        empty.spheres.remove(0);
        let (a, b) = (render(&glass).film, render(&empty).film);
        let worst = a
            .pixels
            .iter()
            .zip(&b.pixels)
            .map(|(x, y)| ((*x - *y).abs() / y.max(Colour::splat(1.0))).max_element())
            .fold(0.0, Real::max);
        // The ray crosses two surfaces whose hit points carry a few ulps of error
        // each, and the room is 1000 units across: a few hundred eps in all.
        eprintln!("index 1: largest relative difference {worst:e}");
        assert!(
            worst < 256.0 * Real::EPSILON,
            "largest relative difference {worst}"
        );
    }
}

/// Rays that skim a surface at angles down to 1e-7 rad, rays lying in the faces of
/// a box, and rays that start exactly on a surface.
mod grazing {
    use super::*;

    /// The angles of the grazing rays, in radians.
    const ANGLES: [Real; 7] = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7];

    /// A ray at `angle` to the plane `y = target.y` that meets it at `target`,
    /// coming from 10 units away.
    fn grazing_ray(target: Vec3, angle: Real) -> Ray {
        let d = Vec3::new(angle.cos(), -angle.sin(), 0.0);
        Ray::new(target - 10.0 * d, d)
    }

    #[test]
    fn grazing_rays_meet_a_sphere_where_they_should() {
        // The ray enters the unit sphere at its top, (0, 1, 0), at `angle` to the
        // tangent plane. Where along the surface it enters is ill-conditioned, by
        // 1 / angle: the hit may move by eps / angle along the surface, but it must
        // be found and lie on the surface.
        let s = Sphere::white(Vec3::ZERO, 1.0);
        let target = Vec3::Y;
        let mut found = Vec::new();
        for angle in ANGLES {
            let ray = grazing_ray(target, angle);
            let Some(t) = s.intersect(&ray) else {
                continue;
            };
            found.push(angle);
            let along = (ray.at(t) - target).length() * angle / Real::EPSILON;
            eprintln!("sphere, {angle:e} rad: {along:.2} eps / angle from the target");
            assert!(surface_error(&s, &ray, t) <= 4.0, "{angle}");
            assert!(along <= 64.0, "{angle}: {along}");
        }
        // In both precisions: the stable formula's discriminant is computed from
        // the ray's distance to the centre, not as a difference of squares.
        assert_eq!(found, ANGLES, "every grazing ray enters");
    }

    #[cfg(feature = "s5")]
    #[test]
    fn grazing_rays_meet_a_triangle_where_they_should() {
        use raycourse::geometry::{ShearedRay, intersect_triangle};
        let (a, b, c) = (
            Vec3::new(-100.0, 0.0, -100.0),
            Vec3::new(100.0, 0.0, -100.0),
            Vec3::new(0.0, 0.0, 100.0),
        );
        let target = Vec3::new(0.5, 0.0, 0.25);
        for angle in ANGLES {
            let ray = grazing_ray(target, angle);
            let watertight = ShearedRay::new(&ray).intersect(a, b, c, Real::INFINITY);
            let course = intersect_triangle(&ray, a, b, c, Real::INFINITY);
            for hit in [watertight, course] {
                let t = hit.expect("a plane is never missed at a grazing angle").t;
                let along = (ray.at(t) - target).length() * angle / Real::EPSILON;
                eprintln!("triangle, {angle:e} rad: {along:.2} eps / angle from the target");
                assert!(along <= 64.0, "{angle}: {along}");
            }
        }
    }

    #[cfg(feature = "s5")]
    #[test]
    fn rays_in_the_faces_of_a_box_give_no_nan() {
        use raycourse::geometry::Aabb;
        let unit = Aabb::EMPTY.grow(Vec3::ZERO).grow(Vec3::ONE);
        let entry = |origin: Vec3, direction: Vec3| {
            let ray = Ray::new(origin, direction);
            unit.entry(&ray, ray.direction.recip(), Real::INFINITY)
        };
        for zero in [0.0, -0.0] {
            let along_z = Vec3::new(zero, zero, 1.0);
            // In the faces x = 0 and x = 1, and along the edge x = y = 0: inside.
            for o in [
                Vec3::new(0.0, 0.5, -1.0),
                Vec3::new(1.0, 0.5, -1.0),
                Vec3::new(0.0, 0.0, -1.0),
                Vec3::new(1.0, 1.0, -1.0),
            ] {
                assert_eq!(entry(o, along_z), Some(1.0), "{o} {along_z}");
            }
            // Just outside a face, parallel to it: missed.
            let outside = Vec3::new(-Real::EPSILON, 0.5, -1.0);
            assert_eq!(entry(outside, along_z), None);
            // Starting inside: entered at 0.
            assert_eq!(entry(Vec3::splat(0.5), along_z), Some(0.0));
        }
    }

    #[test]
    fn rays_starting_on_a_sphere() {
        let s = Sphere::white(Vec3::ZERO, 1.0);
        let on = Vec3::X;
        assert_eq!(s.intersect(&Ray::new(on, Vec3::X)), None, "leaving it");
        assert_eq!(
            s.intersect(&Ray::new(on, Vec3::Y)),
            None,
            "along its tangent"
        );
        assert_eq!(s.intersect(&Ray::new(on, -Vec3::X)), Some(2.0), "across it");
    }
}

/// A mesh with everything wrong that a file can legally hold: zero-area and
/// repeated-vertex triangles, zero-length normals and one so short that its squared
/// length underflows to zero, texture coordinates far outside [0, 1], and a 1x1
/// texture (a NaN in the file is refused when it is read: `tests/bad_input.rs`). It renders, smooth and textured, with
/// indirect light, to a film with no NaN or infinite value.
#[cfg(feature = "s7")]
#[test]
fn degenerate_meshes_render_without_nan() {
    use raycourse::{Overrides, parse_scene, render};

    let dir = tempfile::tempdir().unwrap();
    image::RgbImage::from_pixel(1, 1, image::Rgb([200, 120, 40]))
        .save(dir.path().join("one.png"))
        .unwrap();
    let obj = "\
v -10 -10 -20\nv 10 -10 -20\nv 0 10 -20\nv 20 -10 -20\nv -10 -10 -20\n\
vn 1e-38 0 0\nvn 0 0 0\nvn 0 0 1\n\
vt -1e30 1e30\nvt 1e30 -1e30\nvt 0.5 0.5\n\
f 1/1/1 2/2/2 3/3/3\n\
f 1/3/3 2/3/3 4/3/3\n\
f 1/3/3 5/3/3 2/3/3\n\
f 3/2/2 3/2/2 3/2/2\n\
f 1/2/2 2/1/1 3/3/3\n";
    std::fs::write(dir.path().join("bad.obj"), obj).unwrap();
    let scene_text = r#"
[render]
width = 32
height = 32
samples = 4
gamma = 2.2
indirect = true
acceleration = "bvh"

[camera]
position = [0, 0, 30]
fov = 60

[light]
position = [0, 20, 20]
intensity = 1e5

[[meshes]]
obj = "bad.obj"
smooth_normals = true
textured = true
texture = "one.png"

[[spheres]]
centre = [0, -1000, 0]
radius = 990
material = { diffuse = [0.8, 0.8, 0.8] }
"#;
    let path = dir.path().join("scene.toml");
    let scene = parse_scene(scene_text, &path, &Overrides::default()).unwrap();
    let result = render(&scene);
    assert!(result.film.pixels.iter().all(|p| p.is_finite()));
    assert_eq!(result.dropped, 0, "no sample was NaN or infinite");
    let lit = result
        .film
        .pixels
        .iter()
        .filter(|p| p.max_element() > 0.0)
        .count();
    assert!(
        lit > 100,
        "the mesh and the floor are seen: {lit} lit pixels"
    );
}
