//! A better-built hierarchy: splits chosen by the surface area heuristic, from
//! candidate planes binned along each axis (Wald 2007). The nodes and the traversal
//! are the course's ([`Bvh`]); only where each box is split changes.

use crate::acceleration::Bvh;
use crate::acceleration::bvh::{Node, partition};
use crate::geometry::Aabb;
use crate::maths::{Real, Vec3};
use crate::meshes::Mesh;

/// Candidate split planes per axis.
const BINS: usize = 16;

/// Cost of visiting one node, relative to testing one triangle.
const TRAVERSAL_COST: Real = 1.0;

/// One bin: the box of the triangles whose centroid falls in it, and how many.
#[derive(Clone, Copy)]
struct Bin {
    bounds: Aabb,
    count: usize,
}

/// The best split of a node: the axis, the bin index where the right side starts,
/// and its cost.
struct Split {
    axis: usize,
    bin: usize,
    cost: Real,
}

// ANCHOR: sah
/// Builds the hierarchy of `mesh` with the surface area heuristic. A node is
/// split where the expected cost of a random ray through it is least:
/// `c_trav + (S_left K_left + S_right K_right) / S`, with `S` the box areas and
/// `K` the triangle counts, over 16 candidate planes per axis (the triangles'
/// centroids sorted into bins). It becomes a leaf when no split is cheaper than
/// testing its `K` triangles, if it holds at most `max_leaf` of them. Where a
/// traversal tests `block` triangles at once, `K` counts blocks, `ceil(K / block)`:
/// a leaf of four costs what a leaf of one does when four are tested together.
pub fn build(mesh: &Mesh, max_leaf: usize, block: usize) -> Bvh {
    let boxes: Vec<Aabb> = (0..mesh.triangles.len() as u32)
        .map(|t| mesh.corners(t).into_iter().fold(Aabb::EMPTY, Aabb::grow))
        .collect();
    let centroids: Vec<Vec3> = boxes.iter().map(Aabb::centre).collect();
    let mut bvh = Bvh {
        nodes: Vec::with_capacity(2 * mesh.triangles.len()),
        order: (0..mesh.triangles.len() as u32).collect(),
    };
    let root = bounds_of(&bvh.order, &boxes);
    bvh.nodes.push(Node {
        bounds: root,
        first: 0,
        count: mesh.triangles.len() as u32,
    });
    let mut pending = vec![0];
    while let Some(index) = pending.pop() {
        let Node {
            bounds,
            first,
            count,
        } = bvh.nodes[index];
        let range = first as usize..(first + count) as usize;
        let items = &mut bvh.order[range];
        let Some(left) = sah_partition(items, &bounds, (&boxes, &centroids), (max_leaf, block))
        else {
            continue;
        };
        let children = bvh.nodes.len() as u32;
        for (start, size) in [
            (first as usize, left),
            (first as usize + left, count as usize - left),
        ] {
            let bounds = bounds_of(&bvh.order[start..start + size], &boxes);
            bvh.nodes.push(Node {
                bounds,
                first: start as u32,
                count: size as u32,
            });
        }
        bvh.nodes[index] = Node {
            bounds,
            first: children,
            count: 0,
        };
        pending.extend([children as usize, children as usize + 1]);
    }
    bvh
}
// ANCHOR_END: sah

/// Splits the node holding `items` (inside `bounds`) by the surface area heuristic:
/// moves the triangles of the left child to the front of `items` and returns how
/// many there are, or `None` when the node stays a leaf. `geometry` holds every
/// triangle's box and centroid; `limits` the most triangles in a leaf and the
/// block size of the leaf cost.
fn sah_partition(
    items: &mut [u32],
    bounds: &Aabb,
    (boxes, centroids): (&[Aabb], &[Vec3]),
    (max_leaf, block): (usize, usize),
) -> Option<usize> {
    let centre_bounds = items
        .iter()
        .fold(Aabb::EMPTY, |b, &t| b.grow(centroids[t as usize]));
    let leaf_cost = blocks(items.len(), block);
    let too_many = items.len() > max_leaf;
    match best_split(items, boxes, centroids, &centre_bounds, block) {
        Some(split) if TRAVERSAL_COST + split.cost / bounds.half_area() < leaf_cost || too_many => {
            let low = centre_bounds.min[split.axis];
            let extent = centre_bounds.max[split.axis] - low;
            Some(partition(items, |&t| {
                bin_of(centroids[t as usize][split.axis], low, extent) < split.bin
            }))
        }
        _ if too_many => Some(items.len() / 2),
        _ => None,
    }
}

/// The box around the triangles `items`.
fn bounds_of(items: &[u32], boxes: &[Aabb]) -> Aabb {
    items
        .iter()
        .fold(Aabb::EMPTY, |b, &t| b.union(&boxes[t as usize]))
}

/// The bin of a centroid coordinate `c` along an axis whose centroids span
/// `[low, low + extent]`.
fn bin_of(c: Real, low: Real, extent: Real) -> usize {
    (((c - low) / extent * BINS as Real) as usize).min(BINS - 1)
}

/// The cost of testing `count` triangles `block` at a time: `ceil(count / block)`.
fn blocks(count: usize, block: usize) -> Real {
    count.div_ceil(block) as Real
}

/// The cheapest of the `3 (BINS - 1)` candidate splits of `items`, with its cost
/// `S_left K_left + S_right K_right` (`K` in blocks of `block` triangles); `None`
/// when every centroid is the same point.
fn best_split(
    items: &[u32],
    boxes: &[Aabb],
    centroids: &[Vec3],
    centre_bounds: &Aabb,
    block: usize,
) -> Option<Split> {
    let mut best: Option<Split> = None;
    for axis in 0..3 {
        let low = centre_bounds.min[axis];
        let extent = centre_bounds.max[axis] - low;
        if extent <= 0.0 {
            continue;
        }
        let mut bins = [Bin {
            bounds: Aabb::EMPTY,
            count: 0,
        }; BINS];
        for &t in items {
            let bin = &mut bins[bin_of(centroids[t as usize][axis], low, extent)];
            bin.bounds = bin.bounds.union(&boxes[t as usize]);
            bin.count += 1;
        }
        // The right-hand sides, bins k.. for every k, swept from the last bin.
        let mut right_cost = [Real::INFINITY; BINS];
        let mut right = Bin {
            bounds: Aabb::EMPTY,
            count: 0,
        };
        for k in (1..BINS).rev() {
            right = merge(right, bins[k]);
            if right.count > 0 {
                right_cost[k] = right.bounds.half_area() * blocks(right.count, block);
            }
        }
        let mut left = bins[0];
        for k in 1..BINS {
            let cost = left.bounds.half_area() * blocks(left.count, block) + right_cost[k];
            if left.count > 0 && best.as_ref().is_none_or(|b| cost < b.cost) {
                best = Some(Split { axis, bin: k, cost });
            }
            left = merge(left, bins[k]);
        }
    }
    best
}

/// Two bins as one.
fn merge(a: Bin, b: Bin) -> Bin {
    Bin {
        bounds: a.bounds.union(&b.bounds),
        count: a.count + b.count,
    }
}
