//! Session 6: building and walking the BVH, the interpolated normal.

use std::path::Path;

use raycourse::acceleration::Bvh;
use raycourse::acceleration::bvh::Node;
use raycourse::geometry::{Aabb, Ray};
use raycourse::maths::{Mat3, Real, Vec3};
use raycourse::meshes::{BruteForce, Mesh, ObjData, Placement, Search, read_obj};

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, close_vec, ensure, maybe, vec};
use crate::say;

/// Session 6's exercises, in the book's order.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "s6.1",
        name: "s6_1_bvh_build",
        shown_by: "bvh",
        needs: &[],
        check: build,
    },
    Exercise {
        id: "s6.2",
        name: "s6_2_bvh_nearest",
        shown_by: "bvh",
        needs: &[],
        check: walk,
    },
    Exercise {
        id: "s6.3",
        name: "s6_3_mesh_smooth_normal",
        shown_by: "smooth-normals",
        needs: &[],
        check: smooth_normal,
    },
];

/// Where a mesh stands as read: no scale, no turn, no move.
pub const AS_READ: Placement = Placement {
    scale: 1.0,
    rotation: Mat3::IDENTITY,
    translation: Vec3::ZERO,
};

/// Spot the cow, 5,856 triangles, as the mesh stages read it.
fn spot() -> Mesh {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/spot/spot.obj");
    Mesh::new(
        &read_obj(&path).expect("assets/spot/spot.obj reads"),
        &AS_READ,
    )
}

/// Whether `outer` holds `inner`, to rounding.
fn holds(outer: &Aabb, inner: &Aabb) -> bool {
    let slack = 1e-9 * (outer.max - outer.min).max_element().max(1.0);
    (inner.min - outer.min).min_element() >= -slack
        && (outer.max - inner.max).min_element() >= -slack
}

/// A hierarchy over Spot: every triangle in exactly one leaf, each leaf's box
/// around its triangles, each child's box inside its parent's, and split into
/// many leaves (at least one per 16 triangles), at most 64 levels deep (the
/// walk's stack).
fn build() -> Outcome {
    let mesh = spot();
    let bvh = Bvh::build(&mesh);
    let n = mesh.triangles.len();
    let mut seen = vec![0u32; n];
    for &t in &bvh.order {
        ensure((t as usize) < n, || {
            say!("s6-bvh-order-holds-the-triangle-number", t = t, n = n)
        })?;
        seen[t as usize] += 1;
    }
    ensure(bvh.order.len() == n && seen.iter().all(|&s| s == 1), || {
        let missing = seen
            .iter()
            .position(|&s| s == 0)
            .map_or("-".into(), |t| t.to_string());
        let twice = seen
            .iter()
            .position(|&s| s > 1)
            .map_or("-".into(), |t| t.to_string());
        say!(
            "s6-bvh-order-must-list-each-of",
            bvh_order = bvh.order.len(),
            n = n,
            missing = missing,
            twice = twice
        )
    })?;
    ensure(!bvh.nodes.is_empty(), || {
        say!("s6-the-hierarchy-has-no-node-node")
    })?;
    let (mut leaves, mut covered) = (0, vec![false; n]);
    let mut pending = vec![(0usize, 1usize)];
    while let Some((index, depth)) = pending.pop() {
        ensure(depth <= 64, || {
            say!("s6-the-hierarchy-is-deeper-than-64", index = index)
        })?;
        let node: Node = *bvh.nodes.get(index).ok_or_else(|| {
            say!(
                "s6-a-node-points-to-node-past",
                bvh_nodes = bvh.nodes.len(),
                index = index
            )
        })?;
        if node.count > 0 {
            leaves += 1;
            let range = node.first as usize..(node.first + node.count) as usize;
            for slot in range.clone() {
                ensure(slot < n && !covered[slot], || {
                    say!(
                        "s6-the-leaf-at-node-covers-bvh",
                        range_start = range.start,
                        range_end = range.end,
                        index = index
                    )
                })?;
                covered[slot] = true;
                let corners = mesh.corners(bvh.order[slot]);
                let around = corners.iter().fold(Aabb::EMPTY, |b, &p| b.grow(p));
                ensure(holds(&node.bounds, &around), || {
                    say!(
                        "s6-the-box-of-leaf-node-to",
                        node_bounds = vec(node.bounds.min),
                        node_bounds2 = vec(node.bounds.max),
                        order_slot = bvh.order[slot],
                        index = index
                    )
                })?;
            }
        } else {
            for child in [node.first as usize, node.first as usize + 1] {
                let inner = bvh.nodes.get(child).ok_or_else(|| {
                    say!(
                        "s6-node-points-to-node-past-the",
                        bvh_nodes = bvh.nodes.len(),
                        index = index,
                        child = child
                    )
                })?;
                ensure(holds(&node.bounds, &inner.bounds), || {
                    say!(
                        "s6-the-box-of-node-sticks-out",
                        child = child,
                        index = index
                    )
                })?;
                pending.push((child, depth + 1));
            }
        }
    }
    ensure(covered.iter().all(|&c| c), || {
        let slot = covered.iter().position(|&c| !c).unwrap_or(0);
        let triangle = bvh.order[slot];
        say!(
            "s6-triangle-bvh-order-is-in-no",
            triangle = triangle,
            slot = slot
        )
    })?;
    ensure(leaves >= n / 16, || {
        say!("s6-spot-s-triangles-end-in-leaves", n = n, leaves = leaves)
    })?;
    generated::bvh_build(Bvh::build)
}

