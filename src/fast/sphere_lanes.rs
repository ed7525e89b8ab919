//! The nearest sphere from session 3 on: the spheres tested four at a time.
//!
//! A Monte Carlo image traces hundreds of rays per pixel, and in the sphere rooms of
//! sessions 3 and 4 most of the time goes into [`Sphere::intersect`], seven times per
//! ray. A processor can do one operation on four numbers at once (SIMD: single
//! instruction, multiple data) if the four numbers lie side by side in memory. So the
//! centres and radii are stored by coordinate, four spheres per group ("structure of
//! arrays"), and every step of the test runs on the four spheres of a group together.
//! The steps are exactly those of [`Sphere::intersect`], in the same order, so each
//! distance is the same number to the last bit and the image keeps its bytes.

use crate::fast::sphere_group::{Group, LANES, RealLanes, meet, nearest_with};
use crate::geometry::{Ray, Sphere};
use crate::maths::Real;

/// The centres and radii of a scene's spheres, by coordinate, in groups of
/// [`LANES`]. The lanes past the last sphere hold NaN, which no test accepts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SphereLanes {
    groups: Vec<Group>,
    /// Each sphere's centre, radius and index, for the four-ray test; the index is
    /// held as the bits of a `Real`, which the lanes copy as they are.
    spheres: Vec<[Real; 5]>,
    /// Whether the processor has AVX, whose instructions work on four `f64` at once
    /// (checked once, when the lanes are made).
    avx: bool,
}

impl SphereLanes {
    /// The lanes of `spheres`, in their order.
    pub fn new(spheres: &[Sphere]) -> SphereLanes {
        let groups = spheres.chunks(LANES).map(|chunk| {
            let lane = |coordinate: fn(&Sphere) -> Real| {
                std::array::from_fn(|k| chunk.get(k).map_or(Real::NAN, coordinate))
            };
            Group {
                x: lane(|s| s.centre.x),
                y: lane(|s| s.centre.y),
                z: lane(|s| s.centre.z),
                radius: lane(|s| s.radius),
            }
        });
        let each = spheres.iter().enumerate();
        SphereLanes {
            groups: groups.collect(),
            spheres: each
                .map(|(i, s)| {
                    [
                        s.centre.x,
                        s.centre.y,
                        s.centre.z,
                        s.radius,
                        Real::from_bits(i as _),
                    ]
                })
                .collect(),
            avx: has_avx(),
        }
    }

    /// The distance to the nearest sphere that `ray` hits and that sphere's index:
    /// what the loop over the spheres in session 1 returns, ties going to the first
    /// sphere as there. With AVX where the processor has it.
    pub fn nearest(&self, ray: &Ray) -> Option<(Real, usize)> {
        #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
        if self.avx {
            // SAFETY: `avx` is true only where the processor has AVX.
            return unsafe { crate::fast::sphere_group_avx::nearest(&self.groups, ray) };
        }
        nearest_with(&self.groups, ray, Group::intersect)
    }

    /// For each of four rays, the distance to the nearest sphere it hits and that
    /// sphere's index: [`SphereLanes::nearest`] for four paths followed at once, one
    /// ray per lane, each sphere tested against the four rays in one go ([`meet`];
    /// with AVX where the processor has it).
    /// Each lane's steps are those of [`Sphere::intersect`], so each answer is
    /// [`SphereLanes::nearest`]'s to the last bit; a strict `<` keeps the first
    /// sphere on a tie.
    pub fn nearest_of_four(&self, rays: [&Ray; 4]) -> [Option<(Real, usize)>; 4] {
        #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
        if self.avx {
            // SAFETY: `avx` is true only where the processor has AVX.
            return unsafe { crate::fast::sphere_group_avx::nearest_of_four(&self.spheres, rays) };
        }
        let lanes = |f: fn(&Ray) -> Real| RealLanes::from(rays.map(f));
        let origin = [
            lanes(|r| r.origin.x),
            lanes(|r| r.origin.y),
            lanes(|r| r.origin.z),
        ];
        let direction = [
            lanes(|r| r.direction.x),
            lanes(|r| r.direction.y),
            lanes(|r| r.direction.z),
        ];
        let mut nearest = RealLanes::splat(Real::INFINITY);
        let mut which = RealLanes::ZERO;
        for &[x, y, z, radius, index] in &self.spheres {
            let centre = [x, y, z].map(RealLanes::splat);
            let t = meet(origin, direction, centre, RealLanes::splat(radius));
            let closer = t.simd_lt(nearest);
            nearest = closer.select(t, nearest);
            which = closer.select(RealLanes::splat(index), which);
        }
        let (nearest, which) = (nearest.to_array(), which.to_array());
        std::array::from_fn(|k| {
            (nearest[k] < Real::INFINITY).then(|| (nearest[k], which[k].to_bits() as usize))
        })
    }
}

