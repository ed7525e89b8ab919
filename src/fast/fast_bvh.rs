//! The hierarchy laid out for speed: the SAH tree collapsed to four children per
//! node, whose four boxes a ray tests at once on the four lanes of a SIMD register,
//! and each leaf's triangles stored in groups of four that a single-precision
//! pre-test ([`TriangleGroup`]) also tests at once, leaving the exact test only the
//! triangles the ray may meet. It finds exactly the hits the course's traversal
//! finds; only the number of steps and the memory traffic shrink.

use arrayvec::ArrayVec;
use glam::Vec4;

use crate::acceleration::Bvh;
use crate::fast::sah;
use crate::fast::triangle_group::{GROUP, GroupRay, TriangleGroup, lanes};
use crate::geometry::{Ray, ShearedRay, TriangleTest};
use crate::maths::{Real, Vec3, to_single};
use crate::meshes::{Mesh, MeshHit, Search};

/// Children per node: one per lane of a 128-bit SIMD register.
const WIDTH: usize = 4;

/// Pending children the traversal keeps in a fixed array; more spill to the heap.
const STACK: usize = 24;

/// One node: the boxes of its four children, one child per lane, and where each
/// child's node or triangles are. Two cache lines.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct WideNode {
    /// The children's boxes by plane: lowest x, y, z, then highest x, y, z; lane `i`
    /// is child `i`. Single precision, rounded outwards so that each box still holds
    /// everything below it. An empty slot's box is the point at infinity on all
    /// three axes, which no ray reaches: along each axis its two planes are crossed
    /// at the same infinite distance, beyond any exit if the ray goes that way, before
    /// any entry if it goes the other.
    planes: [[f32; WIDTH]; 6],
    /// For an inner child, its node's index; for a leaf, its first triangle group.
    child: [u32; WIDTH],
    /// How many triangles a leaf child holds; 0 for an inner child.
    count: [u32; WIDTH],
}

impl WideNode {
    /// A node with four empty slots.
    const EMPTY: WideNode = WideNode {
        planes: [[f32::INFINITY; WIDTH]; 6],
        child: [0; WIDTH],
        count: [0; WIDTH],
    };
}

/// A bounding volume hierarchy flattened for traversal.
#[derive(Clone, Debug, PartialEq)]
pub struct FastBvh {
    /// The nodes, the root first.
    nodes: Vec<WideNode>,
    /// Each leaf's triangles in groups of four, in single precision, for the
    /// pre-test; group `g` holds slots `4 g` to `4 g + 3`.
    groups: Vec<TriangleGroup>,
    /// The mesh's index of the triangle in every slot, for the exact test on the
    /// mesh's own corners. A leaf's last group is padded with its last triangle.
    ids: Vec<u32>,
}

/// `x` rounded to single precision, downwards, then one float further: the margin
/// absorbs the rounding of the box test's own subtraction.
fn round_down(x: Real) -> f32 {
    let f = to_single(x);
    let f = if (f as Real) > x { f.next_down() } else { f };
    f.next_down()
}

/// `x` rounded to single precision, upwards, then one float further.
fn round_up(x: Real) -> f32 {
    let f = to_single(x);
    let f = if (f as Real) < x { f.next_up() } else { f };
    f.next_up()
}

/// A ray in single precision, for the box tests, each value splatted over four
/// lanes. Its origin is kept twice, rounded up and rounded down, both strictly
/// beyond the true origin: a lowest plane is measured from the origin above it and a
/// highest plane from the one below, so whichever way the ray goes, every computed
/// slab is at least as wide as the true one. Being strictly beyond also means that
/// `0 x inf` (a ray parallel to a face, with an infinite inverse direction) occurs
/// only for a ray outside that slab, where either answer is safe.
struct WideRay {
    /// Per axis, the origin rounded up, for the lowest planes.
    above: [Vec4; 3],
    /// Per axis, the origin rounded down, for the highest planes.
    below: [Vec4; 3],
    /// Per axis, `1 / direction`.
    inv_direction: [Vec4; 3],
}

impl WideRay {
    /// `ray`, whose inverse direction is `inv_direction`, for the box tests.
    fn new(ray: &Ray, inv_direction: Vec3) -> WideRay {
        let splat = |f: fn(Real) -> f32, v: Vec3| {
            [
                Vec4::splat(f(v.x)),
                Vec4::splat(f(v.y)),
                Vec4::splat(f(v.z)),
            ]
        };
        WideRay {
            above: splat(round_up, ray.origin),
            below: splat(round_down, ray.origin),
            inv_direction: splat(to_single, inv_direction),
        }
    }