/// A leaf of a hierarchy of `mesh` over `order[first..first + count]`: the box
/// around those triangles.
pub fn leaf_over(mesh: &Mesh, order: &[u32], first: usize, count: usize) -> Node {
    Node {
        bounds: order[first..first + count]
            .iter()
            .flat_map(|&t| mesh.corners(t))
            .fold(Aabb::EMPTY, Aabb::grow),
        first: first as u32,
        count: count as u32,
    }
}

/// A hierarchy made without the exercise's build: each node's triangles halved in
/// the order of the file, a leaf at four or fewer. Its boxes overlap, but it is a
/// hierarchy all the same, and the walk must find in it what testing every
/// triangle finds.
fn halving(mesh: &Mesh) -> Bvh {
    let leaf = |order: &[u32], first, count| leaf_over(mesh, order, first, count);
    let order: Vec<u32> = (0..mesh.triangles.len() as u32).collect();
    let mut nodes = vec![leaf(&order, 0, order.len())];
    let mut pending = vec![0];
    while let Some(index) = pending.pop() {
        let Node {
            bounds,
            first,
            count,
        } = nodes[index];
        if count <= 4 {
            continue;
        }
        let (first, half) = (first as usize, count as usize / 2);
        let children = nodes.len();
        nodes.push(leaf(&order, first, half));
        nodes.push(leaf(&order, first + half, count as usize - half));
        nodes[index] = Node {
            bounds,
            first: children as u32,
            count: 0,
        };
        pending.extend([children, children + 1]);
    }
    Bvh { nodes, order }
}

