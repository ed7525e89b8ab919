//! The work at the hits of the paths followed at once, written once for any kind of lanes ([`RealSource`]):
//! their hit records on spheres, their direct light from a point light with its
//! shadow rays, and their cosine-weighted bounces (a sample of a sphere light is in
//! [`light_samples_at_once`](crate::fast::paths::light_samples_at_once)).
//!
//! Every step is the course function's, in its order, so every number is the same
//! to the last bit: [`Sphere::hit_at`], [`Hit::facing_the_ray`],
//! [`PointLight::lambert`], [`Hit::spawn_towards`], `Tracer::light_sample` (session
//! 4), [`sample_cosine_hemisphere`], [`Frame::new`] and [`Frame::to_world`],
//! [`Hit::spawn`], the last float of a new ray's origin included
//! ([`one_ulp_towards`]: its bits plus or minus one, on the lanes, but for its rare
//! cases). One step stays one number at a time, before these functions: the cosine
//! and sine of an angle, the C library's, which has no lane version that rounds as
//! it does. One number may differ in the sign of a zero: a cosine of `-0` in
//! `lambert`'s `.max(0.0)`, which Rust leaves free to give either zero, and which
//! the lanes give as `+0`; the light it scales is zero either way, and the image
//! is the same.
//!
//! [`Sphere::hit_at`]: crate::geometry::Sphere::hit_at
//! [`Hit::facing_the_ray`]: crate::geometry::Hit::facing_the_ray
//! [`PointLight::lambert`]: crate::lights::PointLight::lambert
//! [`Hit::spawn_towards`]: crate::geometry::Hit::spawn_towards
//! [`Hit::spawn`]: crate::geometry::Hit::spawn
//! [`sample_cosine_hemisphere`]: crate::maths::sampling::sample_cosine_hemisphere
//! [`Frame::new`]: crate::maths::frame::Frame::new
//! [`Frame::to_world`]: crate::maths::frame::Frame::to_world
//! [`one_ulp_towards`]: crate::geometry::spawn::one_ulp_towards

use crate::fast::simd::real_lanes::{
    LANES, RealLanes, RealSource, VectorLanes, abs3, column, divide, dot, gather3, minus, plus,
    scale, scatter3, splat3,
};
use crate::geometry::spawn::one_ulp_towards;
use crate::geometry::{Hit, Ray};
use crate::lights::PointLight;
use crate::maths::{Colour, PI, Real, Vec3, error_bound};

/// [`LANES`] vectors by coordinate: `v[axis][k]` is coordinate `axis` of vector `k`.
pub type LaneVectors = [[Real; LANES]; 3];

/// Vector `k` of `v`.
#[inline(always)]
pub fn vector(v: &LaneVectors, k: usize) -> Vec3 {
    Vec3::new(v[0][k], v[1][k], v[2][k])
}

/// Ray `k` of those whose origins are `origin` and directions `direction`.
#[inline(always)]
pub fn ray(origin: &LaneVectors, direction: &LaneVectors, k: usize) -> Ray {
    Ray {
        origin: vector(origin, k),
        direction: vector(direction, k),
    }
}

/// What [`Sphere::hit_at`](crate::geometry::Sphere::hit_at) finds for [`LANES`] rays,
/// their normals already facing the rays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereHits {
    /// The hit points, projected onto their spheres.
    pub point: LaneVectors,
    /// The unit normals, facing the rays.
    pub normal: LaneVectors,
    /// The bounds on the points' rounding errors, per coordinate.
    pub error: LaneVectors,
    /// The offsets that clear the errors, along the outward normals.
    pub offset: LaneVectors,
    /// Per ray, not zero where it started outside its sphere.
    pub outside: [Real; LANES],
}

/// The direct light at four hits from a point light: what
/// [`PointLight::lambert`](crate::lights::PointLight::lambert) and
/// [`Hit::spawn_towards`](crate::geometry::Hit::spawn_towards) give.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLit {
    /// The light that arrives if nothing is in the way.
    pub lit: LaneVectors,
    /// The shadow rays' origins.
    pub origin: LaneVectors,
    /// The shadow rays' directions.
    pub direction: LaneVectors,
    /// The distances from the origins to the light.
    pub distance: [Real; LANES],
}

/// One direction sampled towards a sphere light from each of four hits: what
/// `Tracer::light_sample` gives (from session 4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSamples {
    /// The light each direction brings if nothing is in the way.
    pub lit: LaneVectors,
    /// The rays' origins.
    pub origin: LaneVectors,
    /// The rays' directions.
    pub direction: LaneVectors,
    /// Per hit, not zero where it has a ray: outside the light, the direction above
    /// the surface.
    pub kept: [Real; LANES],
}

