//! The hierarchy laid out for speed: the same boxes as a [`Bvh`], stored as 32-byte
//! nodes in depth-first order, with each leaf's triangles copied next to each other.
//! It finds exactly the hits the course's traversal finds; only memory traffic and
//! bookkeeping shrink.

use glam::{BVec3A, Vec3A};

use crate::bvh::Bvh;
use crate::math::{Real, Vec3, to_single};
use crate::mesh::{Mesh, MeshHit};
use crate::ray::Ray;
use crate::triangle::{TriangleHit, TriangleTest, intersect_triangle};
use crate::watertight::ShearedRay;

/// Deepest tree the traversal's fixed stack allows; the SAH build stays far below.
const MAX_DEPTH: usize = 64;

/// One node: its box in single precision, rounded outwards so that it still holds
/// everything below it, and where its children or triangles are. Two nodes fit in
/// a 64-byte cache line.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(32))]
pub struct CompactNode {
    min: [f32; 3],
    max: [f32; 3],
    /// For a leaf, its first triangle slot; for an inner node, its second child
    /// (the first child is the next node).
    offset: u32,
    /// How many triangles a leaf holds; 0 for an inner node.
    count: u16,
    /// The axis along which an inner node was split: a ray going towards `-axis`
    /// visits the second child first.
    axis: u16,
}

/// A bounding volume hierarchy flattened for traversal.
#[derive(Clone, Debug, PartialEq)]
pub struct FastBvh {
    nodes: Vec<CompactNode>,
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

/// A ray in single precision, for the box tests: its origin rounded, with the
/// rounding's size, and its inverse direction.
struct SingleRay {
    origin: Vec3A,
    /// How far the rounded origin may be from the true one, per coordinate: boxes
    /// are grown by this much, so that none is missed for the rounding.
    slack: Vec3A,
    inv_direction: Vec3A,
    /// Which components of the direction are negative.
    negative: BVec3A,
}

impl SingleRay {
    fn new(ray: &Ray) -> SingleRay {
        let origin = ray.origin.to_array().map(to_single);
        let slack = [0, 1, 2].map(|i| round_up((ray.origin[i] - origin[i] as Real).abs()));
        let inv_direction = Vec3A::from_array(ray.direction.recip().to_array().map(to_single));
        SingleRay {
            origin: Vec3A::from_array(origin),
            slack: Vec3A::from_array(slack),
            inv_direction,
            negative: inv_direction.cmplt(Vec3A::ZERO),
        }
    }

    /// Whether the ray enters `node`'s box before `limit`: the slab test of
    /// [`Aabb::entry`] on three lanes at once. Each lane's distances carry at
    /// most three roundings, so the exit is widened by `1 + 2 gamma(3)`; a NaN
    /// lane (a ray in the plane of a face) is ignored by `max` and `min`.
    #[inline]
    fn enters(&self, node: &CompactNode, limit: f32) -> bool {
        let low = Vec3A::from_array(node.min) - self.slack;
        let high = Vec3A::from_array(node.max) + self.slack;
        let near = Vec3A::select(self.negative, high, low);
        let far = Vec3A::select(self.negative, low, high);
        let t0 = (near - self.origin) * self.inv_direction;
        let t1 = (far - self.origin) * self.inv_direction;
        let entry = t0.max_element().max(0.0);
        let exit = t1.min_element().min(limit) * WIDENING;
        entry <= exit
    }
}

/// `1 + 2 gamma(3)` in single precision, rounded up.
const WIDENING: f32 = 1.0 + 8.0 * f32::EPSILON;

impl FastBvh {
    /// The hierarchy of `mesh` built with the surface area heuristic
    /// ([`Bvh::build_sah`]), leaves of at most `max_leaf` triangles, flattened.
    pub fn build(mesh: &Mesh, max_leaf: u16) -> FastBvh {
        FastBvh::flattened(&Bvh::build_sah(mesh, max_leaf.into()), mesh)
    }

    /// `bvh`, whose leaves hold at most `u16::MAX` triangles, flattened.
    fn flattened(bvh: &Bvh, mesh: &Mesh) -> FastBvh {
        let mut fast = FastBvh {
            nodes: Vec::with_capacity(bvh.nodes.len()),
            corners: Vec::with_capacity(mesh.triangles.len()),
            ids: Vec::with_capacity(mesh.triangles.len()),
        };
        fast.flatten(bvh, mesh, 0, 0);
        fast
    }

