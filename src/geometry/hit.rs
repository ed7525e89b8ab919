//! What a ray finds: the hit record, and how a new ray leaves it without hitting
//! the same surface again.

use crate::geometry::ray::Ray;
use crate::materials::material::Material;
use crate::maths::numbers::{Colour, Real, Vec3};

/// The nearest intersection of a ray with the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the ray.
    pub t: Real,
    /// The hit point.
    pub point: Vec3,
    /// Unit normal of the surface, pointing out of the object: the geometry's own,
    /// which decides on which side a new ray starts.
    pub normal: Vec3,
    /// Unit normal used for shading: the geometric one, or an interpolated one on
    /// smooth meshes.
    pub shading_normal: Vec3,
    /// A bound on the rounding error of each coordinate of `point`: the true surface
    /// point lies in the box `point ± error`.
    pub error: Vec3,
    /// The material of the surface that was hit.
    pub material: Material,
    /// The radiance the surface emits.
    pub emission: Colour,
    /// Index of the object that was hit in the scene's list.
    pub object: usize,
    /// Whether the ray came from outside the object. Decided by where the ray
    /// started, not by the sign of `direction . normal`, which rounding makes
    /// unreliable for rays that graze the surface.
    pub from_outside: bool,
}

impl Hit {
    // ANCHOR: spawn
    /// A ray leaving the hit point along the unit vector `direction`, its origin pushed off the
    /// surface just far enough to clear the point's rounding error (pbrt-v4,
    /// section 6.8.6): along the normal by `d = |n| . error`, to the side the ray
    /// leaves by, then rounded one more float away. The offset scales with the
    /// scene, so no fixed epsilon can be too small for a large scene or too large
    /// for a small one.
    pub fn spawn(&self, direction: Vec3) -> Ray {
        let d = self.normal.abs().dot(self.error);
        let mut offset = d * self.normal;
        if direction.dot(self.normal) < 0.0 {
            offset = -offset;
        }
        let pushed = self.point + offset;
        let away = |p: Real, o: Real| {
            if o > 0.0 {
                p.next_up()
            } else if o < 0.0 {
                p.next_down()
            } else {
                p
            }
        };
        let origin = Vec3::new(
            away(pushed.x, offset.x),
            away(pushed.y, offset.y),
            away(pushed.z, offset.z),
        );
        Ray { origin, direction }
    }
    // ANCHOR_END: spawn

    /// The hit with its normal turned towards the side the ray came from. A diffuse
    /// surface is lit on whichever side a ray meets it, such as the inside of an
    /// enclosing sphere.
    pub fn facing_the_ray(&self) -> Hit {
        let side = if self.from_outside { 1.0 } else { -1.0 };
        Hit {
            normal: side * self.normal,
            shading_normal: side * self.shading_normal,
            ..*self
        }
    }

    /// A ray from the hit point towards `target`, with the distance to the target
    /// measured from the ray's (offset) origin; used for shadow rays.
    pub fn spawn_towards(&self, target: Vec3) -> (Ray, Real) {
        let ray = self.spawn((target - self.point).normalize());
        (ray, ray.origin.distance(target))
    }
}