    // ANCHOR: wide_slab
    /// Which of `node`'s four boxes the ray enters before `limit` (bit `i` for
    /// child `i`), and the distances at which it enters them: the slab test of
    /// [`Aabb::entry`] on four boxes at once. Per axis the ray crosses the lowest
    /// and the highest plane; the nearer crossing is where it enters the slab,
    /// whichever way it goes. Each distance carries at most three roundings, so the
    /// exit is widened by `1 + 2 delta_3`; `limit` is finite and already widened.
    #[inline(always)]
    fn enters(&self, node: &WideNode, limit: Limit) -> (u32, Vec4) {
        let mut entry = Vec4::ZERO;
        let mut exit = Vec4::INFINITY;
        for axis in 0..3 {
            let inv_direction = self.inv_direction[axis];
            let lowest = (Vec4::from_array(node.planes[axis]) - self.above[axis]) * inv_direction;
            let highest =
                (Vec4::from_array(node.planes[axis + 3]) - self.below[axis]) * inv_direction;
            entry = entry.max(lowest.min(highest));
            exit = exit.min(lowest.max(highest));
        }
        let exit = (exit * WIDENING).min(Vec4::splat(limit.0));
        (entry.cmple(exit).bitmask(), entry)
    }
    // ANCHOR_END: wide_slab
}

/// `1 + 2 delta_3` in single precision, rounded up.
const WIDENING: f32 = 1.0 + 8.0 * f32::EPSILON;

/// How far the box tests look: a distance rounded up to single precision and
/// widened like a box's exit, capped at the largest finite float so that no box is
/// entered at an infinite distance (the empty slots).
#[derive(Clone, Copy)]
struct Limit(f32);

impl Limit {
    fn new(t: Real) -> Limit {
        Limit((round_up(t) * WIDENING).min(f32::MAX))
    }
}

/// A child waiting on the traversal stack: a node, or a leaf's triangles, and the
/// distance at which the ray enters its box.
#[derive(Clone, Copy)]
struct Pending {
    child: u32,
    count: u32,
    entry: f32,
}

/// The root, entered from the ray's start.
const ROOT: Pending = Pending {
    child: 0,
    count: 0,
    entry: 0.0,
};

/// The children waiting to be visited, the next on top.
struct Stack {
    /// The first `STACK` entries, in place (nothing to allocate or clear per ray).
    entries: ArrayVec<Pending, STACK>,
    /// Entries beyond the first `STACK`, for deep trees.
    spilled: Vec<Pending>,
}

impl Stack {
    /// An empty stack.
    #[inline]
    fn new() -> Stack {
        Stack {
            entries: ArrayVec::new(),
            spilled: Vec::new(),
        }
    }

    /// Puts `pending` on top, in the array while it has room.
    #[inline]
    fn push(&mut self, pending: Pending) {
        if let Err(full) = self.entries.try_push(pending) {
            self.spilled.push(full.element());
        }
    }

    /// The entry on top of the array, or a spilled one once the array is empty.
    /// After a spill the order is no longer strictly last-in first-out, which costs
    /// at most some culling, never a hit: every pending child is still visited.
    #[inline]
    fn pop(&mut self) -> Option<Pending> {
        self.entries.pop().or_else(|| self.spilled.pop())
    }

    /// Of the children of `node` whose bit is set in `mask`, returns the nearest,
    /// to be visited next, and pushes the others, the nearer ones last so that they
    /// are popped first.
    #[inline]
    fn push_all_but_nearest(&mut self, node: &WideNode, mask: u32, entry: Vec4) -> Option<Pending> {
        let entry = entry.to_array();
        let pending = |lane: usize| Pending {
            child: node.child[lane],
            count: node.count[lane],
            entry: entry[lane],
        };
        if mask == 0 {
            return None;
        }
        let first = mask.trailing_zeros() as usize;
        let rest = mask & (mask - 1);
        if rest == 0 {
            return Some(pending(first));
        }
        let second = rest.trailing_zeros() as usize;
        if rest & (rest - 1) == 0 {
            let (near, far) = if entry[first] <= entry[second] {
                (first, second)
            } else {
                (second, first)
            };
            self.push(pending(far));
            return Some(pending(near));
        }
        let mut nearest = None;
        for lane in farthest_first(entry) {
            if mask & (1 << lane) != 0 {
                if let Some(farther) = nearest {
                    self.push(farther);
                }
                nearest = Some(pending(lane));
            }
        }
        nearest
    }
}

/// The four lanes ordered by `entry`, farthest first: five compare-and-swaps (a
/// sorting network), without the branches and calls of a general sort.
#[inline]
fn farthest_first(entry: [f32; WIDTH]) -> [usize; WIDTH] {
    let mut order: [usize; WIDTH] = [0, 1, 2, 3];
    for (a, b) in [(0, 1), (2, 3), (0, 2), (1, 3), (1, 2)] {
        if entry[order[a]] < entry[order[b]] {
            order.swap(a, b);
        }
    }
    order
}

