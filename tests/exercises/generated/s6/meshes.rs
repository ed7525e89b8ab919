//! Generated meshes and rays for session 6: from one triangle to two hundred,
//! scattered, copies of one triangle, flat, or degenerate, at scales from `1e-4`
//! to `1e4` and far from the origin; rays from outside their box and inside it.

use proptest::collection::vec;
use proptest::prelude::*;
use raycourse::maths::{Mat3, Real, Vec3};
use raycourse::meshes::{Mesh, ObjData};

use super::super::s1::{direction, scale};
use super::super::s2::farthest_power;
use super::super::{n, v};
use crate::say;
use crate::words::separator;

/// How a generated mesh's triangles lie, for its message.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Layout {
    /// Triangles of every size anywhere in a cube.
    Scattered,
    /// Copies of one triangle, whose centroids are all the same, among a few others.
    Copies,
    /// Every corner in one plane `x = c`: a box of no thickness.
    Flat,
    /// Triangles with two corners the same, or three in a line, among others.
    Degenerate,
}

/// A generated mesh: its triangles' corners in a cube from -1 to 1, which `size`
/// scales and `at` moves.
#[derive(Clone, Debug)]
pub struct Generated {
    /// How the triangles lie.
    pub layout: Layout,
    /// Each triangle's corners, before scaling and moving.
    pub triangles: Vec<[Vec3; 3]>,
    /// The scale, from `1e-4` to `1e4`.
    pub size: Real,
    /// Where the cube's centre lies, up to `1e8` sizes away (`1e4` in single precision).
    pub at: Vec3,
}

