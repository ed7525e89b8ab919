//! Session 6's mistakes: building and walking the hierarchy, the interpolated
//! normal.

use raycourse::acceleration::Bvh;
use raycourse::acceleration::bvh::{LEAF_SIZE, Node};
use raycourse::geometry::{Aabb, Ray, ShearedRay};
use raycourse::maths::{Real, Vec3};
use raycourse::meshes::{Mesh, MeshHit};

use super::Mistake;
use crate::generated;
use crate::s6::leaf_over;

/// Session 6's mistakes.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        exercise: "s6.1",
        what: "no split of a box under 1e-4 across (a fixed epsilon)",
        run: || {
            generated::bvh_build(|mesh| {
                build_cutting(mesh, |b| {
                    ((b.max - b.min).max_element() >= 1e-4).then(|| b.longest_axis())
                })
            })
        },
        rule: "rule-s6-1-whatever-the-box-s-size",
    },
    Mistake {
        exercise: "s6.1",
        what: "every box cut along x",
        run: || generated::bvh_build(|mesh| build_cutting(mesh, |_| Some(0))),
        rule: "rule-s6-1-the-box-is-cut-across",
    },
    Mistake {
        exercise: "s6.2",
        what: "the leaves' triangles tested without t_max",
        run: || {
            generated::bvh_nearest(|bvh, mesh, ray, t_max| {
                walk(bvh, mesh, ray, t_max, Walk::LeavesUnbounded)
            })
        },
        rule: "rule-s6-2-closer-than-t-max",
    },
    Mistake {
        exercise: "s6.2",
        what: "the walk ends at the first node entered beyond the nearest hit",
        run: || {
            generated::bvh_nearest(|bvh, mesh, ray, t_max| {
                walk(bvh, mesh, ray, t_max, Walk::StopsEarly)
            })
        },
        rule: "rule-s6-2-goes-on-with-the-rest",
    },
    Mistake {
        exercise: "s6.3",
        what: "b_B and b_C swapped",
        run: || {
            generated::smooth_normal(|mesh, t, [a, b, c], g| mesh.smooth_normal(t, [a, c, b], g))
        },
        rule: "rule-s6-3-weight-k-goes-with-corner",
    },
    Mistake {
        exercise: "s6.3",
        what: "the normals taken by corner number, normals[k]",
        run: || {
            generated::smooth_normal(|mesh, _, w, g| {
                let by_number = (0..3)
                    .map(|k| w[k] * mesh.normals.get(k).copied().unwrap_or(g))
                    .sum::<Vec3>();
                turned(by_number.try_normalize().unwrap_or(g), g)
            })
        },
        rule: "rule-s6-3-the-vertex-the-triangle-names",
    },
    Mistake {
        exercise: "s6.3",
        what: "no fallback where the normals cancel",
        run: || {
            generated::smooth_normal(|mesh, t, w, g| turned(blend(mesh, t, w, g).normalize(), g))
        },
        rule: "rule-s6-3-falls-back-to-the-geometric",
    },
    Mistake {
        exercise: "s6.3",
        what: "the blend not normalised",
        run: || {
            generated::smooth_normal(|mesh, t, w, g| {
                let blended = blend(mesh, t, w, g);
                if blended == Vec3::ZERO {
                    g
                } else {
                    turned(blended, g)
                }
            })
        },
        rule: "rule-s6-3-normalise-it",
    },
    Mistake {
        exercise: "s6.3",
        what: "the normal not turned to the geometric normal's side",
        run: || {
            generated::smooth_normal(|mesh, t, w, g| {
                blend(mesh, t, w, g).try_normalize().unwrap_or(g)
            })
        },
        rule: "rule-s6-3-turned-to-the-geometric-normal",
    },
];

