//! Rays leaving large triangles: a ground of two triangles 200 units wide on
//! `y = 0`, a strip 200 by 2 of the same (thin triangles), and a tilted ground. A
//! point of the first two has no rounding error at all along the normal, so an
//! offset that follows the point's error alone starts the new ray on the plane, and
//! the watertight test then finds the plane again in front of it, at a `t` of about
//! `10^-14` in double precision, for about a third of the rays that leave at 17
//! degrees or less: the counter-example. With the offset lengthened to the
//! triangle's clearance (`meshes::clearance`), no ray leaving the plane, outwards or
//! through it, at any angle, meets it again.

use raycourse::acceleration::Bvh;
use raycourse::geometry::hit::offset_along;
use raycourse::geometry::{Hit, Ray, TriangleTest};
use raycourse::maths::{Mat3, Real, Vec3, pixel_rng, uniform};
use raycourse::meshes::{Mesh, MeshHit, ObjData, Placement};
use rayon::prelude::*;
use std::sync::Arc;

/// A square of side 200 in `x` and `2 half_depth` in `z`, two triangles, its corners
/// lifted by `tilt` (x, z) in `y`.
fn quad(half_depth: Real, tilt: [Real; 2]) -> ObjData {
    let corner = |x: Real, z: Real| Vec3::new(x, tilt[0] * x + tilt[1] * z, z);
    ObjData {
        positions: vec![
            corner(-100.0, -half_depth),
            corner(100.0, -half_depth),
            corner(100.0, half_depth),
            corner(-100.0, half_depth),
        ],
        normals: Vec::new(),
        uvs: Vec::new(),
        triangles: vec![[0, 2, 1], [0, 3, 2]],
        diffuse_texture: None,
    }
}

/// `data` placed as it is, searched through a BVH with the triangle test `test`.
fn mesh(data: &ObjData, test: TriangleTest) -> Mesh {
    let identity = Placement {
        scale: 1.0,
        rotation: Mat3::IDENTITY,
        translation: Vec3::ZERO,
    };
    let mut mesh = Mesh::new(data, &identity);
    mesh.triangle_test = test;
    mesh.search = Arc::new(Bvh::build(&mesh));
    mesh
}

/// The angles, in degrees, at which the rays leave the plane.
const ANGLES: [Real; 6] = [1e-3, 0.1, 1.0, 17.0, 45.0, 89.0];

/// Rays per angle, half leaving the plane outwards and half through it.
const RAYS: u64 = 20_000;

/// From random points of the mesh's plane (hit by rays from above), a ray at each
/// angle of `ANGLES`, spawned by `spawn`; how many meet the plane again.
fn surface_hits(mesh: &Mesh, half_depth: Real, spawn: impl Fn(&Hit, Vec3) -> Ray + Sync) -> u64 {
    let leaving = |i: u64| -> u64 {
        let mut rng = pixel_rng(17, i);
        let mut u = || 2.0 * uniform(&mut rng) - 1.0;
        let target = Vec3::new(99.0 * u(), 0.0, 0.99 * half_depth * u());
        let ray = Ray::new(
            target + Vec3::new(3.0, 10.0, 2.0),
            Vec3::new(-3.0, -10.0, -2.0),
        );
        let Some(found) = mesh.intersect(&ray, Real::INFINITY) else {
            return 0;
        };
        let hit = mesh.hit_record(&ray, found, 0).facing_the_ray();
        let phi = 3.0 * u();
        let angle = ANGLES[i as usize % ANGLES.len()].to_radians();
        let side = if i.is_multiple_of(2) { 1.0 } else { -1.0 };
        let along = (hit.normal.cross(Vec3::X) * phi.cos() + Vec3::X * phi.sin()).normalize();
        let direction = along * angle.cos() + hit.normal * (side * angle.sin());
        let again = mesh.intersect(&spawn(&hit, direction.normalize()), Real::INFINITY);
        u64::from(again.is_some_and(|MeshHit { at, .. }| at.t < 1.0))
    };
    (0..RAYS * ANGLES.len() as u64)
        .into_par_iter()
        .map(leaving)
        .sum()
}

#[test]
fn no_ray_leaving_a_large_triangle_meets_it_again() {
    let shapes = [
        ("the ground", 100.0, [0.0, 0.0]),
        ("the strip", 1.0, [0.0, 0.0]),
        ("the tilted ground", 100.0, [0.05, 0.035]),
    ];
    for (name, half_depth, tilt) in shapes {
        for test in [TriangleTest::Watertight, TriangleTest::MollerTrumbore] {
            let mesh = mesh(&quad(half_depth, tilt), test);
            let again = surface_hits(&mesh, half_depth, |hit, direction| hit.spawn(direction));
            assert_eq!(again, 0, "{name}, {test:?}");
        }
    }
}

#[test]
fn the_point_s_error_alone_is_not_enough() {
    let mesh = mesh(&quad(100.0, [0.0, 0.0]), TriangleTest::Watertight);
    let with_point_error_only = |hit: &Hit, direction: Vec3| {
        let offset = offset_along(hit.normal, hit.error);
        Hit { offset, ..*hit }.spawn(direction)
    };
    let again = surface_hits(&mesh, 100.0, with_point_error_only);
    let total = RAYS * ANGLES.len() as u64;
    assert!(
        again > total / 10,
        "{again} of {total} rays met the plane again"
    );
}
