//! The probe's account of a sphere light (session 4): the ray drawn towards it and
//! the first object it meets.

use crate::geometry::Hit;
use crate::inspect::path::ShadowRay;
use crate::integrator::tracer::Traced;
use crate::lights::SphereLight;
use crate::maths::Colour;

/// The ray drawn towards `light` from the diffuse hit `facing`, when the scene
/// samples the light: the course's `light_sample`, run again from a copy of the
/// tracer as it was, and what it meets first if that is not the light.
pub fn shadow_ray(
    traced: &Traced,
    facing: &Hit,
    albedo: Colour,
    light: &SphereLight,
) -> Option<ShadowRay> {
    if !traced.before.scene.settings.light_sampling {
        return None;
    }
    let (ray, _) = traced.before.clone().light_sample(light, facing, albedo)?;
    let nearest = traced.before.scene.nearest(&ray);
    let distance = nearest.filter(|n| n.1 == light.object).map(|n| n.0);
    Some(ShadowRay::new(
        &ray,
        distance,
        nearest.filter(|n| n.1 != light.object),
    ))
}
