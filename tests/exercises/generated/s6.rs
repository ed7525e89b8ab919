//! Session 6 on generated inputs: the hierarchy's build and walk on generated
//! meshes, the interpolated normal on generated triangles.

mod hierarchy;
mod meshes;

use course::meshes::Search;
use raycourse::acceleration::Bvh;
use raycourse::acceleration::bvh::Node;
use raycourse::geometry::{Aabb, Ray};
use raycourse::maths::{Real, Vec3};
use raycourse::meshes::{Mesh, MeshHit};

use super::{differs, n, near_vec, on_generated, ulps, v};
use crate::known::Outcome;
use crate::say;
use meshes::{Aim, Generated, Shot, aims, describe_shot};

/// The course's copy of the student's hierarchy.
fn course_bvh(bvh: &Bvh) -> course::acceleration::Bvh {
    let node = |n: &Node| course::acceleration::bvh::Node {
        bounds: course::geometry::Aabb {
            min: n.bounds.min,
            max: n.bounds.max,
        },
        first: n.first,
        count: n.count,
    };
    course::acceleration::Bvh {
        nodes: bvh.nodes.iter().map(node).collect(),
        order: bvh.order.clone(),
    }
}

/// The student's copy of the course's hierarchy.
fn student_bvh(bvh: &course::acceleration::Bvh) -> Bvh {
    let node = |n: &course::acceleration::bvh::Node| Node {
        bounds: Aabb {
            min: n.bounds.min,
            max: n.bounds.max,
        },
        first: n.first,
        count: n.count,
    };
    Bvh {
        nodes: bvh.nodes.iter().map(node).collect(),
        order: bvh.order.clone(),
    }
}

/// The distance of the nearest triangle that `shot` meets in the course's
/// `mesh`, testing every one.
fn brute_force(mesh: &course::meshes::Mesh, (origin, direction, t_max): Shot) -> Option<Real> {
    let ray = course::geometry::Ray::new(origin, direction);
    course::meshes::BruteForce
        .nearest(mesh, &ray, t_max)
        .map(|h| h.at.t)
}

/// Whether two nearest distances agree: both absent, or within a few roundings.
fn same_hit(gave: Option<Real>, expected: Option<Real>) -> bool {
    match (gave, expected) {
        (None, None) => true,
        (Some(t), Some(e)) => (t - e).abs() <= ulps(4.0) * e,
        _ => false,
    }
}

/// A nearest distance in the book's notation.
fn show(t: Option<Real>) -> String {
    t.map_or(say!("generated-s6-no-hit"), |t| format!("t = {}", n(t)))
}

/// Exercise s6.1 on generated meshes. A right build may split otherwise than the
/// course's, so what the chapter promises is checked (see [`hierarchy::fault`]),
/// then the course's walk through the student's hierarchy must find, on a few
/// rays, the nearest hit that testing every triangle finds.
pub fn bvh_build(yours: impl Fn(&Mesh) -> Bvh) -> Outcome {
    on_generated(
        "Bvh::build",
        (meshes::meshes(), aims()),
        |(generated, aims)| {
            let (mesh, course_mesh) = generated.meshes();
            let bvh = course_bvh(&yours(&mesh));
            if let Some(fault) = hierarchy::fault(&bvh, &course_mesh) {
                let case = generated.describe();
                return Err(say!("generated-s6-message", case = case, fault = fault));
            }
            for aim in aims {
                course_walk_differs(&bvh, (&generated, &course_mesh), aim)?;
            }
            Ok(())
        },
    )
}

/// The course's walk through the student's hierarchy `bvh` against testing
/// every triangle, on one generated ray.
fn course_walk_differs(
    bvh: &course::acceleration::Bvh,
    (generated, mesh): (&Generated, &course::meshes::Mesh),
    aim: Aim,
) -> Result<(), String> {
    let shot = aim.shot(generated, mesh);
    let (origin, direction, t_max) = shot;
    let ray = course::geometry::Ray::new(origin, direction);
    let gave = bvh.nearest(mesh, &ray, t_max).map(|h| h.at.t);
    let expected = brute_force(mesh, shot);
    if same_hit(gave, expected) {
        return Ok(());
    }
    let case = format!("{}, {}", generated.describe(), describe_shot(shot));
    Err(say!(
        "generated-s6-the-course-s-walk-through-your",
        show_gave = show(gave),
        show_expected = show(expected),
        case = case
    ))
}

/// A walk of the student's crate: the hierarchy, the mesh, the ray and `t_max`.
type Walk<'a> = &'a dyn Fn(&Bvh, &Mesh, &Ray, Real) -> Option<MeshHit>;

