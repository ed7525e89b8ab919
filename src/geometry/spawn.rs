//! New rays from a hit point: shadow rays, reflected, refracted and bounced rays.

use crate::geometry::{Hit, Ray};
use crate::maths::{Real, Vec3};

impl Hit {
    // ANCHOR: spawn
    /// A ray leaving the hit point along the unit vector `direction`, its origin
    /// pushed off the surface to the side the ray leaves by, just far enough to
    /// clear the point's rounding error (and on a triangle, the triangle test's:
    /// [`Hit::offset`]), then rounded one more
    /// float away. The course pushes it by a fixed `epsilon` along the normal (see
    /// [`Hit::spawn_with_epsilon`]); an offset that follows the point's own error
    /// is never too small for a large scene nor too large for a small one.
    ///
    /// Exercise s2.2, the offset origin of a new ray: book session 2, "Shadows".
    pub fn spawn(&self, direction: Vec3) -> Ray {
        let offset = if direction.dot(self.offset) < 0.0 {
            -self.offset
        } else {
            self.offset
        };
        let pushed = self.point + offset;
        let origin = Vec3::new(
            one_ulp_towards(pushed.x, offset.x),
            one_ulp_towards(pushed.y, offset.y),
            one_ulp_towards(pushed.z, offset.z),
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

    // ANCHOR: spawn_towards
    /// A ray from the hit point towards `target`, with the distance to the target
    /// measured from the ray's (offset) origin; used for shadow rays.
    ///
    /// Exercise s2.3, the shadow ray towards the light: book session 2, "Shadows".
    pub fn spawn_towards(&self, target: Vec3) -> (Ray, Real) {
        let ray = self.spawn((target - self.point).normalize());
        (ray, ray.origin.distance(target))
    }
    // ANCHOR_END: spawn_towards
}

// ANCHOR: one_ulp_towards
/// `p` moved to the next float in the direction of `o`'s sign: `p.next_up()` where
/// `o > 0`, `p.next_down()` where `o < 0`, `p` itself where `o` is zero (or NaN).
///
/// It gives the same numbers as those three cases without choosing among them by
/// the signs, which are as good as random from one ray to the next: a processor
/// guesses the way of each branch before it knows it, and a wrong guess costs more
/// than the whole step. A finite float other than zero is one integer step away from
/// its neighbours: its bits plus one lie further from zero, minus one nearer. Only a
/// `p` that is zero, infinite or NaN, or an `o` that is zero or NaN, takes the three
/// cases.
pub fn one_ulp_towards(p: Real, o: Real) -> Real {
    let rare = p == 0.0 || !p.is_finite() || o == 0.0 || o.is_nan();
    if rare {
        return if o > 0.0 {
            p.next_up()
        } else if o < 0.0 {
            p.next_down()
        } else {
            p
        };
    }
    let outwards = (o > 0.0) == (p > 0.0);
    let bits = p.to_bits();
    Real::from_bits(if outwards { bits + 1 } else { bits - 1 })
}
// ANCHOR_END: one_ulp_towards

#[cfg(test)]
mod tests {
    use crate::geometry::{Ray, Sphere};
    use crate::maths::{Real, Vec3};

    #[test]
    fn spawned_rays_never_hit_their_own_sphere() {
        // Rays leaving a convex sphere outwards must miss it; rays entering it must
        // find the far side, not the point they left.
        let s = Sphere::white(Vec3::new(0.0, -1000.0, 0.0), 990.0);
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

    #[test]
    fn one_ulp_towards_is_next_up_or_next_down() {
        let expected = |p: Real, o: Real| {
            if o > 0.0 {
                p.next_up()
            } else if o < 0.0 {
                p.next_down()
            } else {
                p
            }
        };
        let specials = [
            0.0,
            -0.0,
            Real::MIN_POSITIVE,
            -Real::MIN_POSITIVE,
            Real::from_bits(1),
            -Real::from_bits(1),
            Real::MAX,
            Real::MIN,
            Real::INFINITY,
            Real::NEG_INFINITY,
            Real::NAN,
            1.0,
            -1.0,
            990.0,
            -60.0,
        ];
        let mut values = specials.to_vec();
        values.extend((0..2000).map(|k| ((k as Real) * 0.618).sin() * 10.0 * (k as Real)));
        for &p in &values {
            for &o in &specials {
                let (got, want) = (super::one_ulp_towards(p, o), expected(p, o));
                assert_eq!(got.to_bits(), want.to_bits(), "p = {p:e}, o = {o:e}");
            }
        }
    }
}
