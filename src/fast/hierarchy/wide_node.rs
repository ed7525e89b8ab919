//! One node of the fast hierarchy: the boxes of its eight children, which a ray
//! tests at once, eight single-precision numbers per operation where the processor
//! has AVX (`crate::fast::simd::avx_eight`) and as two halves of four on any other.

use crate::fast::hierarchy::triangle_group::{GroupRay, TriangleGroup};
#[cfg(target_arch = "x86_64")]
use crate::fast::simd::avx::Avx;
use crate::fast::simd::float_lanes::{FloatLanes, Half, LaneSource};
use crate::fast::simd::portable::Portable;
use crate::geometry::Ray;
use crate::maths::{Real, Vec3, to_single};

/// Children per node: one per lane of a 256-bit SIMD register of `f32`.
pub const WIDTH: usize = 8;

/// One node: the boxes of its eight children, one child per lane, and where each
/// child's node or triangles are. Four cache lines.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct WideNode {
    /// The children's boxes by plane: lowest x, y, z, then highest x, y, z; lane `i`
    /// is child `i`. Single precision, rounded outwards so that each box still holds
    /// everything below it. An empty slot's box is the point at infinity on all
    /// three axes, which no ray reaches: along each axis its two planes are crossed
    /// at the same infinite distance, beyond any exit if the ray goes that way, before
    /// any entry if it goes the other.
    pub planes: [[f32; WIDTH]; 6],
    /// For an inner child, its node's index; for a leaf, its first triangle group.
    pub child: [u32; WIDTH],
    /// How many triangles a leaf child holds; 0 for an inner child.
    pub count: [u32; WIDTH],
}

impl WideNode {
    /// A node with eight empty slots.
    pub const EMPTY: WideNode = WideNode {
        planes: [[f32::INFINITY; WIDTH]; 6],
        child: [0; WIDTH],
        count: [0; WIDTH],
    };
}

/// How far [`round_down`] and [`round_up`] move a number outwards before rounding it
/// to single precision, relative to its size: `2^-21`, eight times the unit
/// roundoff of single precision `u = 2^-24`.
const OUTWARDS: Real = 1.0 / (1 << 21) as Real;

/// The same move for numbers near zero: four times the smallest positive `f32`.
const OUTWARDS_NEAR_ZERO: Real = 4.0 * f32::from_bits(1) as Real;

/// `x` rounded to single precision downwards, at least two floats below it: the
/// margin absorbs the rounding of the box test's own subtraction. Moving `x` down
/// by `8 u |x|` (at least four spacings of single precision near `x`) and then
/// rounding to the nearest float (half a spacing at most) lands three spacings
/// below it or lower; the absolute term does the same for subnormal numbers. A
/// number beyond single precision's range gives its largest float.
pub fn round_down(x: Real) -> f32 {
    to_single(x - (x.abs() * OUTWARDS + OUTWARDS_NEAR_ZERO)).min(f32::MAX)
}

/// `x` rounded to single precision upwards, at least two floats above it
/// ([`round_down`]).
pub fn round_up(x: Real) -> f32 {
    to_single(x + (x.abs() * OUTWARDS + OUTWARDS_NEAR_ZERO)).max(-f32::MAX)
}

/// `1 + 2 delta_3` in single precision, rounded up.
const WIDENING: f32 = 1.0 + 8.0 * f32::EPSILON;

/// How far the box tests look: a distance rounded up to single precision and
/// widened like a box's exit, capped at the largest finite float so that no box is
/// entered at an infinite distance (the empty slots).
#[derive(Clone, Copy)]
pub struct Limit(pub f32);

impl Limit {
    /// The limit of a search for hits closer than `t`.
    pub fn new(t: Real) -> Limit {
        Limit((round_up(t) * WIDENING).min(f32::MAX))
    }
}

/// A ray in single precision, for the box tests, with each axis's planes chosen by
/// the sign of its direction. Going up an axis, a ray enters a slab at its lowest
/// plane and leaves at its highest; going down, the other way round. The origin is
/// rounded up for the lowest planes and down for the highest, both strictly beyond
/// the true origin, so that every computed slab is at least as wide as the true one.
/// Being strictly beyond also means that `0 x inf` (a ray parallel to a face, with
/// an infinite inverse direction) occurs only for a ray outside that slab, where
/// either answer is safe.
pub struct WideRay {
    /// Per axis, the plane (`0` to `5`, as in [`WideNode::planes`]) where the ray
    /// enters the slab.
    pub near: [usize; 3],
    /// Per axis, the plane where it leaves.
    pub far: [usize; 3],
    /// Per axis, the origin as the near plane is measured from.
    pub near_origin: [f32; 3],
    /// Per axis, the origin as the far plane is measured from.
    pub far_origin: [f32; 3],
    /// Per axis, `1 / direction`.
    pub inv_direction: [f32; 3],
}

impl WideRay {
    /// `ray`, whose inverse direction is `inv_direction`, for the box tests. Each
    /// axis's planes and origins are picked with the sign bit of its inverse
    /// direction as an index, not with a branch, which rays going every way (diffuse
    /// bounces) would make the processor guess wrong half of the time.
    #[inline(always)]
    pub fn new(ray: &Ray, inv_direction: Vec3) -> WideRay {
        let mut wide = WideRay {
            near: [0; 3],
            far: [0; 3],
            near_origin: [0.0; 3],
            far_origin: [0.0; 3],
            inv_direction: [0.0; 3],
        };
        for axis in 0..3 {
            let inv = to_single(inv_direction[axis]);
            let down = (inv.to_bits() >> 31) as usize;
            let origins = [round_up(ray.origin[axis]), round_down(ray.origin[axis])];
            wide.inv_direction[axis] = inv;
            wide.near[axis] = axis + 3 * down;
            wide.far[axis] = axis + 3 - 3 * down;
            wide.near_origin[axis] = origins[down];
            wide.far_origin[axis] = origins[1 - down];
        }
        wide
    }
}