/// Whether this processor has AVX (only ever true on x86-64).
fn has_avx() -> bool {
    #[cfg(target_arch = "x86_64")]
    return std::arch::is_x86_feature_detected!("avx");
    #[cfg(not(target_arch = "x86_64"))]
    return false;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::materials::Material;
    use crate::maths::{Colour, Vec3, pixel_rng, uniform};

    /// The course's loop: every sphere tested, the first of the nearest kept.
    fn course_nearest(spheres: &[Sphere], ray: &Ray) -> Option<(Real, usize)> {
        let mut nearest: Option<(Real, usize)> = None;
        for (i, sphere) in spheres.iter().enumerate() {
            if let Some(t) = sphere.intersect(ray)
                && nearest.is_none_or(|(best, _)| t < best)
            {
                nearest = Some((t, i));
            }
        }
        nearest
    }

    /// The room of the sphere stages, a small ball inside the big one, a tiny far
    /// sphere, and a sphere repeated (a tie): nine spheres, so the last group is
    /// part padding.
    fn spheres() -> Vec<Sphere> {
        let sphere = |x: Real, y: Real, z: Real, radius: Real| Sphere {
            centre: Vec3::new(x, y, z),
            radius,
            material: Material::Diffuse {
                albedo: Colour::ONE,
            },
            emission: Colour::ZERO,
        };
        vec![
            sphere(0.0, 0.0, 0.0, 10.0),
            sphere(0.0, -1000.0, 0.0, 990.0),
            sphere(0.0, 1000.0, 0.0, 940.0),
            sphere(-1000.0, 0.0, 0.0, 940.0),
            sphere(3.0, 2.0, 1.0, 2.0),
            sphere(0.0, 0.0, -1e6, 1e-3),
            sphere(0.0, 0.0, -1000.0, 940.0),
            sphere(3.0, 2.0, 1.0, 2.0),
            sphere(0.0, 0.0, 1000.0, 940.0),
        ]
    }

    #[test]
    fn lanes_find_the_course_loops_sphere_to_the_last_bit() {
        let spheres = spheres();
        let lanes = SphereLanes::new(&spheres);
        let mut rng = pixel_rng(11, 0);
        let mut hits = 0;
        for n in 0..20_000 {
            let mut point = || {
                120.0 * Vec3::new(uniform(&mut rng), uniform(&mut rng), uniform(&mut rng))
                    - Vec3::splat(60.0)
            };
            let origin = if n % 2 == 0 {
                point()
            } else {
                Vec3::new(3.0, 2.0, 1.0)
            };
            let direction = (point() - origin).normalize();
            let ray = Ray { origin, direction };
            let expected = course_nearest(&spheres, &ray);
            hits += usize::from(expected.is_some());
            assert_eq!(lanes.nearest(&ray), expected, "{ray:?}");
            assert_eq!(
                nearest_with(&lanes.groups, &ray, Group::intersect),
                expected
            );
        }
        assert!(hits > 19_000, "{hits}");
        let far = Ray {
            origin: Vec3::new(5e-4, 0.0, 0.0),
            direction: -Vec3::Z,
        };
        assert_eq!(lanes.nearest(&far), course_nearest(&spheres, &far));
    }

    #[test]
    fn a_tie_goes_to_the_first_sphere() {
        let spheres = spheres();
        let ray = Ray {
            origin: Vec3::new(3.0, 2.0, 9.0),
            direction: -Vec3::Z,
        };
        assert_eq!(
            SphereLanes::new(&spheres).nearest(&ray).map(|n| n.1),
            Some(4)
        );
    }
}
