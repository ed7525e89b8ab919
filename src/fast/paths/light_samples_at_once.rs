//! Beyond the course: a sampled sphere light at the hits of the paths followed at
//! once (session 4), all at once on the lanes: `Tracer::light_sample` for their
//! hits, each path drawing its own random numbers first, as
//! [`hits_at_once`](crate::fast::paths::hits_at_once) does for a point light.

use crate::fast::paths::direct_at_once::{Direct, Towards};
use crate::fast::paths::path::{PATHS, Path, Shaded, repeated};
use crate::fast::paths::shading::{self, LightSamples, spawn, to_world, vector};
use crate::fast::simd::real_lanes::{
    RealLanes, RealSource, column, dot, gather3, minus, scale, scatter3, splat3,
};
use crate::geometry::Hit;
use crate::lights::SphereLight;
use crate::maths::{Colour, PI, Real, Vec3, uniform_pair};

/// One direction sampled towards the sphere light `light` from each of the paths'
/// hits, its ray and the light it brings, on `lanes`: `Direct::at` with a sampled
/// sphere light (session 4), each path drawing its own random numbers first.
#[inline(always)]
pub(crate) fn sphere_light_all<L: RealSource>(
    lanes: L,
    paths: &mut [Path],
    hits: &[Shaded; PATHS],
    light: &SphereLight,
) {
    let (mut u1, mut phi) = ([0.0; PATHS], [0.0; PATHS]);
    for (k, (path, hit)) in paths.iter_mut().zip(hits).enumerate() {
        if hit.is_some() {
            let (first, second) = uniform_pair(&mut path.tracer.rng);
            (u1[k], phi[k]) = (first, 2.0 * PI * second);
        }
    }
    let (cos_phi, sin_phi) = shading::cos_sin(lanes, phi);
    let samples = std::array::from_fn(|k| [u1[k], cos_phi[k], sin_phi[k]]);
    let Some(shaded) = repeated(hits) else {
        return;
    };
    let (at, albedo) = (shaded.map(|s| &s.0), shaded.map(|s| s.1));
    let shape = (light.centre, light.radius, light.emission);
    let found = sphere_light(lanes, at, albedo, samples, shape);
    for (k, (path, hit)) in paths.iter_mut().zip(hits).enumerate() {
        if hit.is_none() {
            continue;
        }
        let mut direct = Direct::Known(Colour::ZERO);
        if found.kept[k].to_bits() != 0 {
            path.tracer.rays += 1;
            let ray = shading::ray(&found.origin, &found.direction, k);
            let (lit, towards) = (vector(&found.lit, k), Towards::Body(light.object));
            direct = Direct::Shadowed { ray, lit, towards };
        }
        (path.direct, path.skipped) = (Some(direct), path.tracer.sampled_light());
    }
}

/// `Tracer::light_sample` at [`PATHS`] hits (normals facing their rays) of surfaces of
/// `albedo`, from each hit's `[u1, cos phi, sin phi]`, towards the sphere light of
/// `centre`, `radius` and `emission`, on `lanes`: the cone under which the light is
/// seen (`SphereLight::cone`), its frame, a direction in it (`Cone::sample`), its
/// density, and the ray.
#[inline(always)]
pub fn sphere_light<L: RealSource>(
    lanes: L,
    hits: [&Hit; PATHS],
    albedo: [Colour; PATHS],
    samples: [[Real; 3]; PATHS],
    light: (Vec3, Real, Colour),
) -> LightSamples {
    let (centre, radius, emission) = light;
    let one = lanes.splat(1.0);
    let point = gather3(lanes, hits.map(|h| h.point));
    let to_centre = minus(splat3(lanes, centre), point);
    let r2 = dot(to_centre, to_centre);
    let sin2 = lanes.splat(radius * radius) / r2;
    let outside = sin2.lt(one);
    let cos_max = (one - sin2).sqrt();
    let one_minus_cos_max = sin2 / (one + cos_max);
    let inverse = one / r2.sqrt();
    let axis = scale(inverse, to_centre);
    let u1 = column(lanes, samples, 0);
    let cos_phi = column(lanes, samples, 1);
    let sin_phi = column(lanes, samples, 2);
    let one_minus_cos = u1 * one_minus_cos_max;
    let squared = one_minus_cos * (lanes.splat(2.0) - one_minus_cos);
    let sin_theta = squared.max(lanes.splat(0.0)).sqrt();
    let local = [
        cos_phi * sin_theta,
        sin_phi * sin_theta,
        one - one_minus_cos,
    ];
    let direction = to_world(lanes, axis, local);
    let inside_cone = local[2].ge(cos_max);
    let pdf = inside_cone & (one / (lanes.splat(2.0 * PI) * one_minus_cos_max));
    let normal = gather3(lanes, hits.map(|h| h.normal));
    let cos = dot(direction, normal);
    let kept = outside & cos.gt(lanes.splat(0.0));
    let pi = lanes.splat(PI);
    let ([ax, ay, az], [ex, ey, ez]) = (gather3(lanes, albedo), splat3(lanes, emission));
    let lit = [
        ex * ax / pi * cos / pdf,
        ey * ay / pi * cos / pdf,
        ez * az / pi * cos / pdf,
    ];
    let offset = gather3(lanes, hits.map(|h| h.offset));
    LightSamples {
        lit: scatter3(lit),
        origin: spawn(lanes, point, offset, direction),
        direction: scatter3(direction),
        kept: kept.to_array(),
    }
}
