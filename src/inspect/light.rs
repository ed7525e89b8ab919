//! The probe's account of the light source at a diffuse hit: the shadow ray, what
//! blocks it, and what the light brings, each from the course's own functions.

use crate::geometry::Hit;
use crate::inspect::path::{Direct, ShadowRay};
use crate::integrator::tracer::Traced;
use crate::lights::{Light, PointLight};
use crate::maths::Colour;

/// The light source's part at the diffuse hit `facing` (its normal towards the ray)
/// of albedo `albedo`, reached by `traced`: what the course's `direct_light` brings,
/// run again from a copy of the tracer as it was.
pub fn direct(traced: &Traced, facing: &Hit, albedo: Colour) -> Direct {
    let brings = traced.before.clone().direct_light(facing, albedo);
    let (light, shadow_ray) = match traced.before.scene.light {
        None => ("no light", None),
        Some(Light::Point(light)) => ("point light", point_shadow_ray(traced, facing, &light)),
        #[cfg(feature = "s4")]
        Some(Light::Sphere(light)) => (
            "sphere light",
            crate::inspect::sphere_light::shadow_ray(traced, facing, albedo, &light),
        ),
    };
    Direct {
        light,
        shadow_ray,
        brings: brings.to_array(),
    }
}

/// The shadow ray towards a point light, when the scene traces shadow rays
/// (session 2), and the object in its way.
#[cfg_attr(
    not(feature = "s2"),
    expect(unused_variables, reason = "shadow rays come with session 2")
)]
fn point_shadow_ray(traced: &Traced, facing: &Hit, light: &PointLight) -> Option<ShadowRay> {
    #[cfg(feature = "s2")]
    if traced.before.scene.settings.shadows {
        let (ray, distance) = traced.before.clone().shadow_ray(facing, light);
        let nearest = traced.before.scene.nearest(&ray);
        let in_the_way = crate::scene::occlusion::closer_than(nearest, distance);
        return Some(ShadowRay::new(
            &ray,
            Some(distance),
            nearest.filter(|_| in_the_way),
        ));
    }
    None
}
