//! Spheres: the only shape of the first four sessions. The room's walls are
//! spheres too, so large that they look flat.

use crate::geometry::hit::offset_along;
use crate::geometry::{Hit, Ray};
use crate::materials::Material;
use crate::maths::{Colour, Real, Vec3, error_bound};

// ANCHOR: sphere
/// A sphere of centre `centre`, radius `radius`, made of `material`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Centre of the sphere.
    pub centre: Vec3,
    /// Radius, positive.
    pub radius: Real,
    /// What its surface is made of: how it reflects light.
    pub material: Material,
    /// Radiance the surface emits by itself, in every direction (zero for most
    /// objects): the white disk of figure 1 glows, and so will session 4's light.
    pub emission: Colour,
}
// ANCHOR_END: sphere

impl Sphere {
    /// A white diffuse sphere (albedo 1) that emits nothing: the plainest object,
    /// which tests and examples place by the hundred.
    pub fn white(centre: Vec3, radius: Real) -> Sphere {
        Sphere {
            centre,
            radius,
            material: Material::Diffuse {
                albedo: Colour::ONE,
            },
            emission: Colour::ZERO,
        }
    }

    // ANCHOR: intersect_textbook
    /// The course's ray-sphere test, as the textbook writes it: with `s = O - C`,
    /// `t^2 + 2 (s.d) t + (|s|^2 - R^2) = 0` has the roots
    /// `t = -(s.d) +- sqrt((s.d)^2 - (|s|^2 - R^2))`, and the nearest hit is the smaller
    /// positive one. Right for the course's scenes; [`Sphere::intersect`], which the
    /// renderer uses, computes the same without the cancellation that makes this
    /// formula miss a small, distant sphere.
    ///
    /// Exercise s1.2, the ray-sphere distance: book session 1, "A white disk".
    pub fn intersect_textbook(&self, ray: &Ray) -> Option<Real> {
        let s = ray.origin - self.centre;
        let sd = s.dot(ray.direction);
        let discriminant = sd * sd - (s.length_squared() - self.radius * self.radius);
        if discriminant < 0.0 {
            return None;
        }
        let root = discriminant.sqrt();
        [-sd - root, -sd + root].into_iter().find(|&t| t > 0.0)
    }
    // ANCHOR_END: intersect_textbook

    // ANCHOR: intersect
    /// The smallest `t > 0` at which `ray` meets the sphere, if any.
    ///
    /// With `s = O - C` and a unit direction `d`, the points `|O + t d - C|^2 = R^2`
    /// solve `t^2 + 2 (s.d) t + (|s|^2 - R^2) = 0`. The textbook discriminant
    /// `(s.d)^2 - (|s|^2 - R^2)` subtracts two large, nearly equal numbers for a small
    /// or distant sphere; Ray Tracing Gems, chapter 7, computes the same quantity as
    /// `R^2 - |s - (s.d) d|^2`, the squared half-chord, without that cancellation.
    /// The roots then come from `mu = -(s.d + sign(s.d) sqrt(discriminant))` as
    /// `(|s|^2 - R^2) / mu` and `mu`, so the smaller one is not computed as a
    /// difference of nearly equal numbers either.
    ///
    /// Exercise s1.2, the ray-sphere distance: book session 1, "A white disk".
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<Real> {
        let s = ray.origin - self.centre;
        let sd = s.dot(ray.direction);
        let c = s.length_squared() - self.radius * self.radius;
        if c > 0.0 && sd > 0.0 {
            return None; // outside, and moving away
        }
        let chord = s - sd * ray.direction;
        let discriminant = self.radius * self.radius - chord.length_squared();
        if discriminant < 0.0 {
            return None;
        }
        let mu = -(sd + discriminant.sqrt().copysign(sd));
        if mu == 0.0 {
            return None;
        }
        let (t0, t1) = (c / mu, mu);
        let (near, far) = if t0 < t1 { (t0, t1) } else { (t1, t0) };
        if near > 0.0 {
            Some(near)
        } else if far > 0.0 {
            Some(far)
        } else {
            None
        }
    }
    // ANCHOR_END: intersect

