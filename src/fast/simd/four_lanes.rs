//! Which lanes of four `Real` numbers the paths followed at once run on: AVX's,
//! where the processor has them (asked once, at run time), else the portable ones.
//! Both compute every number to the last bit as the course's functions do; this type
//! only chooses, and calls the tests and the shading written once for any lanes
//! ([`lanes`](crate::fast::simd::lanes), [`shading`](crate::fast::paths::shading)).

use crate::fast::paths::shading::{FourVectors, LightSamples, PointLit, SphereHits};
#[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
use crate::fast::simd::avx::Avx;
use crate::fast::simd::portable;
use crate::geometry::{Hit, Ray};
use crate::lights::PointLight;
use crate::maths::{Colour, Real, Vec3};

/// The lanes that the four-ray tests and the four hits' shading run on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FourLanes {
    /// AVX: four `f64` per instruction, on the x86-64 processors that have it.
    #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
    Avx(Avx),
    /// The `wide` crate's lanes, on any processor.
    Portable,
}

impl FourLanes {
    /// The fastest lanes this processor has.
    pub fn fastest() -> FourLanes {
        #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
        if let Some(avx) = Avx::detect() {
            return FourLanes::Avx(avx);
        }
        FourLanes::Portable
    }

    /// For each of four `rays`, the nearest of `spheres` (centre, radius and index
    /// as the bits of a `Real`) and its distance: the course's loop, on the lanes.
    pub fn nearest_of_four(
        self,
        spheres: &[[Real; 5]],
        rays: [&Ray; 4],
    ) -> [Option<(Real, usize)>; 4] {
        match self {
            #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
            FourLanes::Avx(avx) => avx.nearest_of_four(spheres, rays),
            FourLanes::Portable => portable::nearest_of_four(spheres, rays),
        }
    }

    /// The hit records of four rays on their spheres, ray `k` meeting `spheres[k]`
    /// at `t[k]`, their normals facing the rays: `Sphere::hit_at` and
    /// `Hit::facing_the_ray`, on the lanes.
    pub fn sphere_hits(
        self,
        rays: [&Ray; 4],
        t: [Real; 4],
        spheres: [&[Real; 5]; 4],
    ) -> SphereHits {
        match self {
            #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
            FourLanes::Avx(avx) => avx.sphere_hits(rays, t, spheres),
            FourLanes::Portable => portable::sphere_hits(rays, t, spheres),
        }
    }

    /// At four hits of surfaces of `albedo`, the light from `light` if nothing is
    /// in the way and the shadow rays: `PointLight::lambert` and
    /// `Hit::spawn_towards`, on the lanes.
    pub fn point_light(self, hits: [&Hit; 4], albedo: [Colour; 4], light: &PointLight) -> PointLit {
        match self {
            #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
            FourLanes::Avx(avx) => avx.point_light(hits, albedo, light),
            FourLanes::Portable => portable::point_light(hits, albedo, light),
        }
    }

    /// At four hits of surfaces of `albedo`, from each hit's random numbers `[u1,
    /// cos phi, sin phi]` (`phi = 2 pi u2`), a direction towards the sphere light of
    /// centre, radius and emission `light`, its ray and the light it brings:
    /// `Tracer::light_sample` after its random numbers, on the lanes.
    pub fn sphere_light(
        self,
        hits: [&Hit; 4],
        albedo: [Colour; 4],
        samples: [[Real; 3]; 4],
        light: (Vec3, Real, Colour),
    ) -> LightSamples {
        match self {
            #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
            FourLanes::Avx(avx) => avx.sphere_light(hits, albedo, samples, light),
            FourLanes::Portable => portable::sphere_light(hits, albedo, samples, light),
        }
    }

    /// The origins and directions of the cosine-weighted bounces of four hits from
    /// their samples `[cos phi, sin phi, u2]`: `Tracer::cosine_direction` after its
    /// random numbers, and `Hit::spawn`, on the lanes.
    pub fn bounces(self, hits: [&Hit; 4], samples: [[Real; 3]; 4]) -> (FourVectors, FourVectors) {
        match self {
            #[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
            FourLanes::Avx(avx) => avx.bounces(hits, samples),
            FourLanes::Portable => portable::bounces(hits, samples),
        }
    }
}