    /// Appends node `index` of `bvh` and everything below it, depth first.
    fn flatten(&mut self, bvh: &Bvh, mesh: &Mesh, index: usize, depth: usize) {
        assert!(depth < MAX_DEPTH, "BVH deeper than {MAX_DEPTH} levels");
        let node = &bvh.nodes[index];
        let at = self.nodes.len();
        self.nodes.push(CompactNode {
            min: node.bounds.min.to_array().map(round_down),
            max: node.bounds.max.to_array().map(round_up),
            offset: 0,
            count: 0,
            axis: 0,
        });
        if node.count > 0 {
            self.nodes[at].offset = self.ids.len() as u32;
            self.nodes[at].count = node.count as u16;
            for &t in &bvh.order[node.first as usize..(node.first + node.count) as usize] {
                self.corners.push(mesh.corners(t));
                self.ids.push(t);
            }
        } else {
            let (left, right) = (node.first as usize, node.first as usize + 1);
            let centres = [left, right].map(|c| bvh.nodes[c].bounds.centre());
            let axis = (centres[1] - centres[0]).abs().max_position();
            self.flatten(bvh, mesh, left, depth + 1);
            self.nodes[at].offset = self.nodes.len() as u32;
            self.nodes[at].axis = axis as u16;
            self.flatten(bvh, mesh, right, depth + 1);
        }
    }

    // ANCHOR: fast_traverse
    /// The nearest triangle of `mesh` that `ray` meets closer than `t_max`: the same
    /// hit as [`Bvh::intersect`] (equal distances go to the lower triangle index).
    /// The near child is chosen by the sign of the direction along the node's split
    /// axis, so each box is tested once, when its node is reached.
    pub fn intersect(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        let single = SingleRay::new(ray);
        let sheared = ShearedRay::new(ray);
        let mut best: Option<(Real, u32, TriangleHit)> = None;
        let mut stack = [0u32; MAX_DEPTH];
        let mut depth = 0;
        let mut index = 0;
        // The box test's limit, and the triangle test's (which lets an equal
        // distance through, for the lower index to win).
        let mut box_limit = round_up(t_max);
        let mut triangle_limit = t_max;
        loop {
            let node = &self.nodes[index as usize];
            if single.enters(node, box_limit) {
                if node.count > 0 {
                    let first = node.offset as usize;
                    for slot in first..first + node.count as usize {
                        let [a, b, c] = self.corners[slot];
                        let found = match mesh.triangle_test {
                            TriangleTest::Watertight => sheared.intersect(a, b, c, triangle_limit),
                            TriangleTest::MollerTrumbore => {
                                intersect_triangle(ray, a, b, c, triangle_limit)
                            }
                        };
                        let id = self.ids[slot];
                        if let Some(at) = found
                            && best.is_none_or(|b| (at.t, id) < (b.0, b.1))
                        {
                            best = Some((at.t, id, at));
                            box_limit = round_up(at.t);
                            triangle_limit = at.t.next_up();
                        }
                    }
                } else {
                    let (near, far) = if single.negative.test(node.axis as usize) {
                        (node.offset, index + 1)
                    } else {
                        (index + 1, node.offset)
                    };
                    stack[depth] = far;
                    depth += 1;
                    index = near;
                    continue;
                }
            }
            if depth == 0 {
                break;
            }
            depth -= 1;
            index = stack[depth];
        }
        best.map(|(_, triangle, at)| MeshHit { triangle, at })
    }
    // ANCHOR_END: fast_traverse

    /// Whether `ray` meets any triangle of `mesh` closer than `t_max`, stopping at
    /// the first one found.
    pub fn occluded(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        let single = SingleRay::new(ray);
        let sheared = ShearedRay::new(ray);
        let limit = round_up(t_max);
        let mut stack = [0u32; MAX_DEPTH];
        let mut depth = 0;
        let mut index = 0;
        loop {
            let node = &self.nodes[index as usize];
            if single.enters(node, limit) {
                if node.count > 0 {
                    let first = node.offset as usize;
                    let hit = self.corners[first..first + node.count as usize].iter().any(
                        |&[a, b, c]| match mesh.triangle_test {
                            TriangleTest::Watertight => sheared.intersect(a, b, c, t_max).is_some(),
                            TriangleTest::MollerTrumbore => {
                                intersect_triangle(ray, a, b, c, t_max).is_some()
                            }
                        },
                    );
                    if hit {
                        return true;
                    }
                } else {
                    stack[depth] = node.offset;
                    depth += 1;
                    index += 1;
                    continue;
                }
            }
            if depth == 0 {
                return false;
            }
            depth -= 1;
            index = stack[depth];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nodes_are_32_bytes_and_boxes_round_outwards() {
        assert_eq!(std::mem::size_of::<CompactNode>(), 32);
        for x in [0.1, -0.1, 1e-30, 3.0, -1e20] {
            assert!(
                round_down(x) as Real <= x && x <= round_up(x) as Real,
                "{x}"
            );
        }
    }
}