impl FastBvh {
    /// The hierarchy of `mesh` built with the surface area heuristic
    /// ([`sah::build`]), leaves of at most `max_leaf` triangles, collapsed to
    /// four children per node.
    pub fn build(mesh: &Mesh, max_leaf: u16) -> FastBvh {
        let bvh = sah::build(mesh, max_leaf.into(), GROUP);
        let mut fast = FastBvh {
            nodes: vec![],
            groups: vec![],
            ids: Vec::with_capacity(mesh.triangles.len()),
        };
        fast.nodes.push(WideNode::EMPTY);
        if mesh.triangles.is_empty() {
            return fast;
        }
        let root = if bvh.nodes[0].count > 0 {
            vec![0]
        } else {
            children(&bvh, 0).to_vec()
        };
        let mut unfilled = vec![(0, root)];
        while let Some((at, slots)) = unfilled.pop() {
            for (lane, n) in opened(&bvh, slots).into_iter().enumerate() {
                let node = &bvh.nodes[n];
                for axis in 0..3 {
                    fast.nodes[at].planes[axis][lane] = round_down(node.bounds.min[axis]);
                    fast.nodes[at].planes[axis + 3][lane] = round_up(node.bounds.max[axis]);
                }
                if node.count > 0 {
                    fast.nodes[at].child[lane] = fast.groups.len() as u32;
                    fast.nodes[at].count[lane] = node.count;
                    let triangles = node.first as usize..(node.first + node.count) as usize;
                    fast.push_leaf(mesh, &bvh.order[triangles]);
                } else {
                    fast.nodes[at].child[lane] = fast.nodes.len() as u32;
                    unfilled.push((fast.nodes.len(), children(&bvh, n).to_vec()));
                    fast.nodes.push(WideNode::EMPTY);
                }
            }
        }
        fast
    }

    /// Appends a leaf's triangles: their groups, and their indices padded to whole
    /// groups.
    fn push_leaf(&mut self, mesh: &Mesh, triangles: &[u32]) {
        for chunk in triangles.chunks(GROUP) {
            let corners: Vec<[Vec3; 3]> = chunk.iter().map(|&t| mesh.corners(t)).collect();
            self.groups.push(TriangleGroup::new(&corners));
            let last = chunk.len() - 1;
            self.ids
                .extend((0..GROUP).map(|lane| chunk[lane.min(last)]));
        }
    }

    /// The triangle groups of a leaf: group `g` holds slots `4 g` to `4 g + 3`.
    #[inline]
    fn groups_of(leaf: Pending) -> std::ops::Range<usize> {
        let first = leaf.child as usize;
        first..first + (leaf.count as usize).div_ceil(GROUP)
    }

    /// The lanes of group `g` of `leaf` whose triangle the ray may meet (bit `i` for
    /// slot `4 g + i`): those the single-precision pre-test keeps
    /// ([`TriangleGroup::candidates`]) when there is a pre-test ray, every filled
    /// lane otherwise.
    #[inline]
    fn candidates(&self, leaf: Pending, g: usize, ray: Option<&GroupRay>) -> u32 {
        let filled = lanes(leaf.count as usize - (g - leaf.child as usize) * GROUP);
        match ray {
            Some(ray) => filled & self.groups[g].candidates(ray),
            None => filled,
        }
    }
}

/// The set bits of a mask, lowest first.
struct Bits(u32);

impl Iterator for Bits {
    type Item = usize;

    #[inline]
    fn next(&mut self) -> Option<usize> {
        (self.0 != 0).then(|| {
            let bit = self.0.trailing_zeros() as usize;
            self.0 &= self.0 - 1;
            bit
        })
    }
}