/// The four entries of `hits`, a lane without one repeating the first that has
/// one; `None` if none has.
pub(crate) fn repeated<T>(hits: &[Option<T>; 4]) -> Option<[&T; 4]> {
    let first = hits.iter().flatten().next()?;
    let lane = |k: usize| hits[k].as_ref().unwrap_or(first);
    Some([lane(0), lane(1), lane(2), lane(3)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;
    use crate::fast::paths::shading::vector;
    use crate::fast::paths::sphere_lanes::SphereLanes;
    use crate::geometry::Sphere;
    use crate::materials::Material;
    use crate::maths::frame::Frame;
    use crate::maths::sampling::sample_cosine_hemisphere;
    use crate::maths::{PI, PixelRng, Vec3, pixel_rng, uniform};

    /// The room of the sphere stages with a ball in it, and a ball the rays start
    /// inside.
    fn scene() -> Scene {
        let sphere = |centre: Vec3, radius: Real| Sphere {
            centre,
            radius,
            material: Material::Diffuse {
                albedo: Colour::ONE,
            },
            emission: Colour::ZERO,
        };
        let wall = |axis: Vec3, radius: Real| sphere(1000.0 * axis, radius);
        let spheres = vec![
            sphere(Vec3::ZERO, 10.0),
            sphere(Vec3::new(20.0, -5.0, 3.0), 30.0),
            wall(-Vec3::Y, 990.0),
            wall(Vec3::Y, 940.0),
            wall(-Vec3::X, 940.0),
            wall(Vec3::X, 940.0),
            wall(-Vec3::Z, 940.0),
            wall(Vec3::Z, 940.0),
        ];
        Scene::new(Default::default(), spheres, None, Default::default())
    }

    /// A random point of the room.
    fn point(rng: &mut PixelRng) -> Vec3 {
        let mut u = || 110.0 * uniform(rng) - 55.0;
        Vec3::new(u(), u(), u())
    }

    /// The bits of `v`'s coordinates: equal bits are the same number to the last
    /// bit, the sign of a zero included.
    fn bits(v: Vec3) -> [impl PartialEq + std::fmt::Debug; 3] {
        v.to_array().map(Real::to_bits)
    }

    /// Four rays and their nearest spheres' distances and indices.
    type Four = ([Ray; 4], [(Real, usize); 4]);

    /// 4,000 rays between random points of the room, in fours, with their nearest
    /// spheres (every ray meets a wall).
    fn fours(scene: &Scene) -> Vec<Four> {
        let mut rng = pixel_rng(12, 0);
        (0..1000)
            .map(|_| {
                let rays: [Ray; 4] = std::array::from_fn(|_| {
                    let origin = point(&mut rng);
                    let direction = (point(&mut rng) - origin).normalize();
                    Ray { origin, direction }
                });
                let nearest = rays.map(|ray| scene.nearest_sphere(&ray).expect("a wall"));
                (rays, nearest)
            })
            .collect()
    }

    /// The course's hit records of four rays, facing the rays.
    fn course_hits(scene: &Scene, rays: &[Ray; 4], nearest: [(Real, usize); 4]) -> [Hit; 4] {
        std::array::from_fn(|k| {
            let (t, object) = nearest[k];
            scene.spheres[object]
                .hit_at(&rays[k], t, object)
                .facing_the_ray()
        })
    }

    /// Asserts that `lanes` give every number of the course's hit records, direct
    /// light and bounces to the last bit.
    fn agrees_with_the_course(lanes: FourLanes) {
        let scene = scene();
        let rows = SphereLanes::new(&scene.spheres);
        let light = PointLight {
            position: Vec3::new(-10.0, 20.0, 40.0),
            intensity: 2e10,
        };
        let mut rng = pixel_rng(13, 0);
        for (rays, nearest) in fours(&scene) {
            let expected = course_hits(&scene, &rays, nearest);
            let found = lanes.sphere_hits(
                [&rays[0], &rays[1], &rays[2], &rays[3]],
                nearest.map(|n| n.0),
                nearest.map(|n| rows.sphere(n.1)),
            );
            for (k, hit) in expected.iter().enumerate() {
                assert_eq!(bits(vector(&found.point, k)), bits(hit.point));
                assert_eq!(bits(vector(&found.normal, k)), bits(hit.normal));
                assert_eq!(bits(vector(&found.error, k)), bits(hit.error));
                assert_eq!(bits(vector(&found.offset, k)), bits(hit.offset));
                assert_eq!(found.outside[k].to_bits() != 0, hit.from_outside);
            }
            let hits = [&expected[0], &expected[1], &expected[2], &expected[3]];
            let albedo = std::array::from_fn(|_| Vec3::new(uniform(&mut rng), 0.5, 1.0));
            let lit = lanes.point_light(hits, albedo, &light);
            let samples: [[Real; 2]; 4] =
                std::array::from_fn(|_| [uniform(&mut rng), uniform(&mut rng)]);
            let phi = samples.map(|[u1, _]| 2.0 * PI * u1);
            let with_angles = std::array::from_fn(|k| [phi[k].cos(), phi[k].sin(), samples[k][1]]);
            let (origin, direction) = lanes.bounces(hits, with_angles);
            for (k, hit) in expected.iter().enumerate() {
                let (shadow, distance) = hit.spawn_towards(light.position);
                let lambert = light.lambert(hit.point, hit.normal, albedo[k]);
                assert_eq!(bits(vector(&lit.lit, k)), bits(lambert));
                assert_eq!(bits(vector(&lit.origin, k)), bits(shadow.origin));
                assert_eq!(bits(vector(&lit.direction, k)), bits(shadow.direction));
                assert_eq!(lit.distance[k].to_bits(), distance.to_bits());
                let [u1, u2] = samples[k];
                let bounce = Frame::new(hit.normal).to_world(sample_cosine_hemisphere(u1, u2));
                assert_eq!(bits(vector(&direction, k)), bits(bounce));
                assert_eq!(bits(vector(&origin, k)), bits(hit.spawn(bounce).origin));
            }
        }
    }

    #[test]
    fn the_portable_lanes_shade_as_the_course_to_the_last_bit() {
        agrees_with_the_course(FourLanes::Portable);
    }

    #[test]
    fn the_fastest_lanes_shade_as_the_course_to_the_last_bit() {
        agrees_with_the_course(FourLanes::fastest());
    }

    #[test]
    fn origins_in_the_rare_cases_are_the_courses() {
        let scene = scene();
        let (rays, nearest) = fours(&scene)[0];
        let mut hits = course_hits(&scene, &rays, nearest);
        hits[1].point.x = 0.0;
        hits[2].offset.y = 0.0;
        hits[3].offset.z = Real::NAN;
        for lanes in [FourLanes::Portable, FourLanes::fastest()] {
            let four = [&hits[0], &hits[1], &hits[2], &hits[3]];
            let (origin, direction) = lanes.bounces(four, [[0.6, 0.8, 0.3]; 4]);
            for (k, hit) in hits.iter().enumerate() {
                let course = hit.spawn(vector(&direction, k)).origin;
                assert_eq!(bits(vector(&origin, k)), bits(course));
            }
        }
    }

    /// The light samples of a sphere light, from session 4.
    mod light_samples {
        use super::*;
        use crate::integrator::Tracer;
        use crate::lights::SphereLight;
        use crate::maths::uniform_pair;

        /// Asserts that `lanes` draw the course's light samples towards a sphere light
        /// to the last bit, rays and their absence included, from points inside the
        /// light too.
        fn sample_the_light_as_the_course(lanes: FourLanes) {
            let scene = scene();
            // Around the second ball, so that the rays from its surface start inside.
            let light = SphereLight::new(Vec3::new(20.0, -5.0, 3.0), 35.0, 2e10, 0);
            let mut tracer = Tracer::new(&scene);
            let (mut kept, mut rays, mut inside) = (0, 0, 0);
            for (rays_of_four, nearest) in fours(&scene) {
                let hits = course_hits(&scene, &rays_of_four, nearest);
                let albedo = [Vec3::new(1.0, 0.5, 0.25); 4];
                let mut samples = [[0.0; 3]; 4];
                let mut expected = Vec::new();
                for (hit, sample) in hits.iter().zip(&mut samples) {
                    let (u1, u2) = uniform_pair(&mut tracer.rng.clone());
                    let phi = 2.0 * PI * u2;
                    *sample = [u1, phi.cos(), phi.sin()];
                    expected.push(tracer.light_sample(&light, hit, albedo[0]));
                    inside += usize::from(light.cone(hit.point).is_none());
                }
                let shape = (light.centre, light.radius, light.emission);
                let four = [&hits[0], &hits[1], &hits[2], &hits[3]];
                let found = lanes.sphere_light(four, albedo, samples, shape);
                for (k, expected) in expected.iter().enumerate() {
                    let ray = (found.kept[k].to_bits() != 0).then(|| {
                        let (origin, direction) =
                            (vector(&found.origin, k), vector(&found.direction, k));
                        [bits(origin), bits(direction), bits(vector(&found.lit, k))]
                    });
                    let expected = expected
                        .map(|(ray, lit)| [bits(ray.origin), bits(ray.direction), bits(lit)]);
                    assert_eq!(ray, expected);
                    kept += usize::from(ray.is_some());
                }
                rays += 4;
            }
            // Many directions lie below their surfaces, and some points are inside the
            // light: lanes with and without a ray are tested.
            assert!(kept > rays / 4 && kept < rays * 3 / 4, "{kept} of {rays}");
            assert!(inside > 100, "{inside} points inside the light");
        }

        #[test]
        fn both_lanes_sample_the_light_as_the_course_to_the_last_bit() {
            sample_the_light_as_the_course(FourLanes::Portable);
            sample_the_light_as_the_course(FourLanes::fastest());
        }
    }
}
