//! The bounding volume hierarchy of the course: boxes within boxes, so that a ray
//! tests the triangles of only the few boxes it passes through.

use smallvec::SmallVec;

use crate::geometry::{Aabb, Ray, ShearedRay};
use crate::maths::{Real, Vec3};
use crate::meshes::{Mesh, MeshHit, Search};

/// The most triangles a leaf holds: the course stops splitting at small leaves.
pub const LEAF_SIZE: usize = 4;

/// One box of the hierarchy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// The box around every triangle below this node.
    pub bounds: Aabb,
    /// For a leaf, the first of its entries in [`Bvh::order`]; for an inner node,
    /// the index of its first child (the second follows it).
    pub first: u32,
    /// For a leaf, how many triangles it holds; 0 for an inner node.
    pub count: u32,
}

/// A hierarchy stored flat: nodes in a `Vec`, children found by index, the root at 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    /// The nodes.
    pub nodes: Vec<Node>,
    /// Triangle indices, grouped so that each leaf's are contiguous.
    pub order: Vec<u32>,
}

impl Bvh {
    // ANCHOR: build
    /// Builds the hierarchy of `mesh` as the course does: a node's box is split in
    /// the middle of its longest side, its triangles go to the side of their
    /// centroid, and splitting stops at [`LEAF_SIZE`] triangles or when every
    /// centroid falls on one side.
    ///
    /// Exercise s6.1, building the BVH: book session 6, "BVH".
    pub fn build(mesh: &Mesh) -> Bvh {
        let centroids: Vec<Vec3> = (0..mesh.triangles.len() as u32)
            .map(|i| mesh.corners(i).iter().sum::<Vec3>() / 3.0)
            .collect();
        let mut bvh = Bvh {
            nodes: vec![],
            order: (0..mesh.triangles.len() as u32).collect(),
        };
        let mut pending = vec![bvh.push_leaf(mesh, 0, mesh.triangles.len())];
        while let Some(node) = pending.pop() {
            let Node {
                bounds,
                first,
                count,
            } = bvh.nodes[node];
            let (first, count) = (first as usize, count as usize);
            if count <= LEAF_SIZE {
                continue;
            }
            let axis = bounds.longest_axis();
            let middle = bounds.centre()[axis];
            let range = &mut bvh.order[first..first + count];
            let left = partition(range, |&t| centroids[t as usize][axis] < middle);
            if left == 0 || left == count {
                continue;
            }
            let children = bvh.nodes.len() as u32;
            bvh.push_leaf(mesh, first, left);
            bvh.push_leaf(mesh, first + left, count - left);
            bvh.nodes[node] = Node {
                bounds,
                first: children,
                count: 0,
            };
            pending.extend([children as usize, children as usize + 1]);
        }
        bvh
    }
    // ANCHOR_END: build

    /// Appends a leaf over `order[first..first + count]` and returns its index.
    fn push_leaf(&mut self, mesh: &Mesh, first: usize, count: usize) -> usize {
        let bounds = self.order[first..first + count]
            .iter()
            .flat_map(|&t| mesh.corners(t))
            .fold(Aabb::EMPTY, Aabb::grow);
        self.nodes.push(Node {
            bounds,
            first: first as u32,
            count: count as u32,
        });
        self.nodes.len() - 1
    }
}

impl Search for Bvh {
    fn name(&self) -> &'static str {
        "bvh"
    }

    // ANCHOR: traverse
    /// The nearest triangle of `mesh` that `ray` meets closer than `t_max`. Without
    /// recursion: a stack (on the call stack unless the tree is very deep) holds the
    /// nodes still to visit. Of two children, the one
    /// the ray enters first is visited first, and a node whose box the ray enters
    /// beyond the nearest hit found so far is skipped.
    ///
    /// Exercise s6.2, walking the BVH: book session 6, "BVH".
    fn nearest(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        let inv = ray.direction.recip();
        let sheared = ShearedRay::new(ray);
        let mut best: Option<MeshHit> = None;
        let mut stack: SmallVec<[(u32, Real); 64]> = SmallVec::new();
        if let Some(t) = self.nodes[0].bounds.entry(ray, inv, t_max) {
            stack.push((0, t));
        }
        while let Some((index, entry)) = stack.pop() {
            let limit = best.map_or(t_max, |b| b.at.t);
            if entry > limit {
                continue;
            }
            let node = self.nodes[index as usize];
            if node.count > 0 {
                let leaf = &self.order[node.first as usize..(node.first + node.count) as usize];
                best = mesh.nearest_among(ray, &sheared, leaf.iter().copied(), best, t_max);
                continue;
            }
            let [a, b] = [node.first, node.first + 1]
                .map(|c| (c, self.nodes[c as usize].bounds.entry(ray, inv, limit)));
            let (near, far) = match (a.1, b.1) {
                (Some(ta), Some(tb)) if tb < ta => (b, a),
                (None, _) => (b, a),
                _ => (a, b),
            };
            // The far child goes on the stack first, so the near one is visited first.
            for (child, entry) in [far, near] {
                if let Some(t) = entry {
                    stack.push((child, t));
                }
            }
        }
        best
    }
    // ANCHOR_END: traverse

    /// Whether `ray` meets any triangle of `mesh` closer than `t_max`: the same walk
    /// through the boxes, in any order, ending at the first triangle hit.
    fn occluded(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        let inv = ray.direction.recip();
        let sheared = ShearedRay::new(ray);
        let mut stack: SmallVec<[u32; 64]> = SmallVec::new();
        stack.push(0);
        while let Some(index) = stack.pop() {
            let node = self.nodes[index as usize];
            if node.bounds.entry(ray, inv, t_max).is_none() {
                continue;
            }
            if node.count > 0 {
                let leaf = &self.order[node.first as usize..(node.first + node.count) as usize];
                if mesh.hits_any(ray, &sheared, leaf.iter().copied(), t_max) {
                    return true;
                }
            } else {
                stack.extend([node.first, node.first + 1]);
            }
        }
        false
    }
}

/// Moves the elements for which `left` holds to the front of `items` and returns
/// how many there are (the order within each side is not kept).
pub(crate) fn partition(items: &mut [u32], left: impl Fn(&u32) -> bool) -> usize {
    let mut boundary = 0;
    for i in 0..items.len() {
        if left(&items[i]) {
            items.swap(i, boundary);
            boundary += 1;
        }
    }
    boundary
}