impl Search for FastBvh {
    fn name(&self) -> &'static str {
        "fast"
    }

    // ANCHOR: fast_traverse
    /// The nearest triangle of `mesh` that `ray` meets closer than `t_max`: the same
    /// hit as the course's [`Bvh`] (equal distances go to the lower triangle index).
    /// A ray that misses the mesh's box (most rays, in a room where the mesh is small)
    /// is turned away by that one slab test, as the course's bounding box does, before
    /// anything else is made for it. Of the children a ray enters, the nearest is
    /// visited next and the others wait on the stack, nearer ones on top; a child is
    /// skipped when popped if a hit found meanwhile is closer than its box. In a leaf,
    /// only the triangles the pre-test keeps get the exact test.
    fn nearest(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        let inv_direction = ray.direction.recip();
        mesh.bounds.entry(ray, inv_direction, t_max)?;
        let wide = WideRay::new(ray, inv_direction);
        let mut leaf_rays = LeafRays::default();
        let mut best: Option<MeshHit> = None;
        // The box test's limit, and the triangle test's (which lets an equal
        // distance through, for the lower index to win).
        let mut box_limit = Limit::new(t_max);
        let mut triangle_limit = t_max;
        let mut stack = Stack::new();
        let mut next = Some(ROOT);
        while let Some(pending) = next.take().or_else(|| stack.pop()) {
            if pending.entry > box_limit.0 {
                continue;
            }
            if pending.count == 0 {
                let node = &self.nodes[pending.child as usize];
                let (mask, entry) = wide.enters(node, box_limit);
                next = stack.push_all_but_nearest(node, mask, entry);
                continue;
            }
            let (sheared, group_ray) = leaf_rays.get(mesh, ray);
            for g in FastBvh::groups_of(pending) {
                for lane in Bits(self.candidates(pending, g, group_ray)) {
                    let triangle = self.ids[GROUP * g + lane];
                    if let Some(at) = mesh.hit_triangle(ray, sheared, triangle, triangle_limit)
                        && best.is_none_or(|b| (at.t, triangle) < (b.at.t, b.triangle))
                    {
                        best = Some(MeshHit { triangle, at });
                        box_limit = Limit::new(at.t);
                        triangle_limit = at.t.next_up();
                    }
                }
            }
        }
        best
    }
    // ANCHOR_END: fast_traverse

    /// Whether `ray` meets any triangle of `mesh` closer than `t_max`, stopping at
    /// the first one found.
    fn occluded(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        let inv_direction = ray.direction.recip();
        if mesh.bounds.entry(ray, inv_direction, t_max).is_none() {
            return false;
        }
        let wide = WideRay::new(ray, inv_direction);
        let mut leaf_rays = LeafRays::default();
        let limit = Limit::new(t_max);
        let mut stack = Stack::new();
        stack.push(ROOT);
        while let Some(pending) = stack.pop() {
            if pending.count == 0 {
                let node = &self.nodes[pending.child as usize];
                let (mask, _) = wide.enters(node, limit);
                for lane in Bits(mask) {
                    stack.push(Pending {
                        child: node.child[lane],
                        count: node.count[lane],
                        entry: 0.0,
                    });
                }
            } else {
                let (sheared, group_ray) = leaf_rays.get(mesh, ray);
                for g in FastBvh::groups_of(pending) {
                    for lane in Bits(self.candidates(pending, g, group_ray)) {
                        let triangle = self.ids[GROUP * g + lane];
                        if mesh.hit_triangle(ray, sheared, triangle, t_max).is_some() {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }
}

/// The ray as the triangle tests take it, made when the traversal reaches its first
/// leaf: a ray that enters no leaf's box (most rays, in a room where the mesh is
/// small) never pays for it.
#[derive(Default)]
struct LeafRays(Option<(ShearedRay, Option<GroupRay>)>);

impl LeafRays {
    /// The sheared ray of the exact test and the ray of the pre-test, if any.
    #[inline]
    fn get(&mut self, mesh: &Mesh, ray: &Ray) -> (&ShearedRay, Option<&GroupRay>) {
        let (sheared, group_ray) = self.0.get_or_insert_with(|| {
            let sheared = ShearedRay::new(ray);
            let group_ray = pretest_ray(mesh, &sheared);
            (sheared, group_ray)
        });
        (sheared, group_ray.as_ref())
    }
}

/// The ray of the single-precision pre-test, for a mesh searched with the watertight
/// test; `None` for the course's Moller-Trumbore test, whose own rounding the
/// pre-test's margin does not cover, so that all its triangles get the exact test.
/// Decided once per ray.
fn pretest_ray(mesh: &Mesh, sheared: &ShearedRay) -> Option<GroupRay> {
    (mesh.triangle_test == TriangleTest::Watertight).then(|| GroupRay::new(sheared))
}

/// The binary nodes `slots` with inner ones replaced by their children, the
/// largest box first, until there are four: the children of one wide node.
fn opened(bvh: &Bvh, mut slots: Vec<usize>) -> Vec<usize> {
    while slots.len() < WIDTH {
        let inner = slots
            .iter()
            .enumerate()
            .filter(|(_, n)| bvh.nodes[**n].count == 0);
        let largest = inner.max_by(|a, b| {
            let area = |n: usize| bvh.nodes[n].bounds.half_area();
            area(*a.1).total_cmp(&area(*b.1))
        });
        let Some((at, &open)) = largest else { break };
        slots.splice(at..=at, children(bvh, open));
    }
    slots
}

/// The two children of the binary node `n`, an inner node.
fn children(bvh: &Bvh, n: usize) -> [usize; 2] {
    let first = bvh.nodes[n].first as usize;
    [first, first + 1]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nodes_are_two_cache_lines_and_boxes_round_outwards() {
        assert_eq!(std::mem::size_of::<WideNode>(), 128);
        for x in [0.1, -0.1, 1e-30, 3.0, -1e20] {
            assert!(
                round_down(x) as Real <= x && x <= round_up(x) as Real,
                "{x}"
            );
        }
    }
}
