//! Eight triangles tested at once, in single precision, to set aside the ones a ray
//! certainly misses: the watertight test's edge functions ([`ShearedRay`]) on the
//! lanes of a SIMD register, eight in AVX and four at a time on any processor, with a
//! margin that covers every rounding error. Only the triangles that survive go to
//! the exact test, so the answer is the exact test's; most of a leaf's triangles
//! never reach it.

use crate::fast::simd::float_lanes::{FloatLanes, Half, LaneSource};
use crate::geometry::ShearedRay;
use crate::maths::{Vec3, to_single};

/// Triangles per group: one per lane of a 256-bit SIMD register of `f32`.
pub const GROUP: usize = 8;

/// The unit roundoff of single precision, `2^-24`.
const UNIT_ROUNDOFF: f32 = f32::EPSILON / 2.0;

/// Eight triangles, structure of arrays: `corners[v][axis]` holds coordinate `axis`
/// of corner `v` of the eight triangles, lane `i` for triangle `i`, each rounded to
/// the nearest float. Lanes past the last triangle repeat it and are never reported.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(32))]
pub struct TriangleGroup {
    /// The corners, by corner and axis.
    corners: [[[f32; GROUP]; 3]; 3],
    /// Per lane, the largest magnitude of any of the triangle's coordinates.
    reach: [f32; GROUP],
}

/// A ray in the watertight test's frame, in single precision.
pub struct GroupRay {
    /// The origin, rounded to the nearest floats.
    origin: [f32; 3],
    /// The axes that become `x`, `y` and `z` in the ray's frame.
    axes: [usize; 3],
    /// The shear factors `s_x`, `s_y`, within `[-1, 1]`.
    shear: [f32; 2],
    /// The largest magnitude of the origin's coordinates.
    reach: f32,
    /// The sign of the scale `s_z` (the direction's `z` in the ray's frame).
    toward: f32,
}

impl GroupRay {
    /// The single-precision copy of `sheared`.
    pub fn new(sheared: &ShearedRay) -> GroupRay {
        let o = sheared.origin;
        let origin = [to_single(o.x), to_single(o.y), to_single(o.z)];
        GroupRay {
            origin,
            axes: sheared.axes,
            shear: [to_single(sheared.shear.x), to_single(sheared.shear.y)],
            reach: origin.iter().fold(0.0, |reach, x| reach.max(x.abs())),
            toward: to_single(sheared.shear.z).signum(),
        }
    }
}

impl TriangleGroup {
    /// The group of `triangles` (one to eight).
    pub fn new(triangles: &[[Vec3; 3]]) -> TriangleGroup {
        let lane = |i: usize| triangles[i.min(triangles.len() - 1)];
        let coordinate =
            |v: usize, axis: usize| std::array::from_fn(|i| to_single(lane(i)[v][axis]));
        let corners = [0, 1, 2].map(|v| [0, 1, 2].map(|axis| coordinate(v, axis)));
        let reach = std::array::from_fn(|i| {
            corners
                .iter()
                .flatten()
                .fold(0.0_f32, |reach, c| reach.max(c[i].abs()))
        });
        TriangleGroup { corners, reach }
    }

    /// [`candidates_in`](TriangleGroup::candidates_in) on any processor: the eight
    /// lanes as two halves of four.
    #[inline]
    pub fn candidates(&self, ray: &GroupRay) -> u32 {
        self.candidates_in(ray, Half(0)) | self.candidates_in(ray, Half(4)) << 4
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
    /// when one edge function is below minus twice its bound and another above plus
    /// twice it, or when the determinant's sign is certain and `t`'s is certainly
    /// negative, by twice the bounds: the exact values are then beyond any error of a double- or
    /// single-precision evaluation of the exact test, which would miss too.
    ///
    /// The lanes are those that `source` loads (all eight, or a half of four).
    #[inline(always)]
    pub fn candidates_in<S: LaneSource>(&self, ray: &GroupRay, source: S) -> u32 {
        let a = sheared(source, &self.corners[0], ray);
        let b = sheared(source, &self.corners[1], ray);
        let c = sheared(source, &self.corners[2], ray);
        let edges = [edge(b, c), edge(c, a), edge(a, b)];
        let size = a.0.abs() + a.1.abs() + b.0.abs() + b.1.abs() + c.0.abs() + c.1.abs();
        let coordinate_error =
            (source.load(&self.reach) + source.splat(ray.reach)) * (20.0 * UNIT_ROUNDOFF);
        let edge_error = size * coordinate_error
            + coordinate_error * coordinate_error * 2.0
            + size * size * (0.5 * UNIT_ROUNDOFF);
        let margin = edge_error * 2.0;
        let below = edges[0].lt(-margin) | edges[1].lt(-margin) | edges[2].lt(-margin);
        let above = edges[0].gt(margin) | edges[1].gt(margin) | edges[2].gt(margin);
        let beside = below & above;

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
        let behind = (determinant.gt(determinant_margin) & t_numerator.lt(-t_margin))
            | (determinant.lt(-determinant_margin) & t_numerator.gt(t_margin));
        !S::Lanes::bits(beside | behind) & ((1 << S::Lanes::LANES) - 1)
    }
    // ANCHOR_END: group_test
}

/// The corners `p` (one corner of each triangle, by axis) in the frame of `ray`:
/// `x = q_kx + s_x q_kz`, `y = q_ky + s_y q_kz`, `z = q_kz` with `q = p - o`.
#[inline(always)]
fn sheared<S: LaneSource>(
    source: S,
    p: &[[f32; GROUP]; 3],
    ray: &GroupRay,
) -> (S::Lanes, S::Lanes, S::Lanes) {
    let [kx, ky, kz] = ray.axes;
    let q = |axis: usize| source.load(&p[axis]) - source.splat(ray.origin[axis]);
    let z = q(kz);
    let (sx, sy) = (source.splat(ray.shear[0]), source.splat(ray.shear[1]));
    (q(kx) + sx * z, q(ky) + sy * z, z)
}

/// The edge function `p_x q_y - p_y q_x` of two sheared corners.
#[inline(always)]
fn edge<L: FloatLanes>(p: (L, L, L), q: (L, L, L)) -> L {
    p.0 * q.1 - p.1 * q.0
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

    /// A group's worth of random triangles of size about `size` around points of
    /// the cube `[-r, r]^3`.
    fn group(rng: &mut PixelRng, r: Real, size: Real) -> Vec<[Vec3; 3]> {
        (0..GROUP)
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
                set_aside += (!kept_lanes(&triangles, &ray) & lanes(GROUP)).count_ones();
            }
            // Near the origin the other seven triangles are nearly always set aside;
            // far from it, single precision cannot tell, and most are kept.
            if scale == 1.0 {
                assert!(set_aside > 110_000, "only {set_aside} of 160,000 set aside");
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
        assert_eq!(lanes(9), 0b1111_1111);
    }
}