    // ANCHOR: hit_at
    /// The hit record at distance `t` along `ray`, for the sphere numbered `object`
    /// in the scene. The point is projected back onto
    /// the sphere, `c + r (p - c) / |p - c|`, so that its error depends on the size
    /// and position of the sphere only, not on how far the ray travelled.
    pub fn hit_at(&self, ray: &Ray, t: Real, object: usize) -> Hit {
        let radial = ray.at(t) - self.centre;
        let normal = radial / radial.length();
        let point = self.centre + self.radius * normal;
        let error = error_bound(7) * (self.centre.abs() + (self.radius * normal).abs());
        Hit {
            t,
            point,
            normal,
            error,
            offset: offset_along(normal, error),
            material: self.material,
            emission: self.emission,
            object,
            from_outside: (ray.origin - self.centre).length_squared() > self.radius * self.radius,
        }
    }
    // ANCHOR_END: hit_at
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Real, b: Real, tolerance: Real) -> bool {
        (a - b).abs() <= tolerance * b.abs().max(1.0)
    }

    #[test]
    fn ray_from_outside_hits_the_near_side() {
        let s = Sphere::white(Vec3::ZERO, 10.0);
        let ray = Ray::new(Vec3::new(0.0, 0.0, 55.0), -Vec3::Z);
        assert_eq!(s.intersect(&ray), Some(45.0));
    }

    #[test]
    fn ray_from_inside_hits_the_far_side() {
        let s = Sphere::white(Vec3::ZERO, 10.0);
        let ray = Ray::new(Vec3::new(0.0, 0.0, 3.0), -Vec3::Z);
        assert_eq!(s.intersect(&ray), Some(13.0));
    }

    #[test]
    fn sphere_behind_the_ray_is_missed() {
        let s = Sphere::white(Vec3::ZERO, 10.0);
        let ray = Ray::new(Vec3::new(0.0, 0.0, 55.0), Vec3::Z);
        assert_eq!(s.intersect(&ray), None);
    }

    /// Offsets of 1e-9 and 1e-6 at 10 are below single precision's resolution:
    /// tests/suite/extremes.rs compares the two precisions.
    #[test]
    #[cfg(not(feature = "f32"))]
    fn tangent_and_near_tangent_rays() {
        let s = Sphere::white(Vec3::ZERO, 10.0);
        let tangent = Ray::new(Vec3::new(10.0, 0.0, 55.0), -Vec3::Z);
        assert!(close(s.intersect(&tangent).unwrap(), 55.0, 1e-12));
        let outside = Ray::new(Vec3::new(10.0 + 1e-9, 0.0, 55.0), -Vec3::Z);
        assert_eq!(s.intersect(&outside), None);
        let inside = Ray::new(Vec3::new(10.0 - 1e-6, 0.0, 55.0), -Vec3::Z);
        let t = s.intersect(&inside).unwrap();
        let expected = 55.0 - (100.0 - (10.0 - 1e-6 as Real).powi(2)).sqrt();
        assert!(close(t, expected, 1e-12), "{t} vs {expected}");
    }

    #[test]
    fn oblique_ray_distance_matches_geometry() {
        // From (0, 0, 55) towards (3, 4, 0): the chord's midpoint is the projection of
        // the centre on the ray.
        let s = Sphere::white(Vec3::ZERO, 10.0);
        let o = Vec3::new(0.0, 0.0, 55.0);
        let ray = Ray::new(o, Vec3::new(3.0, 4.0, -55.0));
        let t = s.intersect(&ray).unwrap();
        let along = (-o).dot(ray.direction);
        let miss2 = o.length_squared() - along * along;
        let expected = along - (100.0 - miss2).sqrt();
        assert!(close(t, expected, 256.0 * Real::EPSILON));
        assert!(close(ray.at(t).length(), 10.0, 256.0 * Real::EPSILON));
    }

    #[test]
    fn far_giant_spheres_are_hit_accurately() {
        // Walls of radius 1e5 whose surface lies 10 units from the origin.
        for axis in [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X] {
            let s = Sphere::white(axis * (1e5 + 10.0), 1e5);
            let ray = Ray::new(Vec3::ZERO, axis);
            let t = s.intersect(&ray).unwrap();
            // Rounding the centre, about 1e5, moves the surface by a few ulps of 1e5.
            let bound = 4.0 * Real::EPSILON * 1e5 / 10.0;
            assert!(close(t, 10.0, bound), "t = {t}");
            // From inside the giant sphere, the far side.
            let from_inside = Ray::new(axis * 20.0, axis);
            let t = s.intersect(&from_inside).unwrap();
            assert!(close(t, 2e5 - 10.0, 64.0 * Real::EPSILON), "t = {t}");
        }
    }

    #[test]
    fn the_textbook_formula_agrees_in_the_course_s_scenes() {
        let s = Sphere::white(Vec3::new(3.0, -1.0, 2.0), 10.0);
        for k in 0..1000 {
            let a = k as Real * 0.0137;
            let ray = Ray::new(
                Vec3::new(0.0, 0.0, 55.0),
                Vec3::new(a.sin() * 0.3, a.cos() * 0.3, -1.0),
            );
            match (s.intersect(&ray), s.intersect_textbook(&ray)) {
                (Some(robust), Some(textbook)) => {
                    assert!(close(robust, textbook, 1e-9), "{robust} {textbook}")
                }
                (robust, textbook) => assert_eq!(robust.is_some(), textbook.is_some(), "ray {k}"),
            }
        }
    }

    #[test]
    fn tiny_far_sphere_is_hit_where_the_textbook_formula_breaks() {
        // A sphere of radius 1e-3 at 1e6: b^2 and c are about 1e12 and their
        // difference 1e-6, below the rounding of either.
        let s = Sphere::white(Vec3::new(0.0, 0.0, -1e6), 1e-3);
        let ray = Ray::new(Vec3::new(5e-4, 0.0, 0.0), -Vec3::Z);
        let t = s
            .intersect(&ray)
            .expect("the ray passes through the sphere");
        let expected = 1e6 - (1e-6 - 25e-8 as Real).sqrt();
        assert!(close(t, expected, 1e-12), "t = {t}, expected {expected}");
        // In single precision 1e6 has no digits left for a sphere of 1e-3 at all.
        let textbook = s.intersect_textbook(&ray);
        assert!(
            cfg!(feature = "f32") || textbook.is_none_or(|t| (t - expected).abs() > 0.5e-3),
            "the textbook formula misses the sphere or is off by half its radius: {textbook:?}"
        );
    }

    #[test]
    fn hit_point_lies_on_the_sphere_within_its_error_bound() {
        let s = Sphere::white(Vec3::new(3.0, -1000.0, 7.0), 990.0);
        let ray = Ray::new(Vec3::new(0.0, 0.0, 55.0), Vec3::new(0.3, -1.0, -0.8));
        let hit = s.hit_at(&ray, s.intersect(&ray).unwrap(), 0);
        let off = ((hit.point - s.centre).length() - s.radius).abs();
        assert!(off <= hit.error.length(), "{off} > {}", hit.error.length());
        assert!((hit.normal.length() - 1.0).abs() < 1e-15);
    }
}
