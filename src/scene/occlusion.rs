//! Shadow rays: whether anything lies between a point and a light.

use crate::geometry::Ray;
use crate::maths::Real;
use crate::scene::Scene;

impl Scene {
    // ANCHOR: occluded
    /// Whether any object lies on `ray` closer than `distance`: the shadow-ray test.
    pub fn occluded(&self, ray: &Ray, distance: Real) -> bool {
        self.intersect(ray).is_some_and(|hit| hit.t < distance)
    }
    // ANCHOR_END: occluded
}
