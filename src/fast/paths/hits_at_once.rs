//! Beyond the course: the work at the hits of the paths followed at once, all at
//! once on the lanes ([`RealSource`]): their records on spheres, their direct light
//! (a point light and its shadow rays, or samples of a sphere light), and their
//! bounces. Each is written once for any lanes in [`shading`], the
//! course's functions step by step, so that every number is theirs to the last bit
//! but the cosines and sines of the angles, taken on the lanes too.

use crate::fast::paths::direct_at_once::{Direct, Towards};
use crate::fast::paths::light_samples_at_once;
use crate::fast::paths::path::{PATHS, Path, Shaded, repeated};
use crate::fast::paths::shading::{self, bounces, point_light, vector};
use crate::fast::paths::sphere_lanes::SphereLanes;
use crate::fast::simd::real_lanes::RealSource;
use crate::geometry::{Hit, Ray};
use crate::lights::{Light, PointLight};
use crate::materials::Material;
use crate::maths::Real;
use crate::scene::Scene;

/// The records of the hits `nearest` (distance and sphere of `scene`) of the
/// `rays`, their normals facing the rays, worked out on the lanes, with their
/// albedos, into `hits`, which stay `None` where a ray meets no sphere (a lane
/// whose ray meets none repeats another lane's sphere).
#[inline(always)]
pub(crate) fn sphere_hits<L: RealSource>(
    lanes: L,
    scene: &Scene,
    spheres: &SphereLanes,
    rays: [&Ray; PATHS],
    nearest: [Option<(Real, usize)>; PATHS],
    hits: &mut [Shaded; PATHS],
) {
    let Some(&Some(any)) = nearest.iter().find(|n| n.is_some()) else {
        return;
    };
    let found = nearest.map(|n| n.unwrap_or(any));
    let (t, object) = (found.map(|n| n.0), found.map(|n| n.1));
    let rows = object.map(|object| spheres.sphere(object));
    let found = shading::sphere_hits(lanes, rays, t, rows);
    for (k, hit) in hits.iter_mut().enumerate() {
        let sphere = &scene.spheres[object[k]];
        let Material::Diffuse { albedo } = sphere.material else {
            unreachable!("paths at once are used only where every object is diffuse")
        };
        *hit = nearest[k].is_some().then_some((
            Hit {
                t: t[k],
                point: vector(&found.point, k),
                normal: vector(&found.normal, k),
                error: vector(&found.error, k),
                offset: vector(&found.offset, k),
                material: sphere.material,
                emission: sphere.emission,
                object: object[k],
                from_outside: found.outside[k].to_bits() != 0,
            },
            albedo,
        ));
    }
}

/// The direct light at the paths' hits (`hits[k]` for `paths[k]`): for all the
/// hits at once on `lanes` where the light is a point light with shadows or
/// (session 4) a sampled sphere light, as [`Direct::at`] does it for one;
/// otherwise by `Direct::at`.
#[inline(always)]
pub(crate) fn light_all<L: RealSource>(lanes: L, paths: &mut [Path], hits: &[Shaded; PATHS]) {
    let scene = paths[0].tracer.scene;
    match scene.light {
        Some(Light::Point(light)) if scene.settings.shadows => {
            point_light_all(lanes, paths, hits, &light);
        }
        Some(Light::Sphere(light)) if scene.settings.light_sampling => {
            light_samples_at_once::sphere_light_all(lanes, paths, hits, &light);
        }
        _ => {
            for (path, hit) in paths.iter_mut().zip(hits) {
                if let Some((hit, albedo)) = hit {
                    let (direct, skipped) = Direct::at(&mut path.tracer, hit, *albedo);
                    (path.direct, path.skipped) = (Some(direct), skipped);
                }
            }
        }
    }
}

/// The light from the point light `light` at the paths' hits, and their shadow
/// rays, on `lanes`: `Direct::at` with a point light and shadows.
#[inline(always)]
fn point_light_all<L: RealSource>(
    lanes: L,
    paths: &mut [Path],
    hits: &[Shaded; PATHS],
    light: &PointLight,
) {
    let Some(shaded) = repeated(hits) else {
        return;
    };
    let lit = point_light(lanes, shaded.map(|s| &s.0), shaded.map(|s| s.1), light);
    for (k, (path, hit)) in paths.iter_mut().zip(hits).enumerate() {
        if hit.is_some() {
            path.tracer.rays += 1;
            let ray = shading::ray(&lit.origin, &lit.direction, k);
            let (lit, towards) = (vector(&lit.lit, k), Towards::Point(lit.distance[k]));
            (path.direct, path.skipped) = (Some(Direct::Shadowed { ray, lit, towards }), None);
        }
    }
}

// ANCHOR: bounce_all
/// Takes the paths on from their hits (`hits[k]` for `paths[k]`): keeps what each
/// hit adds, and makes the next rays of those that bounce, all at once on
/// `lanes`, each from its own path's random numbers, the cosines and sines of their
/// angles taken on the lanes too.
#[inline(always)]
pub(crate) fn bounce_all<L: RealSource>(lanes: L, paths: &mut [Path], hits: &[Shaded; PATHS]) {
    let mut samples = [None; PATHS];
    let mut bouncing = [None; PATHS];
    for (k, (path, hit)) in paths.iter_mut().zip(hits).enumerate() {
        if let Some((hit, albedo)) = hit
            && path.go_on(hit, *albedo)
        {
            (samples[k], bouncing[k]) = (Some(path.bounce_sample()), Some(hit));
        }
    }
    let Some(bouncing) = repeated(&bouncing) else {
        return;
    };
    let any = samples.iter().flatten().next().copied().unwrap_or_default();
    let rows = samples.map(|s| s.unwrap_or(any));
    let (cos_phi, sin_phi) = shading::cos_sin(lanes, rows.map(|[phi, _]| phi));
    let u2 = rows.map(|[_, u2]| u2);
    let with_angles = std::array::from_fn(|k| [cos_phi[k], sin_phi[k], u2[k]]);
    let (origin, direction) = bounces(lanes, bouncing.map(|h| *h), with_angles);
    for (k, path) in paths.iter_mut().enumerate() {
        if samples[k].is_some() {
            path.ray = shading::ray(&origin, &direction, k);
        }
    }
}
// ANCHOR_END: bounce_all
