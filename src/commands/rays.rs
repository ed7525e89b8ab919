//! `raycourse rays <mesh.obj> <sets...>`: ray sets in the format of the Embree
//! benchmark, traced against a mesh, timed, with the format's checksums.

use std::num::NonZeroUsize;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use clap::{ArgMatches, FromArgMatches, Parser, ValueEnum};
use raycourse::acceleration::Bvh;
use raycourse::fast::FastBvh;
use raycourse::fast::lanes::Lanes;
use raycourse::maths::{Mat3, Vec3};
use raycourse::meshes::{Mesh, Placement, Search, read_obj};
use raycourse::messages::said::Said;
use raycourse::studies::rayset::{RayKind, RaySet, Timing, time_set};

use crate::commands::Verb;
use crate::commands::failure::Failure;

/// Trace ray sets (`.rays` files of the Embree benchmark) against a mesh on one
/// thread and on all, and print Mrays/s with the format's checksums.
#[derive(Parser)]
#[command(name = "rays")]
struct RaysArgs {
    /// The mesh (OBJ).
    mesh: PathBuf,
    /// One or more ray sets.
    #[arg(required = true)]
    sets: Vec<PathBuf>,
    /// Timed passes per measurement (the median is printed).
    #[arg(long, default_value = "5")]
    passes: usize,
    /// Thread counts to measure (default: 1 and one per core).
    #[arg(long, value_delimiter = ',')]
    threads: Vec<NonZeroUsize>,
    /// Which hierarchy: the course's (midpoint splits), the SAH-built one with
    /// the course's nodes, or the SAH-built one laid out for speed.
    #[arg(long, value_enum, default_value = "fast")]
    bvh: BvhKind,
    /// Most triangles in a leaf of the SAH-built hierarchies.
    #[arg(long, default_value = "8")]
    leaf: u16,
}

/// The hierarchies the `rays` command can time.
#[derive(Clone, Copy, ValueEnum)]
enum BvhKind {
    /// The course's: split in the middle of the longest side.
    Midpoint,
    /// Splits by the surface area heuristic, the course's nodes and traversal.
    Sah,
    /// Splits by the surface area heuristic, compact nodes, triangles in leaf order;
    /// boxes and triangles tested in the fastest lanes the processor has.
    Fast,
    /// The same hierarchy with its boxes and triangles tested as two halves of four
    /// lanes, as on a processor without AVX.
    FastPortable,
}

/// The `rays` command (session 6: the hierarchy).
pub const VERB: Verb = Verb {
    rank: 8,
    command: <RaysArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = RaysArgs::from_arg_matches(matches)?;
    let mesh = load(&args.mesh, args.bvh, args.leaf)?;
    let counts: Vec<usize> = if args.threads.is_empty() {
        vec![1, rayon::current_num_threads()]
    } else {
        args.threads.iter().map(|t| t.get()).collect()
    };
    for path in &args.sets {
        let set = RaySet::read(path).map_err(Failure::input)?;
        let name = path.file_stem().unwrap_or_default().to_string_lossy();
        for &count in &counts {
            let timing = time_set(&mesh, &set, count, args.passes).map_err(|e| {
                let said = Said::new("command-cannot-start-threads")
                    .with("threads", count as u64)
                    .with("why", e.to_string());
                Failure::Broke(said)
            })?;
            print_timing(&name, &set, &timing);
        }
    }
    Ok(())
}

/// The mesh of the OBJ file at `path`, unplaced, with the hierarchy `bvh` (leaves of
/// at most `leaf` triangles for the SAH-built ones); prints the build time.
fn load(path: &Path, bvh: BvhKind, leaf: u16) -> Result<Mesh, Failure> {
    let data = read_obj(path)
        .map_err(|m| Failure::Input(format!("{}: cannot load the mesh: {m}", path.display())))?;
    let placement = Placement {
        scale: 1.0,
        rotation: Mat3::IDENTITY,
        translation: Vec3::ZERO,
    };
    let mut mesh = Mesh::new(&data, &placement);
    let start = Instant::now();
    mesh.search = match bvh {
        BvhKind::Midpoint => Arc::new(Bvh::build(&mesh)) as Arc<dyn Search>,
        BvhKind::Sah => Arc::new(raycourse::fast::hierarchy::sah::build(
            &mesh,
            leaf.into(),
            1,
        )),
        BvhKind::Fast => Arc::new(FastBvh::build(&mesh, leaf)),
        BvhKind::FastPortable => Arc::new(FastBvh::build(&mesh, leaf).with_lanes(Lanes::Portable)),
    };
    println!(
        "build triangles={} ms={:.1}",
        mesh.triangles.len(),
        start.elapsed().as_secs_f64() * 1e3
    );
    Ok(mesh)
}

/// Prints one measurement in the Embree benchmark's line format.
fn print_timing(name: &str, set: &RaySet, timing: &Timing) {
    let sums = match set.kind {
        RayKind::ClosestHit => format!(
            "hits={} tsum={:.6}",
            timing.checksums.hits, timing.checksums.tsum
        ),
        RayKind::Occlusion => format!("occluded={}", timing.checksums.hits),
    };
    println!(
        "raycourse {name} threads={} Mrays/s={:.2} {sums} rays={} range={:.2}-{:.2}",
        timing.threads,
        timing.mrays,
        set.rays.len(),
        timing.range.0,
        timing.range.1
    );
}
