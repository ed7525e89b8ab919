//! A scene's spheres ready for the test of several rays at once, and the nearest
//! sphere of each: what [`Scene::nearest_sphere`](crate::scene::Scene::nearest_sphere)
//! finds for one ray, for the paths followed at once (four, or eight in single
//! precision).
//!
//! The test is [`Sphere::intersect`](crate::geometry::Sphere::intersect)'s, step
//! by step in the same order, on the lanes of a SIMD register (one ray per lane),
//! so every distance is the same number to the last bit. It is written once for
//! any kind of lanes ([`RealSource`]), with the usual operators.

use crate::fast::lanes::Lanes;
use crate::fast::simd::real_lanes::{LANES, RealLanes, RealSource, VectorLanes, gather3};
use crate::geometry::{Ray, Sphere};
use crate::maths::Real;

/// The centre, radius and index of each of a scene's spheres, in its order; the
/// index is held as the bits of a `Real`, which the lanes copy as they are.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereLanes {
    spheres: Vec<[Real; 5]>,
    /// The fastest lanes of the processor (asked once, when the lanes are made).
    lanes: Lanes,
}

impl SphereLanes {
    /// The lanes of `spheres`, in their order.
    pub fn new(spheres: &[Sphere]) -> SphereLanes {
        let row = |(i, s): (usize, &Sphere)| {
            let index = Real::from_bits(i as _);
            [s.centre.x, s.centre.y, s.centre.z, s.radius, index]
        };
        SphereLanes {
            spheres: spheres.iter().enumerate().map(row).collect(),
            lanes: Lanes::fastest(),
        }
    }

    /// The lanes the paths' tests and shading run on.
    pub fn lanes(&self) -> Lanes {
        self.lanes
    }

    /// Sphere `index`'s centre, radius and index, as the lanes hold them.
    pub fn sphere(&self, index: usize) -> &[Real; 5] {
        &self.spheres[index]
    }

    /// For each of the `rays` (one per lane), the distance to the nearest sphere
    /// it hits and that sphere's index, the first sphere on a tie: the course's loop
    /// for all the rays at once, on `lanes`, to the last bit. Each sphere is tested
    /// against the rays at once (`meet`); a strict `<` keeps the first sphere on a
    /// tie, as the course's loop does.
    #[inline(always)]
    pub fn nearest_of_each<L: RealSource>(
        &self,
        lanes: L,
        rays: [&Ray; LANES],
    ) -> [Option<(Real, usize)>; LANES] {
        let origin = gather3(lanes, rays.map(|r| r.origin));
        let direction = gather3(lanes, rays.map(|r| r.direction));
        let mut nearest = lanes.splat(Real::INFINITY);
        let mut which = lanes.splat(0.0);
        for &[x, y, z, radius, index] in &self.spheres {
            let centre = [lanes.splat(x), lanes.splat(y), lanes.splat(z)];
            let t = meet(lanes, origin, direction, centre, lanes.splat(radius));
            let closer = t.lt(nearest);
            nearest = closer.select(t, nearest);
            which = closer.select(lanes.splat(index), which);
        }
        let (t, which) = (nearest.to_array(), which.to_array());
        std::array::from_fn(|k| found(t[k], which[k]))
    }
}

