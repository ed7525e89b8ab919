//! Shadow rays.

use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::lights::PointLight;
use crate::maths::Real;

impl Tracer<'_> {
    // ANCHOR: in_shadow
    /// Whether an object lies between the hit point and the point light: the shadow
    /// ray towards the light meets something before it.
    pub fn in_shadow(&mut self, hit: &Hit, light: &PointLight) -> bool {
        let (shadow_ray, distance) = self.shadow_ray(hit, light);
        self.scene.occluded(&shadow_ray, distance)
    }

    /// The shadow ray from the hit point (pushed off its surface, see [`Hit::spawn`],
    /// or by the scene's fixed `epsilon` along the normal) towards the point light,
    /// counted as one ray, and the distance to the light.
    pub fn shadow_ray(&mut self, hit: &Hit, light: &PointLight) -> (Ray, Real) {
        self.rays += 1;
        let Some(epsilon) = self.scene.settings.shadow_offset else {
            return hit.spawn_towards(light.position);
        };
        let direction = (light.position - hit.point).normalize();
        let ray = hit.spawn_with_epsilon(direction, epsilon);
        (ray, ray.origin.distance(light.position))
    }
    // ANCHOR_END: in_shadow
}
