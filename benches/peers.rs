//! The crate's fast BVH beside its peers on the same rays, one thread, in one run:
//! obvhs (a pure-Rust compressed wide BVH, the peer a Rust user would pick) and
//! tinybvh 1.6.8 (C++, header-only, Jacco Bikker's; `tiny_bvh/`, compiled with the
//! host's instructions by `build.rs`): its binary BVH, its 4-wide `BVH4_CPU` and,
//! where the processor has AVX2, its 8-wide `BVH8_CPU`, each built with spatial
//! splits (`BuildHQ`). Camera rays and diffuse rays (closest hit), shadow rays (any
//! hit) against the ogre.
//!
//! The rays are the `.rays` sets of the Embree benchmark when `RAYSETS` names their
//! folder (`primary.rays`, `diffuse.rays`, `shadow.rays`), so the figures sit beside
//! Embree's; otherwise sets made here the same way (a camera from the front, right and
//! above; cosine-weighted bounces from its hits; shadow rays to a sphere light above).
//! The hits each library finds are counted; they agree but where single precision
//! (the peers) and double precision (the crate) round a grazing ray apart.
//!
//! `cargo bench -p raycourse-benches --bench peers` (or with
//! `RAYSETS=/tmp/raysets/ogre` before it).

use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use glam::Vec3A;
use obvhs::BvhBuildParams;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::{Ray as PeerRay, RayHit};
use obvhs::triangle::Triangle;
use raycourse::fast::FastBvh;
use raycourse::geometry::Ray;
use raycourse::maths::frame::Frame;
use raycourse::maths::sampling::sample_cosine_hemisphere;
use raycourse::maths::{Mat3, Real, Vec3, pixel_rng, to_single, uniform};
use raycourse::meshes::{Mesh, Placement, read_obj};
use raycourse::studies::rayset::{RayKind, RaySet};

use crate::tinybvh::{Layout, TinyBvh, TinyRays};

mod tinybvh;

/// Timed passes per measurement; the median is reported.
const PASSES: usize = 7;

/// A library's name and how it counts the hits of a ray set, given in the crate's
/// double precision and in tinybvh's single-precision layout.
type Tracer<'a> = (&'static str, Box<dyn Fn(&RaySet, &TinyRays) -> usize + 'a>);

fn main() {
    let mut mesh = ogre();
    mesh.search = std::sync::Arc::new(FastBvh::build(&mesh, 8));
    let triangles: Vec<Triangle> = mesh
        .triangles
        .iter()
        .map(|t| {
            let [v0, v1, v2] = t.map(|i| single(mesh.positions[i as usize]));
            Triangle { v0, v1, v2 }
        })
        .collect();
    let peer = timed("obvhs slow build", || {
        build_cwbvh_from_tris(
            &triangles,
            BvhBuildParams::slow_build(),
            &mut Duration::default(),
        )
    });
    let corners: Vec<[f32; 4]> = triangles
        .iter()
        .flat_map(|t| [t.v0, t.v1, t.v2].map(|v| v.extend(0.0).to_array()))
        .collect();
    let tiny = [
        ("tinybvh BVH2", Layout::Binary),
        ("tinybvh BVH4_CPU", Layout::Four),
        ("tinybvh BVH8_CPU", Layout::Eight),
    ]
    .map(|(name, layout)| timed(name, || (name, TinyBvh::build(layout, &corners))));
    let mut tracers: Vec<Tracer> = vec![
        (
            "raycourse fast BVH",
            Box::new(|set, _| trace_mine(&mesh, set)),
        ),
        (
            "obvhs CWBVH",
            Box::new(|set, _| trace_peer(&peer, &triangles, set)),
        ),
    ];
    for (name, bvh) in &tiny {
        match bvh {
            Some(bvh) => tracers.push((name, Box::new(|_, rays| bvh.trace(rays)))),
            None => println!("{name}: not in this build (no AVX2)"),
        }
    }
    table(&ray_sets(&mesh), &mut tracers);
}

