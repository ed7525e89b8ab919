//! Shadow rays.

use crate::geometry::Hit;
use crate::integrator::Tracer;
use crate::lights::PointLight;

impl Tracer<'_> {
    // ANCHOR: in_shadow
    /// Whether an object lies between the hit point and the point light: a shadow
    /// ray from the point (pushed off its surface, see [`Hit::spawn`]) towards the
    /// light, counted as one ray.
    pub fn in_shadow(&mut self, hit: &Hit, light: &PointLight) -> bool {
        let (shadow_ray, distance) = hit.spawn_towards(light.position);
        self.rays += 1;
        self.scene.occluded(&shadow_ray, distance)
    }
    // ANCHOR_END: in_shadow
}