/// The tests the fast hierarchy makes eight at a time, a node's boxes and a group's
/// triangles, one implementation per kind of lanes.
pub trait EightLanes: Copy {
    /// Which of `node`'s boxes `ray` enters before `limit` (bit `i` for child `i`),
    /// and the distances at which it enters them.
    fn enters(self, ray: &WideRay, node: &WideNode, limit: Limit) -> (u32, [f32; WIDTH]);

    /// The triangles of `group` that `ray` may meet
    /// ([`TriangleGroup::candidates_in`]).
    fn candidates(self, group: &TriangleGroup, ray: &GroupRay) -> u32;

    /// Starts loading `item` into the cache where the processor can be asked to
    /// ([`Avx::prefetch`]); nothing elsewhere. A hint, which changes no result.
    #[inline(always)]
    fn prefetch<T>(self, item: &T) {
        let _ = item;
    }
}

/// The tests on any processor: eight lanes as two halves of four.
impl EightLanes for Portable {
    #[inline(always)]
    fn enters(self, ray: &WideRay, node: &WideNode, limit: Limit) -> (u32, [f32; WIDTH]) {
        let mut entries = [0.0; WIDTH];
        let mask = enters_in(Half(0), ray, node, limit, &mut entries)
            | enters_in(Half(4), ray, node, limit, &mut entries);
        (mask, entries)
    }

    #[inline(always)]
    fn candidates(self, group: &TriangleGroup, ray: &GroupRay) -> u32 {
        group.candidates(ray)
    }
}

/// The tests in AVX instructions, eight lanes in one register.
#[cfg(target_arch = "x86_64")]
impl EightLanes for Avx {
    #[inline(always)]
    fn enters(self, ray: &WideRay, node: &WideNode, limit: Limit) -> (u32, [f32; WIDTH]) {
        let mut entries = [0.0; WIDTH];
        let mask = enters_in(self, ray, node, limit, &mut entries);
        (mask, entries)
    }

    #[inline(always)]
    fn candidates(self, group: &TriangleGroup, ray: &GroupRay) -> u32 {
        group.candidates_in(ray, self)
    }

    #[inline(always)]
    fn prefetch<T>(self, item: &T) {
        Avx::prefetch(self, item);
    }
}

// ANCHOR: wide_slab
/// Which of the boxes of `node` that `source` loads the ray enters before `limit`
/// (bit `i` for child `i`), their entry distances written to `entries`: the slab
/// test of [`Aabb::entry`](crate::geometry::Aabb::entry) on several boxes at once.
/// Per axis the ray enters the slab at its near plane and leaves at its far one;
/// the box is entered at the farthest entry (and not before the ray's start) and
/// left at the nearest exit. Each distance carries at most three roundings, so the
/// exit is widened by `1 + 2 delta_3`; `limit` is finite and already widened.
#[inline(always)]
pub fn enters_in<S: LaneSource>(
    source: S,
    ray: &WideRay,
    node: &WideNode,
    limit: Limit,
    entries: &mut [f32; WIDTH],
) -> u32 {
    let mut entry = source.splat(0.0);
    let mut exit = source.splat(f32::INFINITY);
    for axis in 0..3 {
        let inv_direction = source.splat(ray.inv_direction[axis]);
        let crossing = |plane: usize, origin: f32| {
            (source.load(&node.planes[plane]) - source.splat(origin)) * inv_direction
        };
        entry = entry.max(crossing(ray.near[axis], ray.near_origin[axis]));
        exit = exit.min(crossing(ray.far[axis], ray.far_origin[axis]));
    }
    let exit = (exit * WIDENING).min(source.splat(limit.0));
    source.store(entry, entries);
    S::Lanes::bits(entry.le(exit)) << source.first()
}
// ANCHOR_END: wide_slab

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maths::{pixel_rng, uniform};

    /// The second single-precision float strictly below `x`.
    fn second_below(x: Real) -> f32 {
        let f = to_single(x);
        let below = if f as Real >= x { f.next_down() } else { f };
        below.next_down()
    }

    /// `round_down` lands at least two floats below each number and `round_up` two
    /// above, for numbers of every size and sign: zero, subnormal ones, powers of
    /// two (where the spacing of floats halves below), single-precision ones and
    /// numbers between them.
    #[test]
    fn rounding_moves_at_least_two_floats_outwards() {
        let mut rng = pixel_rng(5, 0);
        let mut numbers = vec![0.0, 1.0, 2.0, 0.5, 1e-45, 3e-45, 1e-40, 1e-38, 3e38];
        for _ in 0..100_000 {
            let exponent = (uniform(&mut rng) * 80.0 - 40.0) as i32;
            numbers.push(uniform(&mut rng) * (2.0 as Real).powi(exponent));
            numbers.push(to_single(*numbers.last().unwrap()) as Real);
        }
        for x in numbers.iter().flat_map(|&x| [x, -x]) {
            assert!(round_down(x) <= second_below(x), "{x}");
            assert!(-round_up(x) <= second_below(-x), "{x}");
        }
    }

    /// Twice single precision's largest float: beyond its range in double
    /// precision, infinite in single.
    #[test]
    fn numbers_beyond_single_precision_round_to_its_largest() {
        let beyond = f32::MAX as Real * 2.0;
        assert_eq!(round_down(beyond), f32::MAX);
        assert_eq!(round_up(-beyond), -f32::MAX);
        assert_eq!(round_up(beyond), f32::INFINITY);
    }
}
