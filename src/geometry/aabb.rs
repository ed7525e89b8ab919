//! Axis-aligned bounding boxes and the slab test.

use crate::geometry::{Ray, cost};
use crate::maths::{Real, Vec3, error_bound};

/// The box `[min, max]`: the smallest axis-aligned box around some geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lowest corner.
    pub min: Vec3,
    /// Highest corner.
    pub max: Vec3,
}

impl Aabb {
    /// The empty box, which grows to fit whatever is added to it.
    pub const EMPTY: Aabb = Aabb {
        min: Vec3::splat(Real::INFINITY),
        max: Vec3::splat(Real::NEG_INFINITY),
    };

    /// The smallest box containing this box and `p`.
    pub fn grow(self, p: Vec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The smallest box containing this box and `other`.
    pub fn union(self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Half the surface area of the box, `dx dy + dy dz + dz dx`: the chance that a
    /// random ray meeting a parent box also meets this one is the ratio of their
    /// areas (the factor 2 cancels). Zero for the empty box.
    pub fn half_area(&self) -> Real {
        let d = (self.max - self.min).max(Vec3::ZERO);
        d.x * d.y + d.y * d.z + d.z * d.x
    }

    /// The centre of the box.
    pub fn centre(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }

    /// Index (0, 1, 2 for x, y, z) of the box's longest side.
    pub fn longest_axis(&self) -> usize {
        let size = self.max - self.min;
        if size.x >= size.y && size.x >= size.z {
            0
        } else if size.y >= size.z {
            1
        } else {
            2
        }
    }

    // ANCHOR: slab
    /// The distance at which `ray` enters the box, if it meets it before `t_max`.
    ///
    /// The slab test: between the two planes `x = min.x` and `x = max.x` the ray
    /// spends `t` in `[(min.x - o.x) / d.x, (max.x - o.x) / d.x]`, the planes taken in
    /// the other order when `d.x` is negative; it is inside the box where the three
    /// intervals overlap. `inv_direction` holds `1 / d` per axis, computed once per
    /// ray. The order of the planes is chosen by the sign of `1 / d`, not by
    /// comparing the two distances: a zero component gives infinities whose signs
    /// follow the zero's (`1 / -0 = -inf`), and when the origin also lies on one of
    /// the planes, `0 * inf` is NaN. The comparisons below, false for NaN, then leave
    /// the interval unconstrained on that axis, as they should for a ray lying in the
    /// face. The exit distance is widened by `1 + 2 delta_3` (pbrt-v4) so that
    /// rounding never misses a box that a triangle hit inside it proves the ray
    /// reaches.
    ///
    /// Exercise s5.2, the slab test: book session 5, "The bounding box".
    #[inline]
    pub fn entry(&self, ray: &Ray, inv_direction: Vec3, t_max: Real) -> Option<Real> {
        cost::count_box();
        let (mut near, mut far) = (0.0, t_max);
        for axis in 0..3 {
            let inv = inv_direction[axis];
            let (first, second) = if inv.is_sign_negative() {
                (self.max[axis], self.min[axis])
            } else {
                (self.min[axis], self.max[axis])
            };
            let enter = (first - ray.origin[axis]) * inv;
            let leave = (second - ray.origin[axis]) * inv * (1.0 + 2.0 * error_bound(3));
            if enter > near {
                near = enter;
            }
            if leave < far {
                far = leave;
            }
            if near > far {
                return None;
            }
        }
        Some(near)
    }
    // ANCHOR_END: slab
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box() -> Aabb {
        Aabb::EMPTY.grow(Vec3::ZERO).grow(Vec3::ONE)
    }

    #[test]
    fn slab_test_distances() {
        let b = unit_box();
        let ray = Ray::new(Vec3::new(0.5, 0.5, -2.0), Vec3::Z);
        let inv = ray.direction.recip();
        assert_eq!(b.entry(&ray, inv, Real::INFINITY), Some(2.0));
        assert_eq!(b.entry(&ray, inv, 1.0), None, "beyond t_max");
        let inside = Ray::new(Vec3::splat(0.5), Vec3::X);
        assert_eq!(b.entry(&inside, inside.direction.recip(), 10.0), Some(0.0));
        let away = Ray::new(Vec3::new(0.5, 0.5, -2.0), -Vec3::Z);
        assert_eq!(b.entry(&away, away.direction.recip(), 10.0), None);
    }

    #[test]
    fn rays_parallel_to_a_slab_give_no_nan() {
        let b = unit_box();
        // Direction with zero components: 1/0 = inf, and (0 - 0) * inf = NaN on the
        // plane x = 0 itself.
        let on_plane = Ray::new(Vec3::new(0.0, 0.5, -1.0), Vec3::Z);
        assert_eq!(
            b.entry(&on_plane, on_plane.direction.recip(), 10.0),
            Some(1.0)
        );
        let outside = Ray::new(Vec3::new(-0.1, 0.5, -1.0), Vec3::Z);
        assert_eq!(b.entry(&outside, outside.direction.recip(), 10.0), None);
    }

    #[test]
    fn longest_axis_and_centre() {
        let b = Aabb::EMPTY.grow(Vec3::ZERO).grow(Vec3::new(1.0, 3.0, 2.0));
        assert_eq!(b.longest_axis(), 1);
        assert_eq!(b.centre(), Vec3::new(0.5, 1.5, 1.0));
    }
}