/// Exercise s6.2 on generated meshes and rays, in the course's hierarchy: from
/// outside the mesh's box and inside it, along axes and with `-0` components,
/// with `t_max` infinite or before, between or past the hits, and copies of one
/// triangle, whose ties are compared by distance only. The nearest hit is the one
/// that testing every triangle finds, within a few roundings.
pub fn bvh_nearest(yours: impl Fn(&Bvh, &Mesh, &Ray, Real) -> Option<MeshHit>) -> Outcome {
    on_generated(
        "Bvh::nearest",
        (meshes::meshes(), aims()),
        |(generated, aims)| {
            let (mesh, course_mesh) = generated.meshes();
            let bvh = student_bvh(&course::acceleration::Bvh::build(&course_mesh));
            for aim in aims {
                walk_differs(&yours, (&generated, &mesh, &course_mesh, &bvh), aim)?;
            }
            Ok(())
        },
    )
}

/// The student's walk against testing every triangle on one generated ray.
fn walk_differs(
    yours: Walk,
    (generated, mesh, course_mesh, bvh): (&Generated, &Mesh, &course::meshes::Mesh, &Bvh),
    aim: Aim,
) -> Result<(), String> {
    let shot = aim.shot(generated, course_mesh);
    let (origin, direction, t_max) = shot;
    let gave = yours(bvh, mesh, &Ray::new(origin, direction), t_max).map(|h| h.at.t);
    let expected = brute_force(course_mesh, shot);
    if same_hit(gave, expected) {
        return Ok(());
    }
    let inside = (origin - course_mesh.bounds.min).min_element() >= 0.0
        && (course_mesh.bounds.max - origin).min_element() >= 0.0;
    let why = walk_rule(gave, expected, t_max, inside);
    let case = format!("{}, {}", generated.describe(), describe_shot(shot));
    Err(differs(&case, &show(gave), &show(expected), Some(why)))
}

/// The rule of the walk that `gave` breaks, testing every triangle giving
/// `expected`; `inside`: the ray starts inside the mesh's box.
fn walk_rule(gave: Option<Real>, expected: Option<Real>, t_max: Real, inside: bool) -> String {
    match (gave, expected) {
        (Some(t), _) if t >= t_max => {
            say!("generated-s6-only-hits-closer-than-t-max", t_max = n(t_max))
        }
        (Some(t), Some(e)) if t > e => say!("generated-s6-a-nearer-hit-lies-in-a"),
        (None, Some(_)) if inside => say!("generated-s6-the-ray-starts-inside-the-mesh"),
        (None, Some(_)) => say!("generated-s6-the-walk-missed-a-hit-every"),
        _ => say!("generated-s6-the-nearest-hit-is-the-one"),
    }
}

/// Exercise s6.3 on generated triangles: vertex normals of any direction, zero
/// or none, opposite ones that cancel, weights at the corners, on the edges (`0`
/// and `-0`) and inside, the geometric normal on either side, and a triangle
/// whose vertices are not `0, 1, 2`. The normal is a unit vector, within 64
/// roundings. Normalising a blend of length `L` magnifies its roundings by
/// `1 / L`: the normals agree within `16 (|b_A| + |b_B| + |b_C|) / L` roundings
/// (the geometric normal within 4 where the blend is zero), and either side is
/// right where the normal is perpendicular to the geometric one to that
/// tolerance.
pub fn smooth_normal(yours: impl Fn(&Mesh, u32, [Real; 3], Vec3) -> Vec3) -> Outcome {
    on_generated("Mesh::smooth_normal", meshes::shadings(), |case| {
        let (mesh, course_mesh) = case.meshes();
        let geometric = case.geometric();
        let gave = yours(&mesh, case.triangle, case.weights, geometric);
        let expected = course_mesh.smooth_normal(case.triangle, case.weights, geometric);
        let normals = (!course_mesh.normals.is_empty())
            .then(|| case.vertices().map(|i| course_mesh.normals[i as usize]));
        let tolerance = normals.map_or(ulps(4.0), |normals| {
            let length = blend(normals, case.weights).length();
            let sum: Real = case.weights.iter().map(|w| w.abs()).sum();
            if length == 0.0 {
                ulps(4.0)
            } else {
                (ulps(16.0) * sum / length).min(2.0)
            }
        });
        let either_side = expected.dot(geometric).abs() <= tolerance;
        let unit = (gave.length() - 1.0).abs() <= ulps(64.0);
        if unit
            && (near_vec(gave, expected, tolerance)
                || (either_side && near_vec(gave, -expected, tolerance)))
        {
            return Ok(());
        }
        let at = |w| yours(&mesh, case.triangle, w, geometric);
        let why = shading_rule(&at, expected, (&course_mesh.normals, normals), &case);
        Err(differs(&case.describe(), &v(gave), &v(expected), Some(why)))
    })
}