/// A point of the cube from -1 to 1.
fn point() -> impl Strategy<Value = Vec3> {
    (-1.0..1.0 as Real, -1.0..1.0 as Real, -1.0..1.0 as Real)
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// A triangle in the cube: three corners around a centre, from a two-hundredth
/// of the cube's side to all of it across, so that the boxes of the hierarchy
/// overlap.
fn triangle() -> impl Strategy<Value = [Vec3; 3]> {
    let size = prop_oneof![3 => 0.005..0.25 as Real, 1 => 0.25..1.0 as Real];
    (point(), [point(), point(), point()], size)
        .prop_map(|(centre, corners, size)| corners.map(|p| centre + size * p))
}

/// Triangles laid out in each of the [`Layout`]s: one or two triangles often.
fn layouts() -> impl Strategy<Value = (Layout, Vec<[Vec3; 3]>)> {
    let scattered = prop_oneof![
        vec(triangle(), 1..=2),
        vec(triangle(), 3..=12),
        vec(triangle(), 13..=200)
    ];
    let copies = (triangle(), 5usize..=40, vec(triangle(), 0..=3)).prop_map(|(one, k, others)| {
        let mut all = vec![one; k];
        all.extend(others);
        all
    });
    let flat = vec(triangle(), 1..=60).prop_map(|all| {
        all.into_iter()
            .map(|t| t.map(|p| Vec3::new(0.0, p.y, p.z)))
            .collect()
    });
    let degenerate = vec((triangle(), 0u8..4), 1..=40).prop_map(|all| {
        let spoil = |([a, b, c], how): ([Vec3; 3], u8)| match how {
            0 => [a, b, c],
            1 => [a, a, c],
            2 => [a, b, 0.5 * (a + b)],
            _ => [a, a, a],
        };
        all.into_iter().map(spoil).collect()
    });
    prop_oneof![
        2 => scattered.prop_map(|t| (Layout::Scattered, t)),
        1 => copies.prop_map(|t| (Layout::Copies, t)),
        1 => flat.prop_map(|t| (Layout::Flat, t)),
        1 => degenerate.prop_map(|t| (Layout::Degenerate, t)),
    ]
}

/// Generated meshes, of every layout, scale and place.
pub fn meshes() -> impl Strategy<Value = Generated> {
    (layouts(), scale(), direction(), 0.0..farthest_power()).prop_map(
        |((layout, triangles), size, towards, exponent)| Generated {
            layout,
            triangles,
            size,
            at: (10.0 as Real).powf(exponent) * size * towards,
        },
    )
}

/// The student's mesh and the course's of the same `positions`, vertex `normals`
/// (as the file gives them: none, or one a position) and `triangles`, as read.
pub fn both(
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
) -> (Mesh, course::meshes::Mesh) {
    let course = course::meshes::Mesh::new(
        &course::meshes::ObjData {
            positions: positions.clone(),
            normals: normals.clone(),
            uvs: vec![],
            triangles: triangles.clone(),
            diffuse_texture: None,
        },
        &course::meshes::Placement {
            scale: 1.0,
            rotation: Mat3::IDENTITY,
            translation: Vec3::ZERO,
        },
    );
    let data = ObjData {
        positions,
        normals,
        uvs: vec![],
        triangles,
        diffuse_texture: None,
    };
    (Mesh::new(&data, &crate::s6::AS_READ), course)
}

impl Generated {
    /// The student's mesh and the course's: three vertices a triangle.
    pub fn meshes(&self) -> (Mesh, course::meshes::Mesh) {
        let positions = self
            .triangles
            .iter()
            .flatten()
            .map(|&p| self.at + self.size * p);
        let triangles = (0..self.triangles.len() as u32).map(|t| [3 * t, 3 * t + 1, 3 * t + 2]);
        both(positions.collect(), vec![], triangles.collect())
    }

    /// The mesh in the book's notation: its triangles, how they lie, their size and
    /// place, and the corners of each when there are at most three.
    pub fn describe(&self) -> String {
        let layout = match self.layout {
            Layout::Scattered => say!("generated-s6-meshes-scattered"),
            Layout::Copies => say!("generated-s6-meshes-copies-of-one-triangle-the-same"),
            Layout::Flat => say!("generated-s6-meshes-all-in-the-plane-x", at = n(self.at.x)),
            Layout::Degenerate => say!("generated-s6-meshes-some-degenerate-two-corners-the-same"),
        };
        let count = self.triangles.len();
        let mut text = say!(
            "generated-s6-meshes-a-mesh-of-triangles-of-size",
            size = n(self.size),
            at = v(self.at),
            count = count,
            layout = layout
        );
        if count <= 3 {
            for (t, corners) in self.triangles.iter().enumerate() {
                let [a, b, c] = corners.map(|p| v(self.at + self.size * p));
                text += &say!("generated-s6-meshes-triangle", t = t, a = a, b = b, c = c);
            }
        }
        text
    }
}

/// Where a generated ray points: at a point of the mesh's box, or of one of its
/// triangles (its number taken modulo the count, then two barycentric weights).
#[derive(Clone, Copy, Debug)]
enum Towards {
    /// The point of the box at these coordinates, from -1 to 1 across it.
    Box(Vec3),
    /// The point of triangle `t` (modulo the count) with weights `b_B`, `b_C`.
    Triangle(usize, Real, Real),
}

/// A generated ray at a mesh: from outside its box or from the point it aims at,
/// along a direction with `-0` and axis-aligned ones among them, reaching as far
/// as infinity or a multiple of the distance to that point.
#[derive(Clone, Copy, Debug)]
pub struct Aim {
    /// Whether the ray starts at the point it aims at, inside the box.
    inside: bool,
    /// Its unit direction.
    direction: Vec3,
    /// The point it aims at.
    towards: Towards,
    /// Its `t_max` in units of the distance to that point; none for infinity.
    reach: Option<Real>,
}

/// From one to eight generated rays.
pub fn aims() -> impl Strategy<Value = Vec<Aim>> {
    let towards = prop_oneof![
        point().prop_map(Towards::Box),
        (0usize..200, 0.0..1.0 as Real, 0.0..1.0 as Real).prop_map(|(t, b, c)| {
            let (b, c) = if b + c > 1.0 {
                (1.0 - b, 1.0 - c)
            } else {
                (b, c)
            };
            Towards::Triangle(t, b, c)
        }),
    ];
    let reach = prop_oneof![Just(None), (0.1..4.0 as Real).prop_map(Some)];
    let aim = (any::<bool>(), direction(), towards, reach).prop_map(
        |(inside, direction, towards, reach)| Aim {
            inside,
            direction,
            towards,
            reach,
        },
    );
    vec(aim, 1..=8)
}

/// A ray: its origin, its unit direction and how far it may reach, `t_max`.
pub type Shot = (Vec3, Vec3, Real);

impl Aim {
    /// The ray at the course's `mesh` of `generated`.
    pub fn shot(&self, generated: &Generated, mesh: &course::meshes::Mesh) -> Shot {
        let bounds = mesh.bounds;
        let half = 0.5 * (bounds.max - bounds.min);
        let point = match self.towards {
            Towards::Box(p) => bounds.centre() + half * p,
            Towards::Triangle(t, b, c) => {
                let [p, q, r] = mesh.corners((t % mesh.triangles.len()) as u32);
                p + b * (q - p) + c * (r - p)
            }
        };
        let back = if self.inside {
            0.0
        } else {
            3.0 * (half.length() + generated.size)
        };
        let distance = back.max(generated.size);
        let t_max = self.reach.map_or(Real::INFINITY, |k| k * distance);
        (point - back * self.direction, self.direction, t_max)
    }
}

/// A ray in the book's notation, with its `t_max` when finite.
pub fn describe_shot((origin, direction, t_max): Shot) -> String {
    let reach = if t_max.is_finite() {
        format!(", t_max = {}", n(t_max))
    } else {
        String::new()
    };
    say!(
        "generated-s6-meshes-the-ray-from-along",
        origin = v(origin),
        direction = v(direction),
        reach = reach
    )
}

/// A generated triangle with vertex normals: four vertices, each with a normal
/// of any length (the mesh keeps them normalised) or zero, or none at all; two
/// triangles over them, the second naming its vertices in another order; the
/// triangle asked for, the weights and the side of the geometric normal.
#[derive(Clone, Debug)]
pub struct Shading {
    /// The four vertices.
    positions: [Vec3; 4],
    /// Their normals as the file gives them, or none.
    normals: Vec<Vec3>,
    /// The vertices of the second triangle, the first's being `0, 1, 2`.
    second: [u32; 3],
    /// The triangle asked for: 0 or 1.
    pub triangle: u32,
    /// The barycentric weights `(b_A, b_B, b_C)`.
    pub weights: [Real; 3],
    /// Whether the geometric normal is turned over, the triangle seen from below.
    below: bool,
}

/// A vertex normal as a file may give it: a direction of any length, or zero.
fn file_normal() -> impl Strategy<Value = Vec3> {
    prop_oneof![
        4 => direction(),
        1 => (direction(), 0.1..10.0 as Real).prop_map(|(d, k)| k * d),
        1 => Just(Vec3::ZERO),
    ]
}

/// Barycentric weights: the corners, the edges (with `0` and `-0`), inside.
fn weights() -> impl Strategy<Value = [Real; 3]> {
    let edge = (0usize..3, 0.0..1.0 as Real, any::<bool>()).prop_map(|(k, t, negative)| {
        let mut w = [0.0; 3];
        w[(k + 1) % 3] = 1.0 - t;
        w[(k + 2) % 3] = t;
        w[k] = if negative { -0.0 } else { 0.0 };
        w
    });
    let inside = (0.0..1.0 as Real, 0.0..1.0 as Real).prop_map(|(a, b)| {
        let (low, high) = (a.min(b), a.max(b));
        [low, high - low, 1.0 - high]
    });
    prop_oneof![
        Just([1.0, 0.0, 0.0]),
        Just([0.0, 1.0, 0.0]),
        Just([0.0, 0.0, 1.0]),
        edge,
        inside,
    ]
}

/// Generated shading cases; in some, the first two vertex normals are opposite
/// and weighed alike, so that the blend is zero.
pub fn shadings() -> impl Strategy<Value = Shading> {
    let second = prop_oneof![
        Just([2, 1, 3]),
        Just([3, 0, 1]),
        Just([1, 3, 2]),
        Just([2, 0, 1])
    ];
    let normals = prop_oneof![
        6 => [file_normal(), file_normal(), file_normal(), file_normal()].prop_map(|n| n.to_vec()),
        1 => (direction(), direction(), direction()).prop_map(|(a, c, d)| vec![a, -a, c, d]),
        1 => Just(vec![]),
    ];
    let positions = [point(), point(), point(), point()];
    (
        positions,
        normals,
        second,
        0u32..2,
        weights(),
        any::<bool>(),
    )
        .prop_map(|(positions, normals, second, triangle, weights, below)| {
            let cancel = normals.len() == 4 && normals[1] == -normals[0];
            let (triangle, weights) = if cancel {
                (0, [0.5, 0.5, 0.0])
            } else {
                (triangle, weights)
            };
            Shading {
                positions,
                normals,
                second,
                triangle,
                weights,
                below,
            }
        })
}

impl Shading {
    /// The vertices that the triangle asked for names.
    pub fn vertices(&self) -> [u32; 3] {
        [[0, 1, 2], self.second][self.triangle as usize]
    }

    /// The student's mesh and the course's.
    pub fn meshes(&self) -> (Mesh, course::meshes::Mesh) {
        both(
            self.positions.to_vec(),
            self.normals.clone(),
            vec![[0, 1, 2], self.second],
        )
    }

    /// The geometric normal, `(P_B - P_A) x (P_C - P_A)` normalised, on the side
    /// generated.
    pub fn geometric(&self) -> Vec3 {
        let [a, b, c] = self.vertices().map(|i| self.positions[i as usize]);
        let normal = (b - a).cross(c - a).normalize_or(Vec3::Z);
        if self.below { -normal } else { normal }
    }

    /// The case in the book's notation.
    pub fn describe(&self) -> String {
        let [i, j, k] = self.vertices();
        let normals = if self.normals.is_empty() {
            say!("generated-s6-meshes-no-vertex-normals")
        } else {
            let listed: Vec<String> = self.normals.iter().map(|&n| v(n)).collect();
            say!(
                "generated-s6-meshes-the-vertex-normals-as-the-file",
                listed = listed.join(" ")
            )
        };
        let [a, b, c] = self.weights.map(n);
        let s = separator();
        say!(
            "generated-s6-meshes-triangle-of-the-vertices-the-weights",
            triangle = self.triangle,
            geometric = v(self.geometric()),
            i = i,
            s = s,
            j = j,
            k = k,
            normals = normals,
            a = a,
            b = b,
            c = c
        )
    }
}