// ANCHOR: meet
/// For each of four lanes, the smallest `t > 0` at which the ray from `origin` along
/// the unit vector `direction` meets the sphere of `centre` and `radius`, or
/// infinity: `Sphere::intersect` on four pairs at once. Every lane computes every
/// step, whether or not its sphere is missed early (a negative discriminant gives a
/// NaN root, a zero `mu` an infinite root); the misses are picked out at the end.
#[inline(always)]
fn meet<L: RealSource>(
    lanes: L,
    origin: VectorLanes<L::Wide>,
    direction: VectorLanes<L::Wide>,
    centre: VectorLanes<L::Wide>,
    radius: L::Wide,
) -> L::Wide {
    let [dx, dy, dz] = direction;
    let zero = lanes.splat(0.0);
    // s = O - C, s.d, and c = |s|^2 - R^2.
    let (sx, sy, sz) = (
        origin[0] - centre[0],
        origin[1] - centre[1],
        origin[2] - centre[2],
    );
    let sd = sx * dx + sy * dy + sz * dz;
    let r2 = radius * radius;
    let c = sx * sx + sy * sy + sz * sz - r2;
    // The discriminant R^2 - |s - (s.d) d|^2, without cancellation.
    let (mx, my, mz) = (sx - sd * dx, sy - sd * dy, sz - sd * dz);
    let discriminant = r2 - (mx * mx + my * my + mz * mz);
    // mu = -(s.d + copysign(sqrt(discriminant), s.d)); the roots mu and c / mu.
    let root = discriminant.sqrt() | (sd & lanes.splat(-0.0));
    let mu = -(sd + root);
    let t0 = c / mu;
    let before = t0.lt(mu);
    let (near, far) = (before.select(t0, mu), before.select(mu, t0));
    let t = near.gt(zero).select(near, far);
    let away = c.gt(zero) & sd.gt(zero);
    let valid = discriminant.ge(zero) & (mu.ne(zero) & far.gt(zero));
    away.and_not(valid).select(t, lanes.splat(Real::INFINITY))
}
// ANCHOR_END: meet

/// A lane's answer: the distance `t` and the sphere whose index has the bits of
/// `which`, or `None` where `t` is infinite (no sphere met).
#[inline(always)]
fn found(t: Real, which: Real) -> Option<(Real, usize)> {
    (t < Real::INFINITY).then_some((t, which.to_bits() as usize))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;
    #[cfg(target_arch = "x86_64")]
    use crate::fast::simd::avx::Avx;
    use crate::fast::simd::portable::Portable;
    use crate::materials::Material;
    use crate::maths::{Colour, Vec3, pixel_rng, uniform};

    /// The room of the sphere stages, a small ball inside the big one, a tiny far
    /// sphere, and a sphere repeated (a tie): nine spheres.
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

    /// 20,000 rays: from random points, and from inside the small ball, towards
    /// random points; the last one towards the tiny far sphere.
    fn rays() -> Vec<Ray> {
        let mut rng = pixel_rng(11, 0);
        let mut rays: Vec<Ray> = (0..20_000)
            .map(|n| {
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
                Ray { origin, direction }
            })
            .collect();
        rays.push(Ray {
            origin: Vec3::new(5e-4, 0.0, 0.0),
            direction: -Vec3::Z,
        });
        rays
    }

    /// Asserts that `lanes` find, for every ray, the course loop's sphere and
    /// distance to the last bit.
    fn agrees_with_the_course(lanes: impl RealSource) {
        let spheres = spheres();
        let scene = Scene::new(
            Default::default(),
            spheres.clone(),
            None,
            Default::default(),
        );
        let rows = SphereLanes::new(&spheres);
        let rays = rays();
        let mut hits = 0;
        for chunk in rays.chunks(LANES) {
            let ray = |k: usize| &chunk[k.min(chunk.len() - 1)];
            let found = rows.nearest_of_each(lanes, std::array::from_fn(ray));
            for (ray, found) in chunk.iter().zip(found) {
                let expected = scene.nearest_sphere(ray);
                hits += usize::from(expected.is_some());
                assert_eq!(found, expected, "{ray:?}");
            }
        }
        assert!(hits > 19_000, "{hits}");
    }

    #[test]
    fn the_portable_lanes_find_the_course_loops_sphere_to_the_last_bit() {
        agrees_with_the_course(Portable);
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
    fn the_avx_lanes_find_the_course_loops_sphere_to_the_last_bit() {
        agrees_with_the_course(Avx::for_test());
    }

    #[test]
    fn a_tie_goes_to_the_first_sphere() {
        let ray = Ray {
            origin: Vec3::new(3.0, 2.0, 9.0),
            direction: -Vec3::Z,
        };
        let found = SphereLanes::new(&spheres()).nearest_of_each(Portable, [&ray; LANES]);
        assert!(found.iter().all(|n| n.map(|n| n.1) == Some(4)), "{found:?}");
    }
}