/// 400 rays at Spot from all around, aimed at points spread through its box: the
/// walk finds the hit that testing every triangle finds (the same distance), and
/// no hit where there is none.
fn walk() -> Outcome {
    let mesh = spot();
    let bvh = halving(&mesh);
    let (centre, size) = (
        mesh.bounds.centre(),
        (mesh.bounds.max - mesh.bounds.min).length(),
    );
    for k in 0..400 {
        let (a, b) = (k as Real * 2.399_963, 1.0 - 2.0 * (k as Real + 0.5) / 400.0);
        let from = centre
            + size
                * Vec3::new(
                    a.cos() * (1.0 - b * b).sqrt(),
                    b,
                    a.sin() * (1.0 - b * b).sqrt(),
                );
        let aim = centre
            + 0.4
                * (mesh.bounds.max - mesh.bounds.min)
                * Vec3::new(
                    (k as Real * 0.7).sin(),
                    (k as Real * 1.3).cos(),
                    (k as Real * 2.1).sin(),
                );
        let ray = Ray::new(from, aim - from);
        let gave = bvh.nearest(&mesh, &ray, Real::INFINITY).map(|h| h.at.t);
        let expected = BruteForce
            .nearest(&mesh, &ray, Real::INFINITY)
            .map(|h| h.at.t);
        let right = match (gave, expected) {
            (Some(t), Some(e)) => (t - e).abs() <= 1e-9 * e.max(1.0),
            (None, None) => true,
            _ => false,
        };
        ensure(right, || {
            let why = match (gave, expected) {
                (Some(t), Some(e)) if t > e => say!("s6-a-nearer-hit-lies-in-a"),
                (None, Some(_)) => say!("s6-every-node-whose-box-the-ray"),
                _ => String::new(),
            };
            say!(
                "s6-ray-at-spot-from-along-the",
                ray_origin = vec(ray.origin),
                ray_direction = vec(ray.direction),
                maybe_gave = maybe(gave),
                maybe_expected = maybe(expected),
                k = k,
                why = why
            )
        })?;
    }
    generated::bvh_nearest(Bvh::nearest)
}

/// One triangle `(0, 0, 0), (1, 0, 0), (0, 1, 0)` with the vertex normals
/// `N_A = (0, 0, 1)`, `N_B = (1, 0, 1) / sqrt 2`, `N_C = (0, 1, 1) / sqrt 2`: at `A`
/// the normal is `N_A`; halfway along `BC`, `(0.5, 0.5, 1) / sqrt 1.5`; at the
/// centre, `(0.2706, 0.2706, 0.9239)` (`N_A + N_B + N_C` normalised); seen from
/// below (geometric normal `-z`) the same normal turned over; without vertex
/// normals, the geometric one.
fn smooth_normal() -> Outcome {
    let s = (0.5 as Real).sqrt();
    let data = ObjData {
        positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y],
        normals: vec![Vec3::Z, Vec3::new(s, 0.0, s), Vec3::new(0.0, s, s)],
        uvs: vec![],
        triangles: vec![[0, 1, 2]],
        diffuse_texture: None,
    };
    let mesh = Mesh::new(&data, &AS_READ);
    let third = 1.0 / 3.0;
    let middle = Vec3::new(0.5, 0.5, 1.0) / (1.5 as Real).sqrt();
    let centre = Vec3::new(0.270_598, 0.270_598, 0.923_880);
    let cases = [
        (
            say!("s6-case-at-a-weights-1-0-0"),
            [1.0, 0.0, 0.0],
            Vec3::Z,
            Vec3::Z,
        ),
        (
            say!("s6-case-halfway-along-bc-weights-0-0"),
            [0.0, 0.5, 0.5],
            Vec3::Z,
            middle,
        ),
        (
            say!("s6-case-at-the-centre-weights-1-3"),
            [third, third, third],
            Vec3::Z,
            centre,
        ),
        (
            say!("s6-case-at-the-centre-seen-from-below"),
            [third, third, third],
            -Vec3::Z,
            -centre,
        ),
    ];
    for (what, weights, geometric, expected) in cases {
        close_vec(
            &say!("s6-the-triangle-s-shading-normal", what = what),
            mesh.smooth_normal(0, weights, geometric),
            expected,
            1e-5,
        )?;
    }
    let flat = Mesh::new(
        &ObjData {
            normals: vec![],
            ..data
        },
        &AS_READ,
    );
    close_vec(
        &say!("s6-a-triangle-without-vertex-normals"),
        flat.smooth_normal(0, [third; 3], Vec3::Z),
        Vec3::Z,
        1e-9,
    )?;
    generated::smooth_normal(Mesh::smooth_normal)
}
