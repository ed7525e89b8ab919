//! What the chapter promises of a hierarchy over a mesh, whichever split built
//! it: the indices in range, every triangle in exactly one leaf, each leaf's box
//! around its triangles, each child's box inside its parent's, and leaves of at
//! most four triangles unless their centroids all fall on one side of the middle.

use course::acceleration::Bvh;
use course::acceleration::bvh::LEAF_SIZE;
use course::geometry::Aabb;
use course::meshes::Mesh;
use raycourse::maths::Vec3;

use super::super::{n, ulps, v};
use crate::say;

/// The deepest a hierarchy may go: the walk's stack holds 64 nodes.
const DEPTH: usize = 64;

/// The first promise that `bvh` breaks over `mesh`, in words, if any.
pub fn fault(bvh: &Bvh, mesh: &Mesh) -> Option<String> {
    order_fault(&bvh.order, mesh.triangles.len()).or_else(|| tree_fault(bvh, mesh))
}

/// Whether `order` lists each of `count` triangles once.
fn order_fault(order: &[u32], count: usize) -> Option<String> {
    let mut seen = vec![0; count];
    for &t in order {
        if t as usize >= count {
            return Some(say!(
                "generated-s6-hierarchy-bvh-order-lists-triangle-but-the",
                t = t,
                count = count
            ));
        }
        seen[t as usize] += 1;
    }
    let (lacks, twice) = (
        seen.iter().position(|&s| s == 0),
        seen.iter().position(|&s| s > 1),
    );
    match (lacks, twice) {
        (Some(t), _) => Some(say!(
            "generated-s6-hierarchy-bvh-order-lacks-triangle-every-triangle",
            t = t
        )),
        (_, Some(t)) => Some(say!(
            "generated-s6-hierarchy-bvh-order-lists-triangle-times-every",
            seen = seen[t],
            t = t
        )),
        _ => None,
    }
}

/// Walks the nodes from the root: the first broken promise, if any.
fn tree_fault(bvh: &Bvh, mesh: &Mesh) -> Option<String> {
    if bvh.nodes.is_empty() {
        return Some(say!(
            "generated-s6-hierarchy-the-hierarchy-has-no-node-node"
        ));
    }
    let mut covered = vec![false; bvh.order.len()];
    let mut pending = vec![(0, 1)];
    while let Some((index, depth)) = pending.pop() {
        if depth > DEPTH {
            return Some(say!(
                "generated-s6-hierarchy-the-hierarchy-is-deeper-than-levels",
                DEPTH = DEPTH,
                index = index
            ));
        }
        let node = bvh.nodes[index];
        let fault = if node.count > 0 {
            leaf_fault(bvh, mesh, index, &mut covered)
        } else {
            children_fault(bvh, index)
        };
        if fault.is_some() {
            return fault;
        }
        if node.count == 0 {
            let first = node.first as usize;
            pending.extend([(first, depth + 1), (first + 1, depth + 1)]);
        }
    }
    let slot = covered.iter().position(|&c| !c)?;
    Some(say!(
        "generated-s6-hierarchy-triangle-bvh-order-is-in-no",
        order_slot = bvh.order[slot],
        slot = slot
    ))
}

/// The promises of the leaf `index`: its range, its box, its size.
fn leaf_fault(bvh: &Bvh, mesh: &Mesh, index: usize, covered: &mut [bool]) -> Option<String> {
    let node = bvh.nodes[index];
    let range = node.first as usize..node.first as usize + node.count as usize;
    if range.end > covered.len() || covered[range.clone()].contains(&true) {
        return Some(say!(
            "generated-s6-hierarchy-leaf-node-covers-bvh-order-which",
            range_start = range.start,
            range_end = range.end,
            index = index
        ));
    }
    covered[range.clone()].fill(true);
    for &t in &bvh.order[range] {
        let corners = mesh.corners(t);
        if !holds(
            &node.bounds,
            &corners.iter().fold(Aabb::EMPTY, |b, &p| b.grow(p)),
        ) {
            let [a, b, c] = corners.map(v);
            return Some(say!(
                "generated-s6-hierarchy-the-box-of-leaf-node-to",
                node_bounds = v(node.bounds.min),
                node_bounds2 = v(node.bounds.max),
                index = index,
                t = t,
                a = a,
                b = b,
                c = c
            ));
        }
    }
    split_fault(bvh, mesh, index)
}

/// Whether the leaf `index` stopped where the chapter's rule stops: at
/// [`LEAF_SIZE`] triangles, or when every centroid falls on one side of the
/// middle of its box's longest side.
fn split_fault(bvh: &Bvh, mesh: &Mesh, index: usize) -> Option<String> {
    let node = bvh.nodes[index];
    if node.count as usize <= LEAF_SIZE {
        return None;
    }
    let range = node.first as usize..node.first as usize + node.count as usize;
    let centroids: Vec<Vec3> = bvh.order[range]
        .iter()
        .map(|&t| mesh.corners(t).iter().sum::<Vec3>() / 3.0)
        .collect();
    let bounds = node.bounds;
    let slack = ulps(8.0) * bounds.min.abs().max(bounds.max.abs()).max_element();
    let one_side = |axis: usize| {
        let middle = bounds.centre()[axis];
        centroids.iter().all(|c| c[axis] < middle + slack)
            || centroids.iter().all(|c| c[axis] >= middle - slack)
    };
    let axis = bounds.longest_axis();
    if one_side(axis) {
        return None;
    }
    let names = ["x", "y", "z"];
    let across = (0..3).find(|&a| one_side(a)).map_or(String::new(), |a| {
        say!(
            "generated-s6-hierarchy-if-yours-cut-it-along-where",
            names_a = names[a],
            names_axis = names[axis]
        )
    });
    Some(say!(
        "generated-s6-hierarchy-leaf-node-holds-triangles-its-box",
        node_count = node.count,
        bounds_axis = n((bounds.max - bounds.min)[axis]),
        names_axis = names[axis],
        index = index,
        LEAF_SIZE = LEAF_SIZE,
        across = across
    ))
}

/// Whether the inner node `index` has both children, each inside its box.
fn children_fault(bvh: &Bvh, index: usize) -> Option<String> {
    let node = bvh.nodes[index];
    let first = node.first as usize;
    if first + 1 >= bvh.nodes.len() {
        return Some(say!(
            "generated-s6-hierarchy-node-is-an-inner-node-count",
            first2 = first + 1,
            bvh_nodes = bvh.nodes.len(),
            index = index,
            first = first
        ));
    }
    let child = [first, first + 1]
        .into_iter()
        .find(|&c| !holds(&node.bounds, &bvh.nodes[c].bounds))?;
    Some(say!(
        "generated-s6-hierarchy-the-box-of-node-to-sticks",
        child_bounds = v(bvh.nodes[child].bounds.min),
        child_bounds2 = v(bvh.nodes[child].bounds.max),
        node_bounds = v(node.bounds.min),
        node_bounds2 = v(node.bounds.max),
        child = child,
        index = index
    ))
}

/// Whether `outer` holds `inner`, within a few roundings of their coordinates.
fn holds(outer: &Aabb, inner: &Aabb) -> bool {
    let slack = ulps(4.0) * inner.min.abs().max(inner.max.abs()).max_element();
    (inner.min - outer.min).min_element() >= -slack
        && (outer.max - inner.max).min_element() >= -slack
}