// ANCHOR: to_world
/// `Frame::new(n).to_world(local)`: the local coordinates `local` in the frame
/// around the unit vectors `n`.
#[inline(always)]
pub fn to_world<L: RealSource>(
    lanes: L,
    n: VectorLanes<L::Wide>,
    local: VectorLanes<L::Wide>,
) -> VectorLanes<L::Wide> {
    let [nx, ny, nz] = n;
    let one = lanes.splat(1.0);
    let sign = (nz & lanes.splat(-0.0)) | one;
    let a = lanes.splat(-1.0) / (sign + nz);
    let b = nx * ny * a;
    let t1 = [one + sign * nx * nx * a, sign * b, -sign * nx];
    let t2 = [b, sign + ny * ny * a, -ny];
    let [x, y, z] = local;
    plus(plus(scale(x, t1), scale(y, t2)), scale(z, n))
}
// ANCHOR_END: to_world

/// The lanes where `one_ulp_towards(p, o)` takes its usual case: `p` finite and
/// not zero, `o` not zero (a NaN `o` makes `p` NaN, so such a lane is never usual).
#[inline(always)]
fn usual<L: RealSource>(lanes: L, p: L::Wide, o: L::Wide) -> L::Wide {
    let zero = lanes.splat(0.0);
    let finite = p.abs().lt(lanes.splat(Real::INFINITY));
    p.ne(zero) & finite & o.ne(zero)
}

/// The origins of rays leaving [`LANES`] hits (`point`, `offset`) along `direction`:
/// `Hit::spawn` on the lanes, the last float of each coordinate too where every
/// lane takes `one_ulp_towards`'s usual case (nearly always), one number at a time
/// otherwise.
#[inline(always)]
pub fn spawn<L: RealSource>(
    lanes: L,
    point: VectorLanes<L::Wide>,
    offset: VectorLanes<L::Wide>,
    direction: VectorLanes<L::Wide>,
) -> LaneVectors {
    let away = dot(direction, offset).lt(lanes.splat(0.0));
    let [x, y, z] = offset;
    let offset = [away.select(-x, x), away.select(-y, y), away.select(-z, z)];
    let pushed = plus(point, offset);
    let ([px, py, pz], [ox, oy, oz]) = (pushed, offset);
    let usual = usual(lanes, px, ox) & usual(lanes, py, oy) & usual(lanes, pz, oz);
    if usual.all() {
        return scatter3([
            px.step_towards(ox),
            py.step_towards(oy),
            pz.step_towards(oz),
        ]);
    }
    let (mut origin, offset) = (scatter3(pushed), scatter3(offset));
    for (origin, offset) in origin.iter_mut().zip(offset) {
        for (p, o) in origin.iter_mut().zip(offset) {
            *p = one_ulp_towards(*p, o);
        }
    }
    origin
}

/// `Sphere::hit_at` then `Hit::facing_the_ray` for [`LANES`] rays, ray `k` meeting
/// sphere `spheres[k]` (centre and radius first) at `t[k]`, on `lanes`.
#[inline(always)]
pub fn sphere_hits<L: RealSource>(
    lanes: L,
    rays: [&Ray; LANES],
    t: [Real; LANES],
    spheres: [&[Real; 5]; LANES],
) -> SphereHits {
    let origin = gather3(lanes, rays.map(|r| r.origin));
    let direction = gather3(lanes, rays.map(|r| r.direction));
    let rows = spheres.map(|s| *s);
    let centre = [
        column(lanes, rows, 0),
        column(lanes, rows, 1),
        column(lanes, rows, 2),
    ];
    let radius = column(lanes, rows, 3);
    let radial = minus(plus(origin, scale(lanes.gather(t), direction)), centre);
    let length = dot(radial, radial).sqrt();
    let normal = divide(radial, length);
    let on_sphere = scale(radius, normal);
    let point = plus(centre, on_sphere);
    let bound = lanes.splat(error_bound(7));
    let error = scale(bound, plus(abs3(centre), abs3(on_sphere)));
    let offset = scale(dot(abs3(normal), error), normal);
    let from_centre = minus(origin, centre);
    let outside = dot(from_centre, from_centre).gt(radius * radius);
    let facing = scale(outside.select(lanes.splat(1.0), lanes.splat(-1.0)), normal);
    SphereHits {
        point: scatter3(point),
        normal: scatter3(facing),
        error: scatter3(error),
        offset: scatter3(offset),
        outside: outside.to_array(),
    }
}

