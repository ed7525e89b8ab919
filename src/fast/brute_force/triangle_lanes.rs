//! Beyond the course: Moller and Trumbore's ray-triangle test
//! ([`intersect_triangle`](crate::geometry::intersect_triangle)) for one ray against
//! [`LANES`] triangles at once, four in double precision and eight in single, each
//! step the course's own in its order, so that every lane finds what the course's
//! function finds for its triangle, to the last bit.

use crate::fast::simd::real_lanes::{
    LANES, RealLanes, RealSource, VectorLanes, cross, dot, minus, splat3,
};
use crate::geometry::Ray;
use crate::maths::{Real, Vec3};

/// [`LANES`] triangles by coordinate: corner `A` and the edges `e1 = B - A`,
/// `e2 = C - A`, computed once when the group is made (the course computes them at
/// each test, to the same bits). `a[axis][k]` is coordinate `axis` of triangle `k`'s
/// corner `A`. Lanes past the last triangle repeat it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleLanes {
    /// The first corners.
    a: [[Real; LANES]; 3],
    /// The edges from the first corner to the second.
    e1: [[Real; LANES]; 3],
    /// The edges from the first corner to the third.
    e2: [[Real; LANES]; 3],
}

/// What one ray meets among the triangles of a [`TriangleLanes`]: per lane, the
/// values the course's test computes, and which lanes are hits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaneHits {
    /// Bit `k` set where the ray meets triangle `k` closer than the limit.
    pub hits: u32,
    /// The distances.
    pub t: [Real; LANES],
    /// The weights `b_B` of the second corners.
    pub beta: [Real; LANES],
    /// The weights `b_C` of the third corners.
    pub gamma: [Real; LANES],
}

impl TriangleLanes {
    /// The group of `triangles` (one to [`LANES`]), each given by its three corners.
    pub fn new(triangles: &[[Vec3; 3]]) -> TriangleLanes {
        let lane = |k: usize| triangles[k.min(triangles.len() - 1)];
        let by_axis = |v: fn([Vec3; 3]) -> Vec3| {
            [0, 1, 2].map(|axis| std::array::from_fn(|k| v(lane(k))[axis]))
        };
        TriangleLanes {
            a: by_axis(|[a, _, _]| a),
            e1: by_axis(|[a, b, _]| b - a),
            e2: by_axis(|[a, _, c]| c - a),
        }
    }

    // ANCHOR: lane_test
    /// The lanes whose triangle `ray` meets at a distance in `(0, t_max)`, with the
    /// distances and weights: [`intersect_triangle`](crate::geometry::intersect_triangle)
    /// on every lane at once. The course's test returns early (a ray parallel to
    /// the plane, `b_B` outside `[0, 1]`); the lanes compute every step for every
    /// triangle and keep, as a mask, the lanes that pass each of its conditions,
    /// written so that a NaN fails or passes them as the course's `if`s do.
    #[inline(always)]
    pub fn hits<L: RealSource>(&self, lanes: L, ray: &Ray, t_max: Real) -> LaneHits {
        let (a, e1, e2) = (
            load(lanes, &self.a),
            load(lanes, &self.e1),
            load(lanes, &self.e2),
        );
        let direction: VectorLanes<L::Wide> = splat3(lanes, ray.direction);
        let h = cross(direction, e2);
        let det = dot(e1, h);
        let (zero, one) = (lanes.splat(0.0), lanes.splat(1.0));
        let inv_det = one / det;
        let w = minus(splat3(lanes, ray.origin), a);
        let beta = dot(w, h) * inv_det;
        let q = cross(w, e1);
        let gamma = dot(direction, q) * inv_det;
        let t = dot(e2, q) * inv_det;
        let inside = det.ne(zero) & beta.ge(zero) & one.ge(beta);
        let outside = gamma.lt(zero) | (beta + gamma).gt(one);
        let ahead = t.gt(zero) & t.lt(lanes.splat(t_max));
        LaneHits {
            hits: outside.and_not(inside & ahead).bits(),
            t: t.to_array(),
            beta: beta.to_array(),
            gamma: gamma.to_array(),
        }
    }
    // ANCHOR_END: lane_test
}

