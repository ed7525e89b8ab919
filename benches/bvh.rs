//! Building the course's BVH over the ogre (39,856 triangles) and finding the
//! closest hit of 10,000 rays with it.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use raycourse::acceleration::Bvh;
use raycourse::geometry::Ray;
use raycourse::maths::{Mat3, Real, Vec3, pixel_rng, uniform};
use raycourse::meshes::{Mesh, Placement, read_obj};

fn ogre() -> Mesh {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/ogre/ogre.obj");
    let data = read_obj(&path).expect("the ogre asset loads");
    let placement = Placement {
        scale: 1.0,
        rotation: Mat3::IDENTITY,
        translation: Vec3::ZERO,
    };
    Mesh::new(&data, &placement)
}

/// Seeded rays from the front of the mesh towards random points of its box.
fn rays(mesh: &Mesh, count: u64) -> Vec<Ray> {
    let size = mesh.bounds.max - mesh.bounds.min;
    let eye = mesh.bounds.centre() + Vec3::new(0.0, 0.0, 2.0 * size.length());
    (0..count)
        .map(|i| {
            let mut rng = pixel_rng(1, i);
            let target = mesh.bounds.min
                + size * Vec3::new(uniform(&mut rng), uniform(&mut rng), uniform(&mut rng));
            Ray::new(eye, target - eye)
        })
        .collect()
}

fn bvh(c: &mut Criterion) {
    let mut mesh = ogre();
    c.bench_function("bvh build, ogre", |b| {
        b.iter(|| Bvh::build(black_box(&mesh)))
    });
    let rays = rays(&mesh, 10_000);
    mesh.search = std::sync::Arc::new(Bvh::build(&mesh));
    c.bench_function("closest hit, 10k rays, ogre, bvh", |b| {
        b.iter(|| {
            rays.iter()
                .filter_map(|r| mesh.intersect(black_box(r), Real::INFINITY))
                .count()
        })
    });
}

criterion_group!(benches, bvh);
criterion_main!(benches);
