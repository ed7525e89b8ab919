//! The hierarchy laid out for speed: the SAH tree collapsed to four children per
//! node, whose four boxes a ray tests at once on the four lanes of a SIMD register,
//! with each leaf's triangles copied next to each other. It finds exactly the hits
//! the course's traversal finds; only the number of steps and the memory traffic
//! shrink.

use glam::Vec4;

use crate::bvh::Bvh;
use crate::math::{Real, Vec3, to_single};
use crate::mesh::{Mesh, MeshHit};
use crate::ray::Ray;
use crate::triangle::{TriangleHit, TriangleTest, intersect_triangle};
use crate::watertight::ShearedRay;

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
    /// everything below it. An empty slot's box is inverted, and no ray enters it.
    planes: [[f32; WIDTH]; 6],
    /// For an inner child, its node's index; for a leaf, its first triangle slot.
    child: [u32; WIDTH],
    /// How many triangles a leaf child holds; 0 for an inner child.
    count: [u32; WIDTH],
}

impl WideNode {
    /// A node with four empty slots.
    const EMPTY: WideNode = WideNode {
        planes: [
            [f32::INFINITY; WIDTH],
            [f32::INFINITY; WIDTH],
            [f32::INFINITY; WIDTH],
            [f32::NEG_INFINITY; WIDTH],
            [f32::NEG_INFINITY; WIDTH],
            [f32::NEG_INFINITY; WIDTH],
        ],
        child: [0; WIDTH],
        count: [0; WIDTH],
    };
}

/// A bounding volume hierarchy flattened for traversal.
#[derive(Clone, Debug, PartialEq)]
pub struct FastBvh {
    /// The nodes, the root first.
    nodes: Vec<WideNode>,
    /// The corners of every triangle, in leaf order.
    corners: Vec<[Vec3; 3]>,
    /// The mesh's index of every triangle slot.
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
/// lanes. Its origin is kept twice, rounded down and rounded up, both strictly
/// beyond the true origin: a lowest plane is measured from the origin above it and a
/// highest plane from the one below, so every computed slab is at least as wide as
/// the true one. Being strictly beyond also means that `0 x inf` (a ray parallel to
/// a face, with an infinite inverse direction) occurs only for a ray outside that
/// slab, where either answer is safe.
struct WideRay {
    /// Per axis, the plane the ray meets first (`axis`, or `axis + 3` when the
    /// ray goes towards lower values) and the one it meets last.
    near: [usize; 3],
    far: [usize; 3],
    /// Per axis, the rounded origin each of those planes is measured from.
    near_origin: [Vec4; 3],
    far_origin: [Vec4; 3],
    /// Per axis, `1 / direction`.
    inv_direction: [Vec4; 3],
}

impl WideRay {
    fn new(ray: &Ray) -> WideRay {
        let mut wide = WideRay {
            near: [0, 1, 2],
            far: [3, 4, 5],
            near_origin: [Vec4::ZERO; 3],
            far_origin: [Vec4::ZERO; 3],
            inv_direction: [Vec4::ZERO; 3],
        };
        for axis in 0..3 {
            let inv = to_single(ray.direction[axis].recip());
            let above = Vec4::splat(round_up(ray.origin[axis]));
            let below = Vec4::splat(round_down(ray.origin[axis]));
            wide.inv_direction[axis] = Vec4::splat(inv);
            if inv.is_sign_negative() {
                (wide.near[axis], wide.far[axis]) = (axis + 3, axis);
                (wide.near_origin[axis], wide.far_origin[axis]) = (below, above);
            } else {
                (wide.near_origin[axis], wide.far_origin[axis]) = (above, below);
            }
        }
        wide
    }

    // ANCHOR: wide_slab
    /// Which of `node`'s four boxes the ray enters before `limit` (bit `i` for
    /// child `i`), and the distances at which it enters them: the slab test of
    /// [`Aabb::entry`] on four boxes at once. Each distance carries at most three
    /// roundings, so the exit is widened by `1 + 2 gamma(3)`.
    #[inline(always)]
    fn enters(&self, node: &WideNode, limit: f32) -> (u32, Vec4) {
        let distance = |plane: usize, origin: Vec4, axis: usize| {
            (Vec4::from_array(node.planes[plane]) - origin) * self.inv_direction[axis]
        };
        let near = |axis| distance(self.near[axis], self.near_origin[axis], axis);
        let far = |axis| distance(self.far[axis], self.far_origin[axis], axis);
        let entry = near(0).max(near(1)).max(near(2).max(Vec4::ZERO));
        let exit = far(0).min(far(1)).min(far(2).min(Vec4::splat(limit))) * WIDENING;
        (entry.cmple(exit).bitmask(), entry)
    }
    // ANCHOR_END: wide_slab
}

/// `1 + 2 gamma(3)` in single precision, rounded up.
const WIDENING: f32 = 1.0 + 8.0 * f32::EPSILON;

/// A child waiting on the traversal stack: a node, or a leaf's triangles, and the
/// distance at which the ray enters its box.
#[derive(Clone, Copy, Default)]
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
    entries: [Pending; STACK],
    len: usize,
    /// Entries beyond the first `STACK`, for deep trees.
    spilled: Vec<Pending>,
}

impl Stack {
    #[inline]
    fn push(&mut self, pending: Pending) {
        if self.len < STACK {
            self.entries[self.len] = pending;
            self.len += 1;
        } else {
            self.spilled.push(pending);
        }
    }

    #[inline]
    fn pop(&mut self) -> Option<Pending> {
        if let Some(pending) = self.spilled.pop() {
            return Some(pending);
        }
        self.len = self.len.checked_sub(1)?;
        Some(self.entries[self.len])
    }

