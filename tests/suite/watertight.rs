//! Watertightness: a ray from inside a closed mesh always hits it, even when it is
//! aimed exactly at a vertex or an edge, where two or more triangles meet and
//! rounding decides which of them the ray belongs to. The watertight test never
//! lets such a ray through; the course's Moller-Trumbore test, which rounds the
//! shared edge differently for each of its triangles, does: the counter-example.

use raycourse::acceleration::Bvh;
use raycourse::geometry::{Ray, TriangleTest};
use raycourse::maths::{Mat3, Real, Vec3, pixel_rng, uniform};
use raycourse::meshes::{Mesh, ObjData, Placement, read_obj};
use rayon::prelude::*;
use std::path::Path;

const IDENTITY: Placement = Placement {
    scale: 1.0,
    rotation: Mat3::IDENTITY,
    translation: Vec3::ZERO,
};

/// A unit sphere of `rings` x `segments` quads (triangles at the poles) whose
/// vertices are moved by up to `jitter` in each coordinate: still closed, since
/// neighbouring triangles share their vertices, but with no symmetry left.
fn jittered_sphere(rings: u32, segments: u32, jitter: Real) -> ObjData {
    let mut rng = pixel_rng(5, 0);
    let mut positions = vec![Vec3::Y];
    for i in 1..rings {
        let theta = raycourse::maths::PI * i as Real / rings as Real;
        for j in 0..segments {
            let phi = 2.0 * raycourse::maths::PI * j as Real / segments as Real;
            let mut u = || (2.0 * uniform(&mut rng) - 1.0) * jitter;
            let p = Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            );
            positions.push(p + Vec3::new(u(), u(), u()));
        }
    }
    positions.push(-Vec3::Y);
    let south = positions.len() as u32 - 1;
    let at = |i: u32, j: u32| 1 + (i - 1) * segments + j % segments;
    let mut triangles = Vec::new();
    for j in 0..segments {
        triangles.push([0, at(1, j + 1), at(1, j)]);
        triangles.push([south, at(rings - 1, j), at(rings - 1, j + 1)]);
        for i in 1..rings - 1 {
            let (a, b, c, d) = (at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
            triangles.push([a, b, d]);
            triangles.push([a, d, c]);
        }
    }
    ObjData {
        positions,
        normals: Vec::new(),
        uvs: Vec::new(),
        triangles,
        diffuse_texture: None,
    }
}

/// `data` as a mesh searched through a BVH with the ray-triangle test `test`.
fn mesh(data: &ObjData, test: TriangleTest) -> Mesh {
    let mut mesh = Mesh::new(data, &IDENTITY);
    mesh.triangle_test = test;
    mesh.search = std::sync::Arc::new(Bvh::build(&mesh));
    mesh
}

/// How many of `rays` miss `mesh`.
fn misses(mesh: &Mesh, rays: &[Ray]) -> usize {
    rays.par_iter()
        .filter(|ray| mesh.intersect(ray, Real::INFINITY).is_none())
        .count()
}

/// Rays from `origins` aimed exactly at every vertex of `data`, and at a point of
/// every edge: its midpoint, and a point a random fraction along it.
fn rays_at_vertices_and_edges(data: &ObjData, origins: &[Vec3]) -> Vec<Ray> {
    let mut targets = data.positions.clone();
    let mut rng = pixel_rng(11, 0);
    for t in &data.triangles {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            let (a, b) = (data.positions[a as usize], data.positions[b as usize]);
            targets.push((a + b) * 0.5);
            targets.push(a + (b - a) * uniform(&mut rng));
        }
    }
    origins
        .iter()
        .flat_map(|&o| targets.iter().map(move |&t| Ray::new(o, t - o)))
        .collect()
}

/// Points inside the unit sphere (well inside the jittered one).
fn inner_points(count: u64, radius: Real) -> Vec<Vec3> {
    (0..count)
        .map(|i| {
            let mut rng = pixel_rng(3, i);
            let mut u = || 2.0 * uniform(&mut rng) - 1.0;
            Vec3::new(u(), u(), u()) * radius / (3.0 as Real).sqrt()
        })
        .collect()
}

#[test]
fn a_million_rays_from_inside_a_jittered_sphere_all_hit() {
    let data = jittered_sphere(64, 128, 2e-3);
    let watertight = mesh(&data, TriangleTest::Watertight);
    let rays: Vec<Ray> = (0..1_000_000u64)
        .into_par_iter()
        .map(|i| {
            let mut rng = pixel_rng(13, i);
            let mut u = || 2.0 * uniform(&mut rng) - 1.0;
            let origin = Vec3::new(u(), u(), u()) * 0.5;
            Ray::new(origin, Vec3::new(u(), u(), u()))
        })
        .filter(|ray| ray.direction.is_finite())
        .collect();
    assert!(rays.len() > 999_000);
    assert_eq!(misses(&watertight, &rays), 0);
}

#[test]
fn rays_at_the_vertices_and_edges_of_a_jittered_sphere_never_pass_through() {
    let data = jittered_sphere(64, 128, 2e-3);
    let rays = rays_at_vertices_and_edges(&data, &inner_points(24, 0.9));
    let watertight = misses(&mesh(&data, TriangleTest::Watertight), &rays);
    let course = misses(&mesh(&data, TriangleTest::MollerTrumbore), &rays);
    eprintln!(
        "{} rays at vertices and edges: {watertight} pass through the watertight test, \
         {course} through Moller-Trumbore",
        rays.len()
    );
    assert_eq!(watertight, 0);
    assert!(course > 0, "the counter-example");
}

#[test]
fn rays_at_the_vertices_and_edges_of_spot_never_pass_through() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/spot/spot.obj");
    let data = read_obj(&path).unwrap();
    // Points inside the cow's body (Spot is a closed mesh: every edge is shared by
    // two triangles). The first lies in its plane of symmetry, x = 0, like many of
    // its vertices: those rays lie in the faces of BVH boxes, with a direction
    // component of -0, the case the slab test's sign rule is there for.
    let origins = [
        Vec3::new(0.0, 0.01, 0.0),
        Vec3::new(0.01, 0.015, 0.03),
        Vec3::new(-0.01, 0.01, -0.01),
    ];
    let rays = rays_at_vertices_and_edges(&data, &origins);
    let watertight = misses(&mesh(&data, TriangleTest::Watertight), &rays);
    let course = misses(&mesh(&data, TriangleTest::MollerTrumbore), &rays);
    eprintln!(
        "{} rays at Spot's vertices and edges: {watertight} pass through the watertight \
         test, {course} through Moller-Trumbore",
        rays.len()
    );
    assert_eq!(watertight, 0);
    assert!(course > 0, "the counter-example");
}
