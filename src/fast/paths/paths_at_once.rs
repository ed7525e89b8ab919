//! Beyond the course: the pixels of a row rendered four paths at a time (eight in
//! single precision), to the same bytes as [`pixel`](crate::render::samples::pixel).
//!
//! Following one path is a chain of steps that each wait for the one before: the
//! nearest sphere needs the ray, the bounce needs the hit, the next ray needs the
//! bounce. Four paths of four different pixels have no such chain between them, so
//! they are followed side by side, one hit each per step, on the four lanes of a
//! SIMD register: the nearest-sphere test of their four rays, then of their four
//! shadow rays, runs as one test on four rays at once
//! ([`SphereLanes::nearest_of_each`]), each sphere's steps done for the four rays by
//! one instruction each, and so does the work at their four hits
//! ([`hits_at_once`](crate::fast::paths::hits_at_once)).
//!
//! Every path makes the same computations as the recursive
//! [`radiance`](crate::integrator::Tracer::radiance), in the same order, with its
//! pixel's own random numbers: what each diffuse hit adds is kept (`fast::path`) and
//! summed from the end of the path back to its start, as the recursion does when it
//! returns. The one difference is the cosine and sine of each bounce's and light
//! sample's angle, taken on the lanes
//! ([`sin_cos`](crate::fast::simd::sin_cos::sin_cos)) within 2 units in the last
//! place of the C library's: so each pixel gets the same value to within a few
//! roundings, and the image the same bytes (a test renders every stage both ways).
//! It models only what the rooms of the course need: diffuse spheres and, from
//! session 5, meshes (a mesh is always diffuse; its triangles are searched one ray
//! at a time, after the spheres, in `fast/meshes_at_once.rs`), a point or sphere
//! light, bounce limit and Russian roulette; any other scene takes the course's
//! recursion.
//!
//! [`SphereLanes::nearest_of_each`]: crate::fast::paths::sphere_lanes::SphereLanes::nearest_of_each

use crate::fast::lanes::{LaneKind, OnLanes};
use crate::fast::paths::hits_at_once::{bounce_all, light_all, sphere_hits};
use crate::fast::paths::path::{PATHS, Path};
use crate::fast::paths::sphere_lanes::SphereLanes;
use crate::fast::simd::real_lanes::RealSource;
use crate::materials::Material;
use crate::maths::Colour;
use crate::scene::Scene;
use crate::scene::beyond::Beyond;

/// Whether [`row`] can render `scene`: every sphere diffuse (a mesh always is), and
/// shadow rays offset as the crate offsets them, not by a fixed `epsilon`.
pub fn applies(scene: &Scene) -> bool {
    let diffuse =
        |sphere: &crate::geometry::Sphere| matches!(sphere.material, Material::Diffuse { .. });
    scene.spheres.iter().all(diffuse) && scene.settings.shadow_offset.is_none()
}

/// Renders row `row` of `scene`, whose spheres are `spheres`, with the settings
/// `beyond`, into `line` (each pixel's radiance) and `taken` (its number of
/// samples), `PATHS` (four, or eight in single precision) pixels at a time, the next pixel starting where one is
/// done; returns the rays traced and the samples dropped as not finite, as
/// [`Tracer`](crate::integrator::Tracer) counts them. The row runs on the lanes
/// that `spheres` chose, the fastest the processor has.
pub fn row(
    scene: &Scene,
    beyond: &Beyond,
    spheres: &SphereLanes,
    row: u32,
    line: &mut [Colour],
    taken: &mut [u32],
) -> (u64, u64) {
    let work = Row {
        scene,
        beyond,
        spheres,
        row,
        line,
        taken,
    };
    spheres.lanes().run(work)
}

/// A row to render, and where its pixels go: [`row`]'s arguments.
struct Row<'a> {
    scene: &'a Scene,
    beyond: &'a Beyond,
    spheres: &'a SphereLanes,
    row: u32,
    line: &'a mut [Colour],
    taken: &'a mut [u32],
}

impl OnLanes for Row<'_> {
    type Output = (u64, u64);

    #[inline(always)]
    fn on<L: LaneKind>(self, lanes: L) -> (u64, u64) {
        row_on(lanes, self)
    }
}

/// [`row`] on `lanes`.
#[inline(always)]
fn row_on<L: RealSource>(lanes: L, work: Row) -> (u64, u64) {
    let Row {
        scene,
        beyond,
        spheres,
        row,
        line,
        taken,
    } = work;
    let mut columns = 0..line.len() as u32;
    let mut paths: Vec<Path> = columns
        .by_ref()
        .take(PATHS)
        .map(|column| Path::new(scene, beyond, row, column))
        .collect();
    let (mut rays, mut dropped) = (0, 0);
    while !paths.is_empty() {
        step(lanes, spheres, &mut paths);
        paths.retain_mut(|path| {
            if !path.pixel_done() {
                return true;
            }
            line[path.column as usize] = path.estimate.mean.mean();
            taken[path.column as usize] = path.taken;
            rays += path.tracer.rays;
            dropped += u64::from(path.estimate.mean.dropped);
            columns
                .next()
                .map(|column| *path = Path::new(scene, beyond, row, column))
                .is_some()
        });
    }
    (rays, dropped)
}

// ANCHOR: step
/// Takes each of `paths` (one to [`PATHS`]) one hit further: their rays' nearest hits
/// in one test, then their shadow rays' in another. Where fewer than `PATHS` are
/// left, or a path has no shadow ray, a lane repeats another ray and its answer is
/// not used. The work at the hits (their records, their direct light, their
/// bounces) is done on the lanes too, each part for every path before the next.
#[inline(always)]
fn step<L: RealSource>(lanes: L, spheres: &SphereLanes, paths: &mut [Path]) {
    let last = paths.len() - 1;
    let ray = |k: usize| &paths[k.min(last)].ray;
    let rays = std::array::from_fn(ray);
    let nearest = spheres.nearest_of_each(lanes, rays);
    let mut hits = [None; PATHS];
    sphere_hits(
        lanes,
        paths[0].tracer.scene,
        spheres,
        rays,
        nearest,
        &mut hits,
    );
    for ((path, nearest), hit) in paths.iter_mut().zip(nearest).zip(&mut hits) {
        path.hit(nearest, hit);
    }
    light_all(lanes, paths, &hits);
    bounce_all(lanes, paths, &hits);
    let mut shadow = [None; PATHS];
    if paths.iter().any(|path| path.shadow_ray().is_some()) {
        let ray = |k: usize| {
            let path = &paths[k.min(last)];
            path.shadow_ray().unwrap_or(&path.ray)
        };
        shadow = spheres.nearest_of_each(lanes, std::array::from_fn(ray));
    }
    for (path, shadow) in paths.iter_mut().zip(shadow) {
        path.light(shadow);
    }
}
// ANCHOR_END: step