/// The lanes of three coordinates. Written out, not with `map`, which might not be
/// inlined into the function compiled with AVX ([`lanes`](crate::fast::lanes)).
#[inline(always)]
fn load<L: RealSource>(lanes: L, v: &[[Real; LANES]; 3]) -> VectorLanes<L::Wide> {
    [lanes.gather(v[0]), lanes.gather(v[1]), lanes.gather(v[2])]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fast::simd::portable::Portable;
    use crate::geometry::{TriangleHit, intersect_triangle};
    use crate::maths::{PixelRng, pixel_rng, uniform};

    /// A random point of the cube `[-1, 1]^3`.
    fn point(rng: &mut PixelRng) -> Vec3 {
        Vec3::new(uniform(rng), uniform(rng), uniform(rng)) * 2.0 - Vec3::ONE
    }

    /// Eight awkward triangles around `first`: itself and a repeat of it (equal
    /// distances), one with two equal corners, one with its three corners in a line
    /// (no area), one whose plane holds the ray (`det = 0` or nearly), and three at
    /// random, to be tested in groups of [`LANES`].
    fn triangles(rng: &mut PixelRng, first: [Vec3; 3], ray: &Ray) -> Vec<[Vec3; 3]> {
        let [a, b, _] = first;
        let mut awkward = vec![first, first, [a, a, b], [a, b, a + (b - a) * 2.0]];
        awkward.push([ray.origin, ray.origin + ray.direction, b]);
        awkward.extend((0..3).map(|_| [0; 3].map(|_| point(rng))));
        awkward
    }

    /// A ray aimed at a corner or an edge's middle of `target`, where rounding
    /// decides, or at random.
    fn ray(rng: &mut PixelRng, target: [Vec3; 3]) -> Ray {
        let [a, b, _] = target;
        let aim = match (uniform(rng) * 3.0) as u32 {
            0 => a,
            1 => (a + b) * 0.5,
            _ => point(rng),
        };
        let origin = point(rng) * 4.0;
        Ray::new(origin, (aim - origin).normalize())
    }

    /// Checks every lane of `lanes`' answer against the course's test, bit for bit.
    fn agrees<L: RealSource>(lanes: L, group: &[[Vec3; 3]], ray: &Ray, t_max: Real) -> bool {
        let found = TriangleLanes::new(group).hits(lanes, ray, t_max);
        (0..LANES).all(|k| {
            let [a, b, c] = group[k];
            let lane = (found.hits >> k & 1 == 1).then(|| TriangleHit {
                t: found.t[k],
                beta: found.beta[k],
                gamma: found.gamma[k],
            });
            let course = intersect_triangle(ray, a, b, c, t_max);
            let bits =
                |h: Option<TriangleHit>| h.map(|h| [h.t, h.beta, h.gamma].map(Real::to_bits));
            bits(lane) == bits(course)
        })
    }

    /// Asserts that every lane of `lanes` finds what the course's test finds, to the
    /// bit, on 50,000 rays against groups of awkward triangles.
    fn every_lane_finds_what_the_course_test_finds(lanes: impl RealSource) {
        let mut rng = pixel_rng(11, 0);
        let mut hits = 0;
        for _ in 0..50_000 {
            let first = [0; 3].map(|_| point(&mut rng));
            let ray = ray(&mut rng, first);
            let t_max = if uniform(&mut rng) < 0.2 {
                3.0
            } else {
                Real::INFINITY
            };
            for group in triangles(&mut rng, first, &ray).chunks(LANES) {
                assert!(agrees(lanes, group, &ray, t_max), "{ray:?} {group:?}");
            }
            hits +=
                u32::from(intersect_triangle(&ray, first[0], first[1], first[2], t_max).is_some());
        }
        assert!(
            hits > 10_000,
            "only {hits} of 50,000 rays hit: the test is vacuous"
        );
    }

    #[test]
    fn every_portable_lane_finds_what_the_course_test_finds_to_the_bit() {
        every_lane_finds_what_the_course_test_finds(Portable);
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
    fn every_avx_lane_finds_what_the_course_test_finds_to_the_bit() {
        every_lane_finds_what_the_course_test_finds(crate::fast::simd::avx::Avx::for_test());
    }

    #[test]
    fn a_ray_with_no_direction_meets_nothing_on_any_lane() {
        let mut rng = pixel_rng(12, 0);
        for direction in [Vec3::ZERO, Vec3::splat(Real::NAN)] {
            let ray = Ray {
                origin: Vec3::new(0.1, 0.1, 5.0),
                direction,
            };
            let first = [0; 3].map(|_| point(&mut rng));
            for group in triangles(&mut rng, first, &ray).chunks(LANES) {
                assert!(agrees(Portable, group, &ray, Real::INFINITY));
                let found = TriangleLanes::new(group).hits(Portable, &ray, Real::INFINITY);
                assert_eq!(found.hits, 0);
            }
        }
    }
}
