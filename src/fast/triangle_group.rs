//! Four triangles tested at once, in single precision, to set aside the ones a ray
//! certainly misses: the watertight test's edge functions ([`ShearedRay`]) on the
//! four lanes of a SIMD register, with a margin that covers every rounding error.
//! Only the triangles that survive go to the exact test, so the answer is the exact
//! test's; most of a leaf's triangles never reach it.

use glam::Vec4;

use crate::geometry::ShearedRay;
use crate::maths::{Vec3, to_single};

/// Triangles per group: one per lane of a 128-bit SIMD register.
pub const GROUP: usize = 4;

/// The unit roundoff of single precision, `2^-24`.
const UNIT_ROUNDOFF: f32 = f32::EPSILON / 2.0;

/// Four triangles, structure of arrays: `corners[v][axis]` holds coordinate `axis`
/// of corner `v` of the four triangles, lane `i` for triangle `i`, each rounded to
/// the nearest float. Lanes past the last triangle repeat it and are never reported.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleGroup {
    corners: [[Vec4; 3]; 3],
    /// Per lane, the largest magnitude of any of the triangle's coordinates.
    reach: Vec4,
}

/// A ray in the watertight test's frame, in single precision, each value splatted
/// over four lanes.
pub struct GroupRay {
    /// The origin, rounded to the nearest floats.
    origin: [Vec4; 3],
    /// The axes that become `x`, `y` and `z` in the ray's frame.
    axes: [usize; 3],
    /// The shear factors `s_x`, `s_y`, within `[-1, 1]`.
    shear: [Vec4; 2],
    /// The largest magnitude of the origin's coordinates.
    reach: Vec4,
    /// The sign of the scale `s_z` (the direction's `z` in the ray's frame).
    toward: Vec4,
}

impl GroupRay {
    /// The single-precision copy of `sheared`.
    pub fn new(sheared: &ShearedRay) -> GroupRay {
        let o = sheared.origin;
        let (x, y, z) = (to_single(o.x), to_single(o.y), to_single(o.z));
        GroupRay {
            origin: [Vec4::splat(x), Vec4::splat(y), Vec4::splat(z)],
            axes: sheared.axes,
            shear: [
                Vec4::splat(to_single(sheared.shear.x)),
                Vec4::splat(to_single(sheared.shear.y)),
            ],
            reach: Vec4::splat(x.abs().max(y.abs()).max(z.abs())),
            toward: Vec4::splat(to_single(sheared.shear.z).signum()),
        }
    }
}

impl TriangleGroup {
    /// The group of `triangles` (one to four).
    pub fn new(triangles: &[[Vec3; 3]]) -> TriangleGroup {
        let lane = |i: usize| triangles[i.min(triangles.len() - 1)];
        let coordinate = |v: usize, axis: usize| {
            Vec4::from_array([0, 1, 2, 3].map(|i| to_single(lane(i)[v][axis])))
        };
        let corners = [0, 1, 2].map(|v| [0, 1, 2].map(|axis| coordinate(v, axis)));
        let reach = corners
            .iter()
            .flatten()
            .fold(Vec4::ZERO, |reach, c| reach.max(c.abs()));
        TriangleGroup { corners, reach }
    }

    // ANCHOR: group_test
    /// The lanes (bit `i` for triangle `i`) that `ray` may meet: all but those it
    /// certainly passes beside or meets behind its origin. In the ray's frame the
    /// corners are `x = q_kx + s_x q_kz`, `y = q_ky + s_y q_kz`, `z = q_kz` with
    /// `q = p - o`, and the edge functions are `e = p_x q_y - p_y q_x` as in
    /// [`ShearedRay::intersect`]. With `u` the unit roundoff and `g` the reach of the
    /// corners plus the origin's, each computed coordinate is within `c = 20 u g` of
    /// its exact value (rounding of the corners and origin, the difference, the
    /// shear, the product and the sum), so an edge function is within
    /// `d_e = c S + 2 c^2 + u S^2 / 2`, `S` the sum of the corners' `|x| + |y|`; the
    /// determinant `e_0 + e_1 + e_2` within `3 d_e + 2 u sum |e|`, and
    /// `T = e_0 a_z + e_1 b_z + e_2 c_z`, whose sign times that of `s_z` and of the
    /// determinant is the sign of `t`, within
    /// `c sum |e| + d_e sum |z| + 3 d_e c + 3 u sum |e z|`. A lane is set aside only
    /// when one edge function is below minus twice its bound and another above it,
    /// or when the determinant's sign is certain and `t`'s is certainly negative, by
    /// twice the bounds: the exact values are then beyond any error of a double- or
    /// single-precision evaluation of the exact test, which would miss too.
    #[inline]
    pub fn candidates(&self, ray: &GroupRay) -> u32 {
        let [kx, ky, kz] = ray.axes;
        let sheared = |p: &[Vec4; 3]| {
            let q = |axis: usize| p[axis] - ray.origin[axis];
            let z = q(kz);
            (q(kx) + ray.shear[0] * z, q(ky) + ray.shear[1] * z, z)
        };
        let (a, b, c) = (
            sheared(&self.corners[0]),
            sheared(&self.corners[1]),
            sheared(&self.corners[2]),
        );
        let edge = |p: (Vec4, Vec4, Vec4), q: (Vec4, Vec4, Vec4)| p.0 * q.1 - p.1 * q.0;
        let edges = [edge(b, c), edge(c, a), edge(a, b)];
        let size = [a, b, c]
            .iter()
            .fold(Vec4::ZERO, |s, p| s + p.0.abs() + p.1.abs());
        let coordinate_error = (self.reach + ray.reach) * (20.0 * UNIT_ROUNDOFF);
        let edge_error = size * coordinate_error
            + coordinate_error * coordinate_error * 2.0
            + size * size * (0.5 * UNIT_ROUNDOFF);
        let margin = edge_error * 2.0;
        let below = |e: Vec4| e.cmplt(-margin);
        let above = |e: Vec4| e.cmpgt(margin);
        let beside = (below(edges[0]) | below(edges[1]) | below(edges[2]))
            & (above(edges[0]) | above(edges[1]) | above(edges[2]));

        let abs_edges = edges[0].abs() + edges[1].abs() + edges[2].abs();
        let determinant = edges[0] + edges[1] + edges[2];
        let determinant_margin = (edge_error * 3.0 + abs_edges * (2.0 * UNIT_ROUNDOFF)) * 2.0;
        let t_numerator = (edges[0] * a.2 + edges[1] * b.2 + edges[2] * c.2) * ray.toward;
        let abs_z = a.2.abs() + b.2.abs() + c.2.abs();
        let abs_products = (edges[0] * a.2).abs() + (edges[1] * b.2).abs() + (edges[2] * c.2).abs();
        let t_margin = (abs_edges * coordinate_error
            + abs_z * edge_error
            + edge_error * coordinate_error * 3.0
            + abs_products * (3.0 * UNIT_ROUNDOFF))
            * 2.0;
        let behind = (determinant.cmpgt(determinant_margin) & t_numerator.cmplt(-t_margin))
            | (determinant.cmplt(-determinant_margin) & t_numerator.cmpgt(t_margin));
        !(beside | behind).bitmask() & 0b1111
    }
    // ANCHOR_END: group_test
}