/// `PointLight::lambert` and `Hit::spawn_towards` (towards the light) at [`LANES`] hits
/// (normals facing their rays) of surfaces of `albedo`, on `lanes`.
#[inline(always)]
pub fn point_light<L: RealSource>(
    lanes: L,
    hits: [&Hit; LANES],
    albedo: [Colour; LANES],
    light: &PointLight,
) -> PointLit {
    let point = gather3(lanes, hits.map(|h| h.point));
    let normal = gather3(lanes, hits.map(|h| h.normal));
    let position = splat3(lanes, light.position);
    let to_light = minus(position, point);
    let d2 = dot(to_light, to_light);
    let length = d2.sqrt();
    let cos = dot(normal, divide(to_light, length)).max(lanes.splat(0.0));
    let power = lanes.splat(light.intensity) / (lanes.splat(4.0 * PI) * d2) * cos;
    let pi = lanes.splat(PI);
    let [ax, ay, az] = gather3(lanes, albedo);
    let lit = [power * ax / pi, power * ay / pi, power * az / pi];
    let direction = scale(lanes.splat(1.0) / length, to_light);
    let offset = gather3(lanes, hits.map(|h| h.offset));
    let origin = spawn(lanes, point, offset, direction);
    let [ox, oy, oz] = origin;
    let to_target = minus(
        [lanes.gather(ox), lanes.gather(oy), lanes.gather(oz)],
        position,
    );
    PointLit {
        lit: scatter3(lit),
        origin,
        direction: scatter3(direction),
        distance: dot(to_target, to_target).sqrt().to_array(),
    }
}

/// The cosines and sines of the angles `phi`, [`LANES`] at once
/// ([`sin_cos`](crate::fast::simd::sin_cos::sin_cos)): within 2 units in the last
/// place of the C library's, which the fast engine's promise allows (the same
/// image, not the same last bits).
#[inline(always)]
pub(crate) fn cos_sin<L: RealSource>(
    lanes: L,
    phi: [Real; LANES],
) -> ([Real; LANES], [Real; LANES]) {
    let (sin, cos) = crate::fast::simd::sin_cos::sin_cos(lanes, lanes.gather(phi));
    (cos.to_array(), sin.to_array())
}