/// `b_A N_A + b_B N_B + b_C N_C`.
fn blend(normals: [Vec3; 3], weights: [Real; 3]) -> Vec3 {
    (0..3).map(|k| weights[k] * normals[k]).sum()
}

/// The chapter's shading normal of the corners' `normals` at `weights`: their
/// blend normalised, turned to the side of `geometric`, or `geometric` where the
/// blend is zero.
fn shading_model(normals: [Vec3; 3], weights: [Real; 3], geometric: Vec3) -> Vec3 {
    match blend(normals, weights).try_normalize() {
        Some(n) if n.dot(geometric) < 0.0 => -n,
        Some(n) => n,
        None => geometric,
    }
}

/// The rule of the shading normal that `yours` (a function of the weights)
/// breaks at the case's weights, `expected` being the course's: `all` the mesh's
/// normals, `corners` those of the triangle's corners.
fn shading_rule(
    yours: &dyn Fn([Real; 3]) -> Vec3,
    expected: Vec3,
    (all, corners): (&[Vec3], Option<[Vec3; 3]>),
    case: &meshes::Shading,
) -> String {
    let Some(corners) = corners else {
        return say!("generated-s6-without-vertex-normals-the-shading-normal");
    };
    let gave = yours(case.weights);
    let unit = gave.normalize_or_zero();
    if blend(corners, case.weights).try_normalize().is_none() {
        say!("generated-s6-here-b-a-n-a-b")
    } else if near_vec(gave, -expected, ulps(1024.0)) {
        say!("generated-s6-the-shading-normal-is-turned-to")
    } else if (gave.length() - 1.0).abs() > 1e-3
        && (near_vec(unit, expected, 1e-3) || near_vec(unit, -expected, 1e-3))
    {
        say!("generated-s6-b-a-n-a-b-b", gave_length = n(gave.length()))
    } else {
        pairing_rules(yours, [all[0], all[1], all[2]], corners, case)
            .unwrap_or_else(|| say!("generated-s6-n-s-normalize-b-a-n"))
    }
}

/// How a mistaken blend pairs the normals with the weights.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Pairing {
    /// The weights in another order.
    Weights,
    /// The mesh's first three normals, whatever vertices the triangle names.
    Vertices,
}

/// A shading normal as a function of the weights.
type Shade = Box<dyn Fn([Real; 3]) -> Vec3>;

/// Which normal goes with which weight, when `yours` pairs them otherwise: the
/// weights in another order, or the mesh's first three normals (`by_number`)
/// rather than the `corners`' ones. The pairings that give what yours gives at
/// the case's weights and, where some do, at three other weights too, are named.
fn pairing_rules(
    yours: &dyn Fn([Real; 3]) -> Vec3,
    by_number: [Vec3; 3],
    corners: [Vec3; 3],
    case: &meshes::Shading,
) -> Option<String> {
    let geometric = case.geometric();
    let permuted = [[0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]].map(|p: [usize; 3]| {
        let shade: Shade = Box::new(move |w| shading_model(corners, p.map(|k| w[k]), geometric));
        (Pairing::Weights, shade)
    });
    let mut pairings = permuted.into_iter().collect::<Vec<_>>();
    if case.vertices() != [0, 1, 2] {
        let shade: Shade = Box::new(move |w| shading_model(by_number, w, geometric));
        pairings.push((Pairing::Vertices, shade));
    }
    let explains = |shade: &Shade, weights: &[[Real; 3]]| {
        weights
            .iter()
            .all(|&w| near_vec(yours(w), shade(w), ulps(1024.0)))
    };
    let probes = [[0.2, 0.3, 0.5], [0.6, 0.1, 0.3], [0.15, 0.7, 0.15]];
    let here: Vec<&(Pairing, Shade)> = pairings
        .iter()
        .filter(|(_, shade)| explains(shade, &[case.weights]))
        .collect();
    let everywhere: Vec<Pairing> = here
        .iter()
        .filter(|(_, shade)| explains(shade, &probes))
        .map(|(pairing, _)| *pairing)
        .collect();
    let mut named = if everywhere.is_empty() {
        here.iter().map(|(pairing, _)| *pairing).collect()
    } else {
        everywhere
    };
    named.dedup();
    let rules: Vec<String> = named.into_iter().map(|p| pairing_rule(p, case)).collect();
    (!rules.is_empty()).then(|| rules.join(&say!("generated-s6-or")))
}

/// The rule a `pairing` breaks.
fn pairing_rule(pairing: Pairing, case: &meshes::Shading) -> String {
    let [i, j, k] = case.vertices();
    match pairing {
        Pairing::Weights => say!("generated-s6-weight-k-goes-with-corner-k"),
        Pairing::Vertices => say!(
            "generated-s6-corner-k-s-normal-is-that",
            i = i,
            j = j,
            k = k
        ),
    }
}
