//! Shadow rays: whether anything lies between a point and a light.

use crate::geometry::Ray;
use crate::maths::Real;
use crate::scene::Scene;

impl Scene {
    // ANCHOR: occluded
    /// Whether any object lies on `ray` closer than `distance`: the shadow-ray test.
    /// It finds the nearest object, as [`Scene::intersect`] does, but needs only its
    /// distance ([`Scene::nearest`]).
    pub fn occluded(&self, ray: &Ray, distance: Real) -> bool {
        closer_than(self.nearest(ray), distance)
    }
    // ANCHOR_END: occluded
}

/// Whether the nearest hit of a ray, `nearest` (its distance and object), lies
/// closer than `distance`.
pub fn closer_than(nearest: Option<(Real, usize)>, distance: Real) -> bool {
    nearest.is_some_and(|(t, _)| t < distance)
}
