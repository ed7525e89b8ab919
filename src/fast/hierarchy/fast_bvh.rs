//! The hierarchy laid out for speed: the SAH tree collapsed to eight children per
//! node, whose eight boxes a ray tests at once ([`WideNode`]), and each leaf's
//! triangles stored in groups of eight that a single-precision pre-test
//! ([`TriangleGroup`]) also tests at once, leaving the exact test only the
//! triangles the ray may meet. It finds exactly the hits the course's traversal
//! finds; only the number of steps and the memory traffic shrink.

use crate::acceleration::Bvh;
use crate::fast::hierarchy::sah;
use crate::fast::hierarchy::traversal_stack::{Bits, Pending, Stack};
use crate::fast::hierarchy::triangle_group::{GROUP, GroupRay, TriangleGroup, lanes};
use crate::fast::hierarchy::wide_node::{
    EightLanes, Limit, WIDTH, WideNode, WideRay, round_down, round_up,
};
use crate::fast::lanes::{LaneKind, Lanes, OnLanes};
use crate::geometry::{Ray, ShearedRay, TriangleTest};
use crate::maths::{Real, Vec3};
use crate::meshes::{Mesh, MeshHit, Search};

/// A bounding volume hierarchy flattened for traversal.
#[derive(Clone, Debug, PartialEq)]
pub struct FastBvh {
    /// The nodes, the root first.
    nodes: Vec<WideNode>,
    /// Each leaf's triangles in groups of eight, in single precision, for the
    /// pre-test; group `g` holds slots `8 g` to `8 g + 7`.
    groups: Vec<TriangleGroup>,
    /// The mesh's index of the triangle in every slot, for the exact test on the
    /// mesh's own corners. A leaf's last group is padded with its last triangle.
    ids: Vec<u32>,
    /// How the traversal tests boxes and triangle groups.
    lanes: Lanes,
}

impl FastBvh {
    /// The hierarchy of `mesh` built with the surface area heuristic
    /// ([`sah::build`]), leaves of at most `max_leaf` triangles, collapsed to
    /// eight children per node, its boxes and triangles tested in the fastest lanes
    /// this processor has.
    pub fn build(mesh: &Mesh, max_leaf: u16) -> FastBvh {
        let bvh = sah::build(mesh, max_leaf.into(), GROUP);
        let mut fast = FastBvh {
            nodes: vec![],
            groups: vec![],
            ids: Vec::with_capacity(mesh.triangles.len()),
            lanes: Lanes::fastest(),
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

    /// The same hierarchy with its tests made in `lanes`: to compare them,
    /// or to test the portable lanes on a processor that has faster ones.
    pub fn with_lanes(self, lanes: Lanes) -> FastBvh {
        FastBvh { lanes, ..self }
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

    /// Starts loading the children of `node` whose bit is set in `mask`, nodes or
    /// a leaf's first triangle group, so that each is in the cache by the time the
    /// search reaches it, the nearest while the others are pushed. A hint, which
    /// changes no result.
    #[inline(always)]
    fn prefetch_children(&self, tests: impl EightLanes, node: &WideNode, mask: u32) {
        for lane in Bits(mask) {
            let child = node.child[lane] as usize;
            match node.count[lane] {
                0 => tests.prefetch(&self.nodes[child]),
                _ => tests.prefetch(&self.groups[child]),
            }
        }
    }

    /// The triangle groups of a leaf: group `g` holds slots `8 g` to `8 g + 7`.
    #[inline]
    fn groups_of(leaf: Pending) -> std::ops::Range<usize> {
        let first = leaf.child as usize;
        first..first + (leaf.count as usize).div_ceil(GROUP)
    }

    /// The lanes of group `g` of `leaf` whose triangle the ray may meet (bit `i` for
    /// slot `8 g + i`): those the single-precision pre-test keeps
    /// ([`TriangleGroup::candidates`]) when there is a pre-test ray, every filled
    /// lane otherwise.
    #[inline(always)]
    fn candidates(
        &self,
        tests: impl EightLanes,
        leaf: Pending,
        g: usize,
        ray: Option<&GroupRay>,
    ) -> u32 {
        let filled = lanes(leaf.count as usize - (g - leaf.child as usize) * GROUP);
        match ray {
            Some(ray) => filled & tests.candidates(&self.groups[g], ray),
            None => filled,
        }
    }
}

impl Search for FastBvh {
    fn name(&self) -> &'static str {
        "fast"
    }

    fn nearest(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        self.lanes.run(Nearest(Query::new(self, mesh, ray, t_max)))
    }

    fn occluded(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        self.lanes.run(Occluded(Query::new(self, mesh, ray, t_max)))
    }
}

/// A search of the fast hierarchy: a ray against a mesh, up to `t_max`.
struct Query<'a> {
    bvh: &'a FastBvh,
    mesh: &'a Mesh,
    ray: &'a Ray,
    t_max: Real,
}

impl<'a> Query<'a> {
    /// The search of `bvh` for `ray` against `mesh`, up to `t_max`.
    fn new(bvh: &'a FastBvh, mesh: &'a Mesh, ray: &'a Ray, t_max: Real) -> Query<'a> {
        Query {
            bvh,
            mesh,
            ray,
            t_max,
        }
    }
}

/// The nearest hit of a query, on any lanes ([`FastBvh::nearest_with`]).
struct Nearest<'a>(Query<'a>);

impl OnLanes for Nearest<'_> {
    type Output = Option<MeshHit>;

