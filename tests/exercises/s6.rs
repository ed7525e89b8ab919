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
        french: ["la construction de la BVH", "séance 6, «\u{a0}BVH\u{a0}»"],
    },
    Exercise {
        id: "s6.2",
        name: "s6_2_bvh_nearest",
        shown_by: "bvh",
        needs: &[],
        check: walk,
        french: ["le parcours de la BVH", "séance 6, «\u{a0}BVH\u{a0}»"],
    },
    Exercise {
        id: "s6.3",
        name: "s6_3_mesh_smooth_normal",
        shown_by: "smooth-normals",
        needs: &[],
        check: smooth_normal,
        french: [
            "la normale interpolée",
            "séance 6, «\u{a0}Normales lissées\u{a0}»",
        ],
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
            say!(
                "Bvh::order holds the triangle number {t}, but Spot has {n}",
                "Bvh::order contient le triangle numéro {t}, mais Spot n'en a que {n}"
            )
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
            "Bvh::order must list each of Spot's {n} triangles once: it has {} entries, lacks triangle {missing} and lists triangle {twice} more than once",
            "Bvh::order doit lister une fois chacun des {n} triangles de Spot\u{a0}: il compte {} entrées, il lui manque le triangle {missing} et il liste plus d'une fois le triangle {twice}",
            bvh.order.len()
        )
    })?;
    ensure(!bvh.nodes.is_empty(), || {
        say!(
            "the hierarchy has no node: node 0 is the root",
            "la hiérarchie n'a aucun nœud\u{a0}: le nœud 0 est la racine"
        )
    })?;
    let (mut leaves, mut covered) = (0, vec![false; n]);
    let mut pending = vec![(0usize, 1usize)];
    while let Some((index, depth)) = pending.pop() {
        ensure(depth <= 64, || {
            say!(
                "the hierarchy is deeper than 64 levels at node {index}",
                "la hiérarchie dépasse 64 niveaux de profondeur au nœud {index}"
            )
        })?;
        let node: Node = *bvh.nodes.get(index).ok_or_else(|| {
            say!(
                "a node points to node {index}, past the {} nodes",
                "un nœud pointe vers le nœud {index}, au-delà des {} nœuds",
                bvh.nodes.len()
            )
        })?;
        if node.count > 0 {
            leaves += 1;
            let range = node.first as usize..(node.first + node.count) as usize;
            for slot in range.clone() {
                ensure(slot < n && !covered[slot], || {
                    say!(
                        "the leaf at node {index} covers Bvh::order[{}..{}], which another leaf covers too or lies past the end",
                        "la feuille du nœud {index} couvre Bvh::order[{}..{}], qu'une autre feuille couvre aussi ou qui dépasse la fin",
                        range.start,
                        range.end
                    )
                })?;
                covered[slot] = true;
                let corners = mesh.corners(bvh.order[slot]);
                let around = corners.iter().fold(Aabb::EMPTY, |b, &p| b.grow(p));
                ensure(holds(&node.bounds, &around), || {
                    say!(
                        "the box of leaf node {index}, {} to {}, does not hold its triangle {}",
                        "la boîte de la feuille du nœud {index}, de {} à {}, ne contient pas son triangle {}",
                        vec(node.bounds.min),
                        vec(node.bounds.max),
                        bvh.order[slot]
                    )
                })?;
            }
        } else {
            for child in [node.first as usize, node.first as usize + 1] {
                let inner = bvh.nodes.get(child).ok_or_else(|| {
                    say!(
                        "node {index} points to node {child}, past the {} nodes: an inner node's children are the nodes first and first + 1, pushed side by side when it is split",
                        "le nœud {index} pointe vers le nœud {child}, au-delà des {} nœuds\u{a0}: les enfants d'un nœud interne sont les nœuds first et first + 1, ajoutés côte à côte quand on le divise",
                        bvh.nodes.len()
                    )
                })?;
                ensure(holds(&node.bounds, &inner.bounds), || {
                    say!(
                        "the box of node {child} sticks out of its parent's, node {index}",
                        "la boîte du nœud {child} dépasse de celle de son parent, le nœud {index}"
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
            "triangle {triangle} (Bvh::order[{slot}]) is in no leaf: a ray can never find it; the leaves' ranges must cover the whole of Bvh::order",
            "le triangle {triangle} (Bvh::order[{slot}]) n'est dans aucune feuille\u{a0}: aucun rayon ne peut le trouver\u{a0}; les plages des feuilles doivent couvrir tout Bvh::order"
        )
    })?;
    ensure(leaves >= n / 16, || {
        say!(
            "Spot's {n} triangles end in {leaves} leaves: expected the boxes split until about 4 triangles a leaf",
            "les {n} triangles de Spot aboutissent dans {leaves} feuilles\u{a0}: attendu des boîtes divisées jusqu'à environ 4 triangles par feuille"
        )
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
                (Some(t), Some(e)) if t > e => say!(
                    ": a nearer hit lies in a node the walk left for later; go on with the rest of the stack, and skip only the nodes entered beyond the nearest hit so far",
                    "\u{a0}: une intersection plus proche se trouve dans un nœud que le parcours a laissé pour plus tard\u{a0}; continuez avec le reste de la pile, en ne sautant que les nœuds où le rayon entre au-delà de l'intersection la plus proche trouvée"
                ),
                (None, Some(_)) => say!(
                    ": every node whose box the ray enters must be walked, and each leaf's triangles tested",
                    "\u{a0}: chaque nœud dont le rayon traverse la boîte doit être parcouru, et les triangles de chaque feuille testés"
                ),
                _ => String::new(),
            };
            say!(
                "ray {k} at Spot, from {} along {}: the walk gave {}, testing every triangle {}{why}",
                "rayon {k} vers Spot, issu de {} selon {}\u{a0}: le parcours donne {}, le test de chaque triangle {}{why}",
                vec(ray.origin),
                vec(ray.direction),
                maybe(gave),
                maybe(expected)
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
            [
                "at A, weights (1, 0, 0)",
                "en A, poids (1\u{a0}; 0\u{a0}; 0)",
            ],
            [1.0, 0.0, 0.0],
            Vec3::Z,
            Vec3::Z,
        ),
        (
            [
                "halfway along BC, weights (0, 0.5, 0.5)",
                "au milieu de BC, poids (0\u{a0}; 0,5\u{a0}; 0,5)",
            ],
            [0.0, 0.5, 0.5],
            Vec3::Z,
            middle,
        ),
        (
            [
                "at the centre, weights (1/3, 1/3, 1/3)",
                "au centre, poids (1/3\u{a0}; 1/3\u{a0}; 1/3)",
            ],
            [third, third, third],
            Vec3::Z,
            centre,
        ),
        (
            [
                "at the centre, seen from below (the shading normal is turned to the side the geometric normal faces)",
                "au centre, vu de dessous (la normale d'ombrage est tournée du côté où regarde la normale géométrique)",
            ],
            [third, third, third],
            -Vec3::Z,
            -centre,
        ),
    ];
    for ([what, quoi], weights, geometric, expected) in cases {
        close_vec(
            &say!(
                "the triangle's shading normal {what}",
                "la normale d'ombrage du triangle {quoi}"
            ),
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
        &say!(
            "a triangle without vertex normals",
            "un triangle sans normales aux sommets"
        ),
        flat.smooth_normal(0, [third; 3], Vec3::Z),
        Vec3::Z,
        1e-9,
    )?;
    generated::smooth_normal(Mesh::smooth_normal)
}
