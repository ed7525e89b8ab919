//! A group of four spheres, stored by coordinate, and the ray-sphere test on all four
//! at once.

use crate::geometry::Ray;
use crate::maths::Real;

/// Four [`Real`] numbers worked on by one instruction (SIMD) where the processor has
/// one, by the `wide` crate.
#[cfg(not(feature = "f32"))]
pub type RealLanes = wide::f64x4;
/// Four [`Real`] numbers worked on by one instruction (SIMD) where the processor has
/// one, by the `wide` crate.
#[cfg(feature = "f32")]
pub type RealLanes = wide::f32x4;

/// Spheres tested together: the width of a group.
pub const LANES: usize = 4;

/// The centres (`x`, `y`, `z`) and radii of up to four spheres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Group {
    /// The centres' x coordinates.
    pub x: [Real; LANES],
    /// The centres' y coordinates.
    pub y: [Real; LANES],
    /// The centres' z coordinates.
    pub z: [Real; LANES],
    /// The radii.
    pub radius: [Real; LANES],
}

impl Group {
    /// For each sphere of the group, the smallest `t > 0` at which `ray` meets it,
    /// or infinity: [`Sphere::intersect`](crate::geometry::Sphere::intersect) on four spheres at once ([`meet`] with
    /// the ray's coordinates copied into every lane).
    pub fn intersect(&self, ray: &Ray) -> [Real; LANES] {
        let splat = |v: crate::maths::Vec3| v.to_array().map(RealLanes::splat);
        let centre = [self.x, self.y, self.z].map(RealLanes::from);
        meet(
            splat(ray.origin),
            splat(ray.direction),
            centre,
            RealLanes::from(self.radius),
        )
        .to_array()
    }
}

// ANCHOR: group_intersect
/// For each of four lanes, the smallest `t > 0` at which the ray from `origin` along
/// the unit vector `direction` meets the sphere of `centre` and `radius`, or
/// infinity: [`Sphere::intersect`](crate::geometry::Sphere::intersect) on four pairs at once, in portable SIMD
/// (the `wide` crate: two instructions of two numbers on any x86-64). A group of
/// spheres puts one sphere in each lane and the same ray in all four; four paths
/// followed at once put one ray in each lane and the same sphere in all four. Every
/// lane computes every step, whether or not its sphere is missed early (a negative
/// discriminant gives a NaN root, a zero `mu` an infinite root); the misses are
/// picked out at the end.
#[inline(always)]
pub fn meet(
    origin: [RealLanes; 3],
    direction: [RealLanes; 3],
    centre: [RealLanes; 3],
    radius: RealLanes,
) -> RealLanes {
    let [dx, dy, dz] = direction;
    let zero = RealLanes::ZERO;
    let sx = origin[0] - centre[0];
    let sy = origin[1] - centre[1];
    let sz = origin[2] - centre[2];
    let sd = sx * dx + sy * dy + sz * dz;
    let r2 = radius * radius;
    let c = (sx * sx + sy * sy + sz * sz) - r2;
    let (mx, my, mz) = (sx - sd * dx, sy - sd * dy, sz - sd * dz);
    let discriminant = r2 - (mx * mx + my * my + mz * mz);
    let root = discriminant.sqrt() | (sd & RealLanes::splat(-0.0));
    let mu = -(sd + root);
    let t0 = c / mu;
    let before = t0.simd_lt(mu);
    let near = before.select(t0, mu);
    let far = before.select(mu, t0);
    let t = near.simd_gt(zero).select(near, far);
    let away = c.simd_gt(zero) & sd.simd_gt(zero);
    let hit = !away & discriminant.simd_ge(zero) & mu.simd_ne(zero) & far.simd_gt(zero);
    hit.select(t, RealLanes::splat(Real::INFINITY))
}
// ANCHOR_END: group_intersect

/// The nearest of the distances that `intersect` finds in each of `groups` along
/// `ray`, and its sphere's index; the first sphere wins a tie.
#[inline(always)]
pub fn nearest_with(
    groups: &[Group],
    ray: &Ray,
    intersect: impl Fn(&Group, &Ray) -> [Real; LANES],
) -> Option<(Real, usize)> {
    let mut nearest: Option<(Real, usize)> = None;
    for (g, group) in groups.iter().enumerate() {
        let t = intersect(group, ray);
        let best = t
            .into_iter()
            .fold(Real::INFINITY, |a, b| if b < a { b } else { a });
        if best < nearest.map_or(Real::INFINITY, |n| n.0) {
            let k = t.iter().position(|&t| t == best).unwrap_or(0);
            nearest = Some((best, g * LANES + k));
        }
    }
    nearest
}
