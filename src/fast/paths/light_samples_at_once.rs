//! Beyond the course: a sampled sphere light at the hits of the paths followed at
//! once (session 4), four at a time on the lanes: `Tracer::light_sample` for four
//! hits, each path drawing its own random numbers first, as
//! [`hits_at_once`](crate::fast::paths::hits_at_once) does for a point light.

use crate::fast::paths::direct_at_once::{Direct, Towards};
use crate::fast::paths::path::{PATHS, Path, Shaded};
use crate::fast::paths::shading::{self, vector};
use crate::fast::simd::four_lanes::{FourLanes, repeated};
use crate::lights::SphereLight;
use crate::maths::{Colour, PI, uniform_pair};

/// One direction sampled towards the sphere light `light` from each of the paths'
/// hits, its ray and the light it brings, on `lanes`: `Direct::at` with a sampled
/// sphere light (session 4), each path drawing its own random numbers first.
pub(crate) fn sphere_light_all(
    lanes: FourLanes,
    paths: &mut [Path],
    hits: &[Shaded; PATHS],
    light: &SphereLight,
) {
    let mut samples = [[0.0; 3]; PATHS];
    for ((path, hit), sample) in paths.iter_mut().zip(hits).zip(&mut samples) {
        if hit.is_some() {
            let (u1, u2) = uniform_pair(&mut path.tracer.rng);
            let phi = 2.0 * PI * u2;
            *sample = [u1, phi.cos(), phi.sin()];
        }
    }
    let Some([h0, h1, h2, h3]) = repeated(hits) else {
        return;
    };
    let (four, albedo) = ([&h0.0, &h1.0, &h2.0, &h3.0], [h0.1, h1.1, h2.1, h3.1]);
    let shape = (light.centre, light.radius, light.emission);
    let found = lanes.sphere_light(four, albedo, samples, shape);
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