/// The lanes of a group holding `count` triangles from its first lane on.
pub fn lanes(count: usize) -> u32 {
    (1 << count.min(GROUP)) - 1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Ray;
    use crate::maths::{PixelRng, Real, pixel_rng, uniform};

    /// A random point of the cube `[-r, r]^3`.
    fn point(rng: &mut PixelRng, r: Real) -> Vec3 {
        Vec3::new(uniform(rng), uniform(rng), uniform(rng)) * (2.0 * r) - Vec3::splat(r)
    }

    /// Four random triangles of size about `size` around points of the cube
    /// `[-r, r]^3`.
    fn group(rng: &mut PixelRng, r: Real, size: Real) -> Vec<[Vec3; 3]> {
        (0..4)
            .map(|_| {
                let centre = point(rng, r);
                [0, 1, 2].map(|_| centre + point(rng, size))
            })
            .collect()
    }

    /// Checks that every triangle `ray` hits is kept, and returns the lanes kept.
    fn kept_lanes(triangles: &[[Vec3; 3]], ray: &Ray) -> u32 {
        let sheared = ShearedRay::new(ray);
        let kept = TriangleGroup::new(triangles).candidates(&GroupRay::new(&sheared));
        for (lane, [a, b, c]) in triangles.iter().enumerate() {
            let hit = sheared.intersect(*a, *b, *c, Real::INFINITY).is_some();
            assert!(kept & (1 << lane) != 0 || !hit, "{ray:?} hits lane {lane}");
        }
        kept
    }

    #[test]
    fn no_triangle_the_exact_test_hits_is_set_aside() {
        let mut rng = pixel_rng(7, 0);
        for scale in [1.0, 1e4] {
            let mut set_aside = 0;
            for _ in 0..20_000 {
                let triangles = group(&mut rng, scale, 0.05);
                // Aim at a corner or an edge's middle, where rounding decides.
                let [a, b, _] = triangles[0];
                let target = if uniform(&mut rng) < 0.5 {
                    a
                } else {
                    (a + b) * 0.5
                };
                let origin = target + point(&mut rng, 2.0);
                let ray = Ray::new(origin, (target - origin).normalize());
                set_aside += (!kept_lanes(&triangles, &ray) & 0b1111).count_ones();
            }
            // Near the origin the other three triangles are nearly always set aside;
            // far from it, single precision cannot tell, and most are kept.
            if scale == 1.0 {
                assert!(set_aside > 55_000, "only {set_aside} of 80,000 set aside");
            }
        }
    }

    #[test]
    fn a_triangle_left_behind_is_set_aside() {
        let mut rng = pixel_rng(8, 0);
        for height in [1e-9, 1e-6, 1e-4] {
            let (mut leaving, mut set_aside) = (0, 0);
            for _ in 0..20_000 {
                let triangles = group(&mut rng, 1.0, 0.05);
                let [a, b, c] = triangles[0];
                let normal = (b - a).cross(c - a).normalize();
                let start = (a + b + c) / 3.0 + normal * height;
                let direction = point(&mut rng, 1.0).normalize();
                let kept = kept_lanes(&triangles, &Ray::new(start, direction));
                if direction.dot(normal) > 0.1 {
                    leaving += 1;
                    set_aside += u32::from(kept & 1 == 0);
                }
            }
            // A ray leaving the surface from 1e-4 above it (the ray sets' offset is
            // 2e-4) does not need the exact test for the triangle it leaves.
            if height == 1e-4 {
                assert!(set_aside * 10 > leaving * 9, "{set_aside} of {leaving}");
            }
        }
    }

    #[test]
    fn padding_lanes_are_masked_off() {
        assert_eq!(lanes(1), 0b1);
        assert_eq!(lanes(3), 0b111);
        assert_eq!(lanes(9), 0b1111);
    }
}