/// Runs `build`, printing how long it took.
fn timed<T>(what: &str, build: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let built = build();
    println!("{what}: {:.2} s", start.elapsed().as_secs_f64());
    built
}

/// One row per ray set: each library's Mrays/s, its speed against the crate's, and
/// the hits each counted.
fn table(sets: &[(&str, RaySet)], tracers: &mut [Tracer]) {
    let names: Vec<&str> = tracers.iter().map(|(name, _)| *name).collect();
    println!(
        "| set (rays) | {} Mrays/s | hits |",
        names.join(" Mrays/s | ")
    );
    println!("|---|{}---|", "---|".repeat(names.len()));
    for (name, set) in sets {
        let rays = set.rays.len() as f64 / 1e6;
        let tiny = tiny_rays(set);
        let measured: Vec<(f64, usize)> = tracers
            .iter()
            .map(|(_, trace)| measure(|| trace(set, &tiny)))
            .collect();
        let speeds: Vec<String> = measured
            .iter()
            .map(|(seconds, _)| format!("{:.2} ({:.2}x)", rays / seconds, measured[0].0 / seconds))
            .collect();
        let hits: Vec<String> = measured.iter().map(|(_, hits)| hits.to_string()).collect();
        println!(
            "| {name} ({}) | {} | {} |",
            set.rays.len(),
            speeds.join(" | "),
            hits.join(" / ")
        );
    }
}

/// The median seconds of [`PASSES`] runs of `trace` (after one to warm the caches),
/// and what it counted.
fn measure(trace: impl Fn() -> usize) -> (f64, usize) {
    let count = trace();
    let mut seconds: Vec<f64> = (0..PASSES)
        .map(|_| {
            let start = Instant::now();
            black_box(trace());
            start.elapsed().as_secs_f64()
        })
        .collect();
    seconds.sort_by(f64::total_cmp);
    (seconds[PASSES / 2], count)
}

/// The rays of `set` that hit (closest hit) or are blocked (any hit), by the crate.
fn trace_mine(mesh: &Mesh, set: &RaySet) -> usize {
    set.rays
        .iter()
        .zip(&set.t_max)
        .filter(|(ray, t_max)| match set.kind {
            RayKind::ClosestHit => mesh.intersect(ray, t_max.next_up()).is_some(),
            RayKind::Occlusion => mesh.occluded(ray, t_max.next_up()),
        })
        .count()
}

/// The same count by obvhs, in single precision as it works.
fn trace_peer(peer: &obvhs::cwbvh::CwBvh, triangles: &[Triangle], set: &RaySet) -> usize {
    let test =
        |ray: &PeerRay, id: usize| triangles[peer.primitive_indices[id] as usize].intersect(ray);
    set.rays
        .iter()
        .zip(&set.t_max)
        .filter(|(ray, t_max)| {
            let ray = PeerRay::new(
                single(ray.origin),
                single(ray.direction),
                0.0,
                to_single(**t_max),
            );
            match set.kind {
                RayKind::ClosestHit => peer.ray_traverse(ray, &mut RayHit::none(), test),
                RayKind::Occlusion => !peer.ray_traverse_miss(ray, test),
            }
        })
        .count()
}

/// `set` in single precision, as tinybvh takes it (an unbounded ray reaches its
/// "far", 1e30).
fn tiny_rays(set: &RaySet) -> TinyRays {
    let rays = set.rays.iter().zip(&set.t_max).map(|(ray, t_max)| {
        let (o, d) = (single(ray.origin), single(ray.direction));
        [o.x, o.y, o.z, d.x, d.y, d.z, to_single(*t_max).min(1e30)]
    });
    TinyRays::new(rays, set.kind == RayKind::Occlusion)
}

fn single(v: Vec3) -> Vec3A {
    Vec3A::new(to_single(v.x), to_single(v.y), to_single(v.z))
}

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