    /// Pushes the children of `node` whose bit is set in `mask`, the nearest last
    /// so that it is popped first.
    #[inline]
    fn push_nearest_last(&mut self, node: &WideNode, mask: u32, entry: Vec4) {
        let entry = entry.to_array();
        let pending = |lane: usize| Pending {
            child: node.child[lane],
            count: node.count[lane],
            entry: entry[lane],
        };
        let first = mask.trailing_zeros() as usize;
        match mask.count_ones() {
            0 => {}
            1 => self.push(pending(first)),
            2 => {
                let second = (mask & (mask - 1)).trailing_zeros() as usize;
                let (near, far) = if entry[first] <= entry[second] {
                    (first, second)
                } else {
                    (second, first)
                };
                self.push(pending(far));
                self.push(pending(near));
            }
            _ => {
                let mut lanes: [usize; WIDTH] = [0, 1, 2, 3];
                lanes.sort_unstable_by(|a, b| entry[*b].total_cmp(&entry[*a]));
                for lane in lanes {
                    if mask & (1 << lane) != 0 {
                        self.push(pending(lane));
                    }
                }
            }
        }
    }
}

/// A stack holding the root.
macro_rules! root_stack {
    () => {
        Stack {
            entries: [ROOT; STACK],
            len: 1,
            spilled: Vec::new(),
        }
    };
}

impl FastBvh {
    /// The hierarchy of `mesh` built with the surface area heuristic
    /// ([`Bvh::build_sah`]), leaves of at most `max_leaf` triangles, collapsed to
    /// four children per node.
    pub fn build(mesh: &Mesh, max_leaf: u16) -> FastBvh {
        let bvh = Bvh::build_sah(mesh, max_leaf.into());
        let mut fast = FastBvh {
            nodes: vec![],
            corners: Vec::with_capacity(mesh.triangles.len()),
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
                    fast.nodes[at].child[lane] = fast.ids.len() as u32;
                    fast.nodes[at].count[lane] = node.count;
                    let triangles = node.first as usize..(node.first + node.count) as usize;
                    for &t in &bvh.order[triangles] {
                        fast.corners.push(mesh.corners(t));
                        fast.ids.push(t);
                    }
                } else {
                    fast.nodes[at].child[lane] = fast.nodes.len() as u32;
                    unfilled.push((fast.nodes.len(), children(&bvh, n).to_vec()));
                    fast.nodes.push(WideNode::EMPTY);
                }
            }
        }
        fast
    }

    // ANCHOR: fast_traverse
    /// The nearest triangle of `mesh` that `ray` meets closer than `t_max`: the same
    /// hit as [`Bvh::intersect`] (equal distances go to the lower triangle index).
    /// The children a ray enters are visited nearest first, and a child is skipped
    /// when popped if a hit found meanwhile is closer than its box.
    pub fn intersect(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        let wide = WideRay::new(ray);
        let sheared = ShearedRay::new(ray);
        let mut best: Option<(Real, u32, TriangleHit)> = None;
        // The box test's limit, and the triangle test's (which lets an equal
        // distance through, for the lower index to win).
        let mut box_limit = round_up(t_max);
        let mut triangle_limit = t_max;
        let mut stack = root_stack!();
        while let Some(pending) = stack.pop() {
            if pending.entry > box_limit * WIDENING {
                continue;
            }
            if pending.count == 0 {
                let node = &self.nodes[pending.child as usize];
                let (mask, entry) = wide.enters(node, box_limit);
                stack.push_nearest_last(node, mask, entry);
                continue;
            }
            for slot in self.slots(pending) {
                let found = self.test(mesh, slot, ray, &sheared, triangle_limit);
                let id = self.ids[slot];
                if let Some(at) = found
                    && best.is_none_or(|b| (at.t, id) < (b.0, b.1))
                {
                    best = Some((at.t, id, at));
                    box_limit = round_up(at.t);
                    triangle_limit = at.t.next_up();
                }
            }
        }
        best.map(|(_, triangle, at)| MeshHit { triangle, at })
    }
    // ANCHOR_END: fast_traverse

    /// Whether `ray` meets any triangle of `mesh` closer than `t_max`, stopping at
    /// the first one found.
    pub fn occluded(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        let wide = WideRay::new(ray);
        let sheared = ShearedRay::new(ray);
        let limit = round_up(t_max);
        let mut stack = root_stack!();
        while let Some(pending) = stack.pop() {
            if pending.count == 0 {
                let node = &self.nodes[pending.child as usize];
                let (mut mask, _) = wide.enters(node, limit);
                while mask != 0 {
                    let lane = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    stack.push(Pending {
                        child: node.child[lane],
                        count: node.count[lane],
                        entry: 0.0,
                    });
                }
            } else if self
                .slots(pending)
                .any(|slot| self.test(mesh, slot, ray, &sheared, t_max).is_some())
            {
                return true;
            }
        }
        false
    }

    /// The triangle slots of a leaf.
    fn slots(&self, leaf: Pending) -> std::ops::Range<usize> {
        leaf.child as usize..leaf.child as usize + leaf.count as usize
    }

    /// The triangle in `slot` met by `ray` closer than `t_max`, with the mesh's test.
    #[inline]
    fn test(
        &self,
        mesh: &Mesh,
        slot: usize,
        ray: &Ray,
        sheared: &ShearedRay,
        t_max: Real,
    ) -> Option<TriangleHit> {
        let [a, b, c] = self.corners[slot];
        match mesh.triangle_test {
            TriangleTest::Watertight => sheared.intersect(a, b, c, t_max),
            TriangleTest::MollerTrumbore => intersect_triangle(ray, a, b, c, t_max),
        }
    }
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