/// The course's build, cutting each node's box across the axis that `cut`
/// chooses, or keeping it a leaf where `cut` gives none.
fn build_cutting(mesh: &Mesh, cut: fn(&Aabb) -> Option<usize>) -> Bvh {
    let centroid = |t: u32| mesh.corners(t).iter().sum::<Vec3>() / 3.0;
    let leaf = |order: &[u32], first, count| leaf_over(mesh, order, first, count);
    let mut order: Vec<u32> = (0..mesh.triangles.len() as u32).collect();
    let mut nodes = vec![leaf(&order, 0, order.len())];
    let mut pending = vec![0];
    while let Some(index) = pending.pop() {
        let Node {
            bounds,
            first,
            count,
        } = nodes[index];
        let (first, count) = (first as usize, count as usize);
        let Some(axis) = cut(&bounds).filter(|_| count > LEAF_SIZE) else {
            continue;
        };
        let middle = bounds.centre()[axis];
        let (left, right): (Vec<u32>, Vec<u32>) = order[first..first + count]
            .iter()
            .partition(|&&t| centroid(t)[axis] < middle);
        if left.is_empty() || right.is_empty() {
            continue;
        }
        let split = left.len();
        order[first..first + count].copy_from_slice(&[left, right].concat());
        let children = nodes.len();
        nodes.push(leaf(&order, first, split));
        nodes.push(leaf(&order, first + split, count - split));
        nodes[index] = Node {
            bounds,
            first: children as u32,
            count: 0,
        };
        pending.extend([children, children + 1]);
    }
    Bvh { nodes, order }
}

/// A mistake in the walk.
#[derive(Clone, Copy, PartialEq)]
enum Walk {
    /// The leaves' triangles are tested as far as infinity, whatever `t_max`.
    LeavesUnbounded,
    /// The walk ends, rather than goes on, at a node entered beyond the nearest hit.
    StopsEarly,
}

/// The course's walk with `mistake`: the nearer child visited first.
fn walk(bvh: &Bvh, mesh: &Mesh, ray: &Ray, t_max: Real, mistake: Walk) -> Option<MeshHit> {
    let (inv, sheared) = (ray.direction.recip(), ShearedRay::new(ray));
    let leaf_max = if mistake == Walk::LeavesUnbounded {
        Real::INFINITY
    } else {
        t_max
    };
    let mut best: Option<MeshHit> = None;
    let mut stack: Vec<(u32, Real)> = bvh.nodes[0]
        .bounds
        .entry(ray, inv, t_max)
        .map(|t| (0, t))
        .into_iter()
        .collect();
    while let Some((index, entry)) = stack.pop() {
        let limit = best.map_or(t_max, |b| b.at.t);
        if entry > limit && mistake == Walk::StopsEarly {
            break;
        } else if entry > limit {
            continue;
        }
        let node = bvh.nodes[index as usize];
        if node.count > 0 {
            let leaf = &bvh.order[node.first as usize..(node.first + node.count) as usize];
            best = mesh.nearest_among(ray, &sheared, leaf.iter().copied(), best, leaf_max);
            continue;
        }
        let mut entered: Vec<(u32, Real)> = [node.first, node.first + 1]
            .into_iter()
            .filter_map(|c| Some((c, bvh.nodes[c as usize].bounds.entry(ray, inv, limit)?)))
            .collect();
        entered.sort_by(|a, b| b.1.total_cmp(&a.1));
        stack.extend(entered);
    }
    best
}

/// `b_A N_A + b_B N_B + b_C N_C` over `triangle` of `mesh`, or `geometric`
/// without vertex normals.
fn blend(mesh: &Mesh, triangle: u32, weights: [Real; 3], geometric: Vec3) -> Vec3 {
    if mesh.normals.is_empty() {
        return geometric;
    }
    let corners = mesh.triangles[triangle as usize];
    (0..3)
        .map(|k| weights[k] * mesh.normals[corners[k] as usize])
        .sum()
}

/// `normal` turned to the side of `geometric`.
fn turned(normal: Vec3, geometric: Vec3) -> Vec3 {
    if normal.dot(geometric) < 0.0 {
        -normal
    } else {
        normal
    }
}
