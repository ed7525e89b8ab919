//! New rays from a hit point: shadow rays, reflected, refracted and bounced rays.

use crate::geometry::{Hit, Ray};
use crate::maths::{Real, Vec3};

impl Hit {
    // ANCHOR: spawn
    /// A ray leaving the hit point along the unit vector `direction`, its origin
    /// pushed off the surface to the side the ray leaves by, just far enough to
    /// clear the point's rounding error ([`Hit::offset`]), then rounded one more
    /// float away. The course pushes it by a fixed `epsilon` along the normal (see
    /// [`Hit::spawn_with_epsilon`]); an offset that follows the point's own error
    /// is never too small for a large scene nor too large for a small one.
    pub fn spawn(&self, direction: Vec3) -> Ray {
        let offset = if direction.dot(self.offset) < 0.0 {
            -self.offset
        } else {
            self.offset
        };
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

    // ANCHOR: spawn_epsilon
    /// The course's way: a ray along the unit vector `direction` from the hit point
    /// moved by `epsilon` along the normal, to the side the ray leaves by. Without
    /// it, a shadow ray can meet its own surface at `t` of about 0 because the
    /// point was rounded to just below the surface: shadow acne.
    pub fn spawn_with_epsilon(&self, direction: Vec3, epsilon: Real) -> Ray {
        let side = if direction.dot(self.normal) < 0.0 {
            -1.0
        } else {
            1.0
        };
        Ray {
            origin: self.point + side * epsilon * self.normal,
            direction,
        }
    }
    // ANCHOR_END: spawn_epsilon

    /// A ray from the hit point towards `target`, with the distance to the target
    /// measured from the ray's (offset) origin; used for shadow rays.
    pub fn spawn_towards(&self, target: Vec3) -> (Ray, Real) {
        let ray = self.spawn((target - self.point).normalize());
        (ray, ray.origin.distance(target))
    }
}

#[cfg(test)]
mod tests {
    use crate::geometry::{Ray, Sphere};
    use crate::materials::Material;
    use crate::maths::{Colour, Real, Vec3};

    fn sphere(centre: Vec3, radius: Real) -> Sphere {
        Sphere {
            centre,
            radius,
            material: Material::Diffuse {
                albedo: Colour::ONE,
            },
            emission: Colour::ZERO,
        }
    }

    #[test]
    fn spawned_rays_never_hit_their_own_sphere() {
        // Rays leaving a convex sphere outwards must miss it; rays entering it must
        // find the far side, not the point they left.
        let s = sphere(Vec3::new(0.0, -1000.0, 0.0), 990.0);
        let mut self_hits = 0;
        for k in 0..2000 {
            let a = k as Real * 0.37;
            let target = Vec3::new(40.0 * a.cos(), 0.0, 40.0 * a.sin());
            let ray = Ray::new(
                Vec3::new(0.0, 30.0, 20.0),
                target - Vec3::new(0.0, 30.0, 20.0),
            );
            let Some(t) = s.intersect(&ray) else { continue };
            let hit = s.hit_at(&ray, t, 0);
            let reflected = hit.spawn(Vec3::new(a.sin(), 1.0, a.cos()).normalize());
            if s.intersect(&reflected).is_some() {
                self_hits += 1;
            }
            let inward = hit.spawn((-hit.normal + Vec3::new(0.1 * a.cos(), 0.0, 0.1)).normalize());
            if s.intersect(&inward).is_some_and(|t| t < 1.0) {
                self_hits += 1;
            }
        }
        assert_eq!(self_hits, 0);
    }
}