/// The cosine-weighted bounces of [`LANES`] hits (normals facing their rays), on
/// `lanes`: `sample_cosine_hemisphere` from each sample's `[cos phi, sin phi, u2]`,
/// turned into the frame of the normal and spawned from the hit; the rays' origins
/// and directions.
#[inline(always)]
pub fn bounces<L: RealSource>(
    lanes: L,
    hits: [&Hit; LANES],
    samples: [[Real; 3]; LANES],
) -> (LaneVectors, LaneVectors) {
    let cos_phi = column(lanes, samples, 0);
    let sin_phi = column(lanes, samples, 1);
    let u2 = column(lanes, samples, 2);
    let r = (lanes.splat(1.0) - u2).sqrt();
    let local = [cos_phi * r, sin_phi * r, u2.sqrt()];
    let normal = gather3(lanes, hits.map(|h| h.normal));
    let direction = to_world(lanes, normal, local);
    let point = gather3(lanes, hits.map(|h| h.point));
    let offset = gather3(lanes, hits.map(|h| h.offset));
    (spawn(lanes, point, offset, direction), scatter3(direction))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;
    use crate::fast::paths::sphere_lanes::SphereLanes;
    #[cfg(target_arch = "x86_64")]
    use crate::fast::simd::avx::Avx;
    use crate::fast::simd::portable::Portable;
    use crate::geometry::Sphere;
    use crate::materials::Material;
    use crate::maths::frame::Frame;
    use crate::maths::sampling::sample_cosine_hemisphere;
    use crate::maths::{PixelRng, pixel_rng, uniform};

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

    /// One ray per lane and their nearest spheres' distances and indices.
    type Batch = ([Ray; LANES], [(Real, usize); LANES]);

    /// 1,000 batches of rays between random points of the room, one ray per lane,
    /// with their nearest spheres (every ray meets a wall).
    fn batches(scene: &Scene) -> Vec<Batch> {
        let mut rng = pixel_rng(12, 0);
        (0..1000)
            .map(|_| {
                let rays: [Ray; LANES] = std::array::from_fn(|_| {
                    let origin = point(&mut rng);
                    let direction = (point(&mut rng) - origin).normalize();
                    Ray { origin, direction }
                });
                let nearest = rays.map(|ray| scene.nearest_sphere(&ray).expect("a wall"));
                (rays, nearest)
            })
            .collect()
    }

    /// The course's hit records of a batch of rays, facing the rays.
    fn course_hits(
        scene: &Scene,
        rays: &[Ray; LANES],
        nearest: [(Real, usize); LANES],
    ) -> [Hit; LANES] {
        std::array::from_fn(|k| {
            let (t, object) = nearest[k];
            scene.spheres[object]
                .hit_at(&rays[k], t, object)
                .facing_the_ray()
        })
    }

    /// Asserts that `lanes` give every number of the course's hit records, direct
    /// light and bounces to the last bit.
    fn agrees_with_the_course(lanes: impl RealSource) {
        let scene = scene();
        let rows = SphereLanes::new(&scene.spheres);
        let light = PointLight {
            position: Vec3::new(-10.0, 20.0, 40.0),
            intensity: 2e10,
        };
        let mut rng = pixel_rng(13, 0);
        for (rays, nearest) in batches(&scene) {
            let expected = course_hits(&scene, &rays, nearest);
            let found = sphere_hits(
                lanes,
                std::array::from_fn(|k| &rays[k]),
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
            let hits = std::array::from_fn(|k| &expected[k]);
            let albedo = std::array::from_fn(|_| Vec3::new(uniform(&mut rng), 0.5, 1.0));
            let lit = point_light(lanes, hits, albedo, &light);
            let samples: [[Real; 2]; LANES] =
                std::array::from_fn(|_| [uniform(&mut rng), uniform(&mut rng)]);
            let phi = samples.map(|[u1, _]| 2.0 * PI * u1);
            let with_angles = std::array::from_fn(|k| [phi[k].cos(), phi[k].sin(), samples[k][1]]);
            let (origin, direction) = bounces(lanes, hits, with_angles);
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
        agrees_with_the_course(Portable);
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
    fn the_avx_lanes_shade_as_the_course_to_the_last_bit() {
        agrees_with_the_course(Avx::for_test());
    }

    /// Asserts that `lanes` spawn the course's origins where a coordinate of a hit
    /// or of its offset is zero or NaN, the cases `one_ulp_towards` takes one number
    /// at a time.
    fn spawn_as_the_course_in_the_rare_cases(lanes: impl RealSource) {
        let scene = scene();
        let (rays, nearest) = batches(&scene)[0];
        let mut hits = course_hits(&scene, &rays, nearest);
        hits[1].point.x = 0.0;
        hits[2].offset.y = 0.0;
        hits[3].offset.z = Real::NAN;
        let (origin, direction) = bounces(
            lanes,
            std::array::from_fn(|k| &hits[k]),
            [[0.6, 0.8, 0.3]; LANES],
        );
        for (k, hit) in hits.iter().enumerate() {
            let course = hit.spawn(vector(&direction, k)).origin;
            assert_eq!(bits(vector(&origin, k)), bits(course));
        }
    }

    #[test]
    fn origins_in_the_rare_cases_are_the_courses_on_portable_lanes() {
        spawn_as_the_course_in_the_rare_cases(Portable);
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
    fn origins_in_the_rare_cases_are_the_courses_on_avx_lanes() {
        spawn_as_the_course_in_the_rare_cases(Avx::for_test());
    }

    /// The light samples of a sphere light, from session 4.
    mod light_samples {
        use super::*;
        use crate::fast::paths::light_samples_at_once::sphere_light;
        use crate::integrator::Tracer;
        use crate::lights::SphereLight;
        use crate::maths::uniform_pair;

        /// Asserts that `lanes` draw the course's light samples towards a sphere light
        /// to the last bit, rays and their absence included, from points inside the
        /// light too.
        fn sample_the_light_as_the_course(lanes: impl RealSource) {
            let scene = scene();
            // Around the second ball, so that the rays from its surface start inside.
            let light = SphereLight::new(Vec3::new(20.0, -5.0, 3.0), 35.0, 2e10, 0);
            let mut tracer = Tracer::new(&scene);
            let (mut kept, mut rays, mut inside) = (0, 0, 0);
            for (batch, nearest) in batches(&scene) {
                let hits = course_hits(&scene, &batch, nearest);
                let albedo = [Vec3::new(1.0, 0.5, 0.25); LANES];
                let mut samples = [[0.0; 3]; LANES];
                let mut expected = Vec::new();
                for (hit, sample) in hits.iter().zip(&mut samples) {
                    let (u1, u2) = uniform_pair(&mut tracer.rng.clone());
                    let phi = 2.0 * PI * u2;
                    *sample = [u1, phi.cos(), phi.sin()];
                    expected.push(tracer.light_sample(&light, hit, albedo[0]));
                    inside += usize::from(light.cone(hit.point).is_none());
                }
                let shape = (light.centre, light.radius, light.emission);
                let at = std::array::from_fn(|k| &hits[k]);
                let found = sphere_light(lanes, at, albedo, samples, shape);
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
                rays += LANES;
            }
            // Many directions lie below their surfaces, and some points are inside the
            // light: lanes with and without a ray are tested.
            assert!(kept > rays / 4 && kept < rays * 3 / 4, "{kept} of {rays}");
            assert!(inside > 100, "{inside} points inside the light");
        }

        #[test]
        fn the_portable_lanes_sample_the_light_as_the_course_to_the_last_bit() {
            sample_the_light_as_the_course(Portable);
        }

        #[cfg(target_arch = "x86_64")]
        #[test]
        #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
        fn the_avx_lanes_sample_the_light_as_the_course_to_the_last_bit() {
            sample_the_light_as_the_course(Avx::for_test());
        }
    }
}