    #[inline(always)]
    fn on<L: LaneKind>(self, lanes: L) -> Option<MeshHit> {
        let query = self.0;
        query
            .bvh
            .nearest_with(lanes, query.mesh, query.ray, query.t_max)
    }
}

/// Whether a query's ray meets anything, on any lanes ([`FastBvh::occluded_with`]).
struct Occluded<'a>(Query<'a>);

impl OnLanes for Occluded<'_> {
    type Output = bool;

    #[inline(always)]
    fn on<L: LaneKind>(self, lanes: L) -> bool {
        let query = self.0;
        query
            .bvh
            .occluded_with(lanes, query.mesh, query.ray, query.t_max)
    }
}

impl FastBvh {
    // ANCHOR: fast_traverse
    /// The nearest triangle of `mesh` that `ray` meets closer than `t_max`: the same
    /// hit as the course's [`Bvh`] (equal distances go to the lower triangle index),
    /// with the boxes and triangle groups tested by `tests`. A ray that misses the
    /// mesh's box (most rays, in a room where the mesh is small) is turned away by
    /// that one slab test, as the course's bounding box does, before anything else
    /// is computed for it. Of the children a ray enters, the nearest is visited next
    /// and the others wait on the stack, nearer ones on top, all of them asked of
    /// the memory at once; a child is skipped when popped if a hit found meanwhile
    /// is closer than its box. In a leaf, only the triangles the pre-test keeps get
    /// the exact test.
    #[inline(always)]
    fn nearest_with(
        &self,
        tests: impl EightLanes,
        mesh: &Mesh,
        ray: &Ray,
        t_max: Real,
    ) -> Option<MeshHit> {
        let inv_direction = ray.direction.recip();
        mesh.bounds.entry(ray, inv_direction, t_max)?;
        let wide = WideRay::new(ray, inv_direction);
        let mut leaf_rays = LeafRays::default();
        let mut best: Option<MeshHit> = None;
        // The box test's limit, and the triangle test's (which lets an equal
        // distance through, for the lower index to win).
        let mut box_limit = Limit::new(t_max);
        let mut triangle_limit = t_max;
        let mut stack = Stack::default();
        let mut next = Some(Pending::ROOT);
        while let Some(pending) = next.take().or_else(|| stack.pop()) {
            if pending.entry > box_limit.0 {
                continue;
            }
            if pending.count == 0 {
                let node = &self.nodes[pending.child as usize];
                let (mask, entry) = tests.enters(&wide, node, box_limit);
                self.prefetch_children(tests, node, mask);
                next = stack.push_all_but_nearest(node, mask, entry);
                continue;
            }
            let (sheared, group_ray) = leaf_rays.get(mesh, ray);
            for g in FastBvh::groups_of(pending) {
                for lane in Bits(self.candidates(tests, pending, g, group_ray)) {
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
    /// the first one found; the boxes and triangle groups tested by `tests`, and the
    /// children a ray enters asked of the memory at once, as in the nearest hit's
    /// search.
    #[inline(always)]
    fn occluded_with(&self, tests: impl EightLanes, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        let inv_direction = ray.direction.recip();
        if mesh.bounds.entry(ray, inv_direction, t_max).is_none() {
            return false;
        }
        let wide = WideRay::new(ray, inv_direction);
        let mut leaf_rays = LeafRays::default();
        let limit = Limit::new(t_max);
        let mut stack = Stack::default();
        stack.push(Pending::ROOT);
        while let Some(pending) = stack.pop() {
            if pending.count == 0 {
                let node = &self.nodes[pending.child as usize];
                let (mask, _) = tests.enters(&wide, node, limit);
                self.prefetch_children(tests, node, mask);
                stack.push_all(node, mask);
                continue;
            }
            let (sheared, group_ray) = leaf_rays.get(mesh, ray);
            for g in FastBvh::groups_of(pending) {
                for lane in Bits(self.candidates(tests, pending, g, group_ray)) {
                    let triangle = self.ids[GROUP * g + lane];
                    if mesh.hit_triangle(ray, sheared, triangle, t_max).is_some() {
                        return true;
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
/// largest box first, until there are eight: the children of one wide node.
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
    fn nodes_are_four_cache_lines() {
        assert_eq!(std::mem::size_of::<WideNode>(), 256);
    }
}
