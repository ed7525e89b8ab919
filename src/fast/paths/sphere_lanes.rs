//! A scene's spheres ready for the four-ray test, and the nearest sphere of each of
//! four rays: what [`Scene::nearest_sphere`](crate::scene::Scene::nearest_sphere)
//! finds for one ray, for four paths followed at once.

use crate::fast::simd::four_lanes::FourLanes;
#[cfg(test)]
use crate::fast::simd::portable;
use crate::geometry::{Ray, Sphere};
use crate::maths::Real;

/// The centre, radius and index of each of a scene's spheres, in its order; the
/// index is held as the bits of a `Real`, which the lanes copy as they are.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereLanes {
    spheres: Vec<[Real; 5]>,
    /// The fastest lanes of the processor (asked once, when the lanes are made).
    lanes: FourLanes,
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
            lanes: FourLanes::fastest(),
        }
    }

    /// The lanes the tests run on, for the shading of the same paths.
    pub fn lanes(&self) -> FourLanes {
        self.lanes
    }

    /// Sphere `index`'s centre, radius and index, as the lanes hold them.
    pub fn sphere(&self, index: usize) -> &[Real; 5] {
        &self.spheres[index]
    }

    /// For each of four rays, the distance to the nearest sphere it hits and that
    /// sphere's index, the first sphere on a tie: the course's loop for four rays at
    /// once, to the last bit, with AVX where the processor has it.
    pub fn nearest_of_four(&self, rays: [&Ray; 4]) -> [Option<(Real, usize)>; 4] {
        self.lanes.nearest_of_four(&self.spheres, rays)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;
    #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
    use crate::fast::simd::avx::Avx;
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

    /// Asserts that `nearest_of_four` finds, for every ray, the course loop's sphere
    /// and distance to the last bit.
    fn agrees_with_the_course(
        nearest_of_four: impl Fn(&[[Real; 5]], [&Ray; 4]) -> [Option<(Real, usize)>; 4],
    ) {
        let spheres = spheres();
        let scene = Scene::new(
            Default::default(),
            spheres.clone(),
            None,
            Default::default(),
        );
        let lanes = SphereLanes::new(&spheres);
        let rays = rays();
        let mut hits = 0;
        for four in rays.chunks(4) {
            let ray = |k: usize| &four[k.min(four.len() - 1)];
            let found = nearest_of_four(&lanes.spheres, [ray(0), ray(1), ray(2), ray(3)]);
            for (ray, found) in four.iter().zip(found) {
                let expected = scene.nearest_sphere(ray);
                hits += usize::from(expected.is_some());
                assert_eq!(found, expected, "{ray:?}");
            }
        }
        assert!(hits > 19_000, "{hits}");
    }

    #[test]
    fn the_portable_lanes_find_the_course_loops_sphere_to_the_last_bit() {
        agrees_with_the_course(portable::nearest_of_four);
    }

    #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
    #[test]
    fn the_avx_lanes_find_the_course_loops_sphere_to_the_last_bit() {
        if let Some(avx) = Avx::detect() {
            agrees_with_the_course(|spheres, rays| avx.nearest_of_four(spheres, rays));
        }
    }

    #[test]
    fn a_tie_goes_to_the_first_sphere() {
        let ray = Ray {
            origin: Vec3::new(3.0, 2.0, 9.0),
            direction: -Vec3::Z,
        };
        let found = SphereLanes::new(&spheres()).nearest_of_four([&ray; 4]);
        assert!(found.iter().all(|n| n.map(|n| n.1) == Some(4)), "{found:?}");
    }
}
