//! Numbers at the extremes: intersections and optics where floating point is at its
//! limits. Each test asserts a bound, and where a naive formula is the reason for the
//! care taken, the test shows that formula failing the same bound.

use raycourse::{Colour, Material, Ray, Real, Sphere, Vec3, pixel_rng, uniform};

fn sphere(centre: Vec3, radius: Real) -> Sphere {
    Sphere {
        centre,
        radius,
        material: Material::Diffuse {
            albedo: Colour::ONE,
        },
        emission: Colour::ZERO,
    }
}

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

/// Spheres small and far, and walls of radius 1e5, hit by seeded rays from near the
/// origin: (how many rays, worst error of the stable formula, of the textbook one,
/// how many textbook hits were lost).
fn precision_survey() -> (usize, Real, Real, usize) {
    let mut worst = (0, 0.0 as Real, 0.0 as Real, 0);
    let mut rng = pixel_rng(17, 0);
    let setups: [(Real, Real); 6] = [
        (1e-3, 1e4),
        (1e-3, 1e6),
        (1.0, 1e7),
        (0.1, 1e5),
        (1e5, 1e5 + 10.0),
        (1e5, 1e5 + 1e3),
    ];
    for (radius, distance) in setups {
        for _ in 0..2000 {
            let mut u = || uniform(&mut rng);
            let axis = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5).normalize();
            let s = sphere(axis * distance, radius);
            let origin = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5);
            // Aim inside the disk the sphere shows, 0.9 of its radius off-centre.
            let side = axis.cross(Vec3::new(u(), u(), u())).normalize();
            let ray = Ray::new(origin, s.centre + 0.9 * radius * u() * side - origin);
            let t = s.intersect(&ray).expect("aimed at the sphere");
            worst.0 += 1;
            worst.1 = worst.1.max(surface_error(&s, &ray, t));
            match textbook_intersect(&s, &ray) {
                Some(t) => worst.2 = worst.2.max(surface_error(&s, &ray, t)),
                None => worst.3 += 1,
            }
        }
    }
    worst
}

#[test]
fn stable_sphere_hits_lie_on_the_surface_and_the_textbook_ones_do_not() {
    let (rays, stable, textbook, lost) = precision_survey();
    eprintln!(
        "{rays} rays: worst |(|p - c| - r)| / (eps max(|p|, r)): stable {stable:.2}, \
         textbook {textbook:.3e}, textbook misses {lost}"
    );
    assert!(stable <= 4.0, "stable formula: {stable}");
    assert!(
        textbook > 1e3 || lost > 0,
        "the textbook formula should break the bound: {textbook}, {lost} misses"
    );
}

#[cfg(feature = "s2")]
mod optics {
    use super::*;
    use raycourse::refract;

    #[test]
    fn refraction_switches_to_reflection_exactly_at_the_critical_angle() {
        for index in [1.33, 1.5, 2.4] {
            let critical = (1.0 / index as Real).asin();
            let d = |a: Real| Vec3::new(a.sin(), -a.cos(), 0.0);
            assert!(
                refract(d(critical - 1e-9), Vec3::Y, index).is_some(),
                "{index}"
            );
            assert!(
                refract(d(critical + 1e-9), Vec3::Y, index).is_none(),
                "{index}"
            );
        }
    }

    #[test]
    fn extreme_indices_stay_finite_and_unit() {
        for eta in [1e-6, 1e-3, 1.0, 1e3, 1e6] {
            for angle in [0.0, 1e-7, 1e-3, 0.5, 1.5] {
                let d = Vec3::new((angle as Real).sin(), -(angle as Real).cos(), 0.0);
                if let Some(t) = refract(d, Vec3::Y, eta) {
                    assert!(
                        t.is_finite() && (t.length() - 1.0).abs() < 1e-9,
                        "{eta} {angle}"
                    );
                }
            }
        }
    }

    #[test]
    fn index_one_lets_rays_pass_straight() {
        use indicatif::ProgressBar;
        use raycourse::{Overrides, find_stage, render};
        use std::num::NonZeroU32;
        let overrides = Overrides {
            width: NonZeroU32::new(48),
            height: NonZeroU32::new(48),
            ..Overrides::default()
        };
        let mut glass = find_stage(2, "glass").unwrap().scene(&overrides).unwrap();
        glass.settings.shadows = false;
        glass.spheres[0].material = Material::Glass { index: 1.0 };
        let mut empty = glass.clone();
        empty.spheres.remove(0);
        let (a, b) = (
            render(&glass, &ProgressBar::hidden()).film,
            render(&empty, &ProgressBar::hidden()).film,
        );
        let worst = a
            .pixels
            .iter()
            .zip(&b.pixels)
            .map(|(x, y)| ((*x - *y).abs() / y.max(Colour::splat(1.0))).max_element())
            .fold(0.0, Real::max);
        assert!(worst < 1e-9, "largest relative difference {worst}");
    }
}