/// The three sets, read from `$RAYSETS` or made here.
fn ray_sets(mesh: &Mesh) -> Vec<(&'static str, RaySet)> {
    let names = ["primary", "diffuse", "shadow"];
    if let Some(dir) = std::env::var_os("RAYSETS").map(PathBuf::from) {
        println!("ray sets of {}", dir.display());
        return names
            .map(|n| {
                (
                    n,
                    RaySet::read(&dir.join(format!("{n}.rays"))).expect("a ray set"),
                )
            })
            .into();
    }
    println!("ray sets made here (set RAYSETS to use the Embree benchmark's)");
    let primary = camera_rays(mesh);
    let hits: Vec<(Vec3, Vec3)> = primary
        .rays
        .iter()
        .filter_map(|ray| {
            let hit = mesh.intersect(ray, Real::INFINITY)?;
            let normal = mesh.hit_record(ray, hit, 0).normal;
            let normal = if normal.dot(ray.direction) > 0.0 {
                -normal
            } else {
                normal
            };
            Some((ray.at(hit.at.t) + normal * 1e-4 * diagonal(mesh), normal))
        })
        .collect();
    let (diffuse, shadow) = bounce_and_shadow_rays(mesh, &hits);
    vec![
        ("primary", primary),
        ("diffuse", diffuse),
        ("shadow", shadow),
    ]
}

/// 512 x 512 rays through the pixel centres of a 40-degree camera looking at the
/// mesh's centre from the front, right and above.
fn camera_rays(mesh: &Mesh) -> RaySet {
    let centre = mesh.bounds.centre();
    let back = Vec3::new(0.5, 0.3, 1.0).normalize();
    let eye = centre + back * 1.6 * diagonal(mesh);
    let frame = Frame::new(-back);
    let half = (20.0 as Real).to_radians().tan();
    let rays: Vec<Ray> = (0..512 * 512)
        .map(|i| {
            let (x, y) = ((i % 512) as Real, (i / 512) as Real);
            let (u, v) = (
                (2.0 * (x + 0.5) / 512.0 - 1.0) * half,
                (1.0 - 2.0 * (y + 0.5) / 512.0) * half,
            );
            Ray::new(eye, frame.to_world(Vec3::new(u, v, 1.0)))
        })
        .collect();
    let t_max = vec![Real::INFINITY; rays.len()];
    RaySet {
        kind: RayKind::ClosestHit,
        rays,
        t_max,
    }
}

/// 2^20 cosine-weighted bounces from the camera's hits, and 2^20 shadow rays from
/// them to points of a sphere light above the mesh.
fn bounce_and_shadow_rays(mesh: &Mesh, hits: &[(Vec3, Vec3)]) -> (RaySet, RaySet) {
    let light = mesh.bounds.centre() + Vec3::new(0.0, 1.0, 1.0).normalize() * diagonal(mesh);
    let radius = 0.125 * diagonal(mesh);
    let (mut bounces, mut shadows, mut t_max) = (vec![], vec![], vec![]);
    for i in 0..1u64 << 20 {
        let (point, normal) = hits[i as usize % hits.len()];
        let mut rng = pixel_rng(1, i);
        let local = sample_cosine_hemisphere(uniform(&mut rng), uniform(&mut rng));
        bounces.push(Ray::new(point, Frame::new(normal).to_world(local)));
        let z = 1.0 - 2.0 * uniform(&mut rng);
        let phi = 2.0 * raycourse::maths::PI * uniform(&mut rng);
        let r = (1.0 - z * z).sqrt();
        let target = light + radius * Vec3::new(r * phi.cos(), r * phi.sin(), z);
        shadows.push(Ray::new(point, target - point));
        t_max.push(point.distance(target));
    }
    let all = vec![Real::INFINITY; bounces.len()];
    (
        RaySet {
            kind: RayKind::ClosestHit,
            rays: bounces,
            t_max: all,
        },
        RaySet {
            kind: RayKind::Occlusion,
            rays: shadows,
            t_max,
        },
    )
}

/// The length of the diagonal of the mesh's bounding box.
fn diagonal(mesh: &Mesh) -> Real {
    (mesh.bounds.max - mesh.bounds.min).length()
}
