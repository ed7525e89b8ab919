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
                "Bvh::order lists triangle {t}, but the mesh has {count}, numbered from 0",
                "Bvh::order liste le triangle {t}, mais le maillage en a {count}, numérotés depuis 0"
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
            "Bvh::order lacks triangle {t}: every triangle is in exactly one leaf",
            "il manque le triangle {t} dans Bvh::order\u{a0}: chaque triangle est dans exactement une feuille"
        )),
        (_, Some(t)) => Some(say!(
            "Bvh::order lists triangle {t} {} times: every triangle is in exactly one leaf",
            "Bvh::order liste {} fois le triangle {t}\u{a0}: chaque triangle est dans exactement une feuille",
            seen[t]
        )),
        _ => None,
    }
}

/// Walks the nodes from the root: the first broken promise, if any.
fn tree_fault(bvh: &Bvh, mesh: &Mesh) -> Option<String> {
    if bvh.nodes.is_empty() {
        return Some(say!(
            "the hierarchy has no node: node 0 is the root",
            "la hiérarchie n'a aucun nœud\u{a0}: le nœud 0 est la racine"
        ));
    }
    let mut covered = vec![false; bvh.order.len()];
    let mut pending = vec![(0, 1)];
    while let Some((index, depth)) = pending.pop() {
        if depth > DEPTH {
            return Some(say!(
                "the hierarchy is deeper than {DEPTH} levels at node {index}",
                "la hiérarchie dépasse {DEPTH} niveaux de profondeur au nœud {index}"
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
        "triangle {} (Bvh::order[{slot}]) is in no leaf, so no ray finds it: the leaves' ranges cover the whole of Bvh::order",
        "le triangle {} (Bvh::order[{slot}]) n'est dans aucune feuille, donc aucun rayon ne le trouve\u{a0}: les plages des feuilles couvrent tout Bvh::order",
        bvh.order[slot]
    ))
}

/// The promises of the leaf `index`: its range, its box, its size.
fn leaf_fault(bvh: &Bvh, mesh: &Mesh, index: usize, covered: &mut [bool]) -> Option<String> {
    let node = bvh.nodes[index];
    let range = node.first as usize..node.first as usize + node.count as usize;
    if range.end > covered.len() || covered[range.clone()].contains(&true) {
        return Some(say!(
            "leaf node {index} covers Bvh::order[{}..{}], which lies past its end or is another leaf's too: every triangle is in exactly one leaf",
            "la feuille du nœud {index} couvre Bvh::order[{}..{}], qui dépasse sa fin ou appartient aussi à une autre feuille\u{a0}: chaque triangle est dans exactement une feuille",
            range.start,
            range.end
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
                "the box of leaf node {index}, {} to {}, does not hold its triangle {t}, {a} {b} {c}: a leaf's box is the min and max of its triangles' corners",
                "la boîte de la feuille du nœud {index}, de {} à {}, ne contient pas son triangle {t}, {a} {b} {c}\u{a0}: la boîte d'une feuille est le min et le max des sommets de ses triangles",
                v(node.bounds.min),
                v(node.bounds.max)
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
            "; if yours cut it along {}, where they all fall on one side: the box is cut across its longest side, here {}",
            "\u{a0}; si la vôtre l'a coupée selon {}, où ils tombent tous d'un côté\u{a0}: la boîte est coupée en travers de son plus grand côté, ici {}",
            names[a],
            names[axis]
        )
    });
    Some(say!(
        "leaf node {index} holds {} triangles, its box {} long along {}, its longest side, with centroids on both sides of that side's middle: splitting stops at {LEAF_SIZE} triangles, or when every centroid falls on one side, whatever the box's size{across}",
        "la feuille du nœud {index} contient {} triangles, sa boîte longue de {} selon {}, son plus grand côté, avec des centroïdes des deux côtés du milieu de ce côté\u{a0}: la division s'arrête à {LEAF_SIZE} triangles, ou quand tous les centroïdes tombent d'un côté, quelle que soit la taille de la boîte{across}",
        node.count,
        n((bounds.max - bounds.min)[axis]),
        names[axis]
    ))
}

/// Whether the inner node `index` has both children, each inside its box.
fn children_fault(bvh: &Bvh, index: usize) -> Option<String> {
    let node = bvh.nodes[index];
    let first = node.first as usize;
    if first + 1 >= bvh.nodes.len() {
        return Some(say!(
            "node {index} is an inner node (count = 0) whose children, nodes {first} and {}, lie past the {} nodes",
            "le nœud {index} est un nœud interne (count = 0) dont les enfants, les nœuds {first} et {}, sont au-delà des {} nœuds",
            first + 1,
            bvh.nodes.len()
        ));
    }
    let child = [first, first + 1]
        .into_iter()
        .find(|&c| !holds(&node.bounds, &bvh.nodes[c].bounds))?;
    Some(say!(
        "the box of node {child}, {} to {}, sticks out of its parent's, node {index}, {} to {}: each child's box lies inside its parent's",
        "la boîte du nœud {child}, de {} à {}, dépasse de celle de son parent, le nœud {index}, de {} à {}\u{a0}: la boîte de chaque enfant est dans celle de son parent",
        v(bvh.nodes[child].bounds.min),
        v(bvh.nodes[child].bounds.max),
        v(node.bounds.min),
        v(node.bounds.max)
    ))
}

/// Whether `outer` holds `inner`, within a few roundings of their coordinates.
fn holds(outer: &Aabb, inner: &Aabb) -> bool {
    let slack = ulps(4.0) * inner.min.abs().max(inner.max.abs()).max_element();
    (inner.min - outer.min).min_element() >= -slack
        && (outer.max - inner.max).min_element() >= -slack
}
