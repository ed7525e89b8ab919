//! Ray sets: rays stored in a file, in the `.rays` format of the Embree benchmark
//! (`RAYFORMAT.md`), traced against one mesh. The checksums of the format let two ray
//! tracers check that they traced the same rays to the same answers, so that their
//! speeds can be compared on exactly the same work.

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::geometry::Ray;
use crate::maths::{Real, Vec3, to_single};
use crate::meshes::Mesh;

/// What is asked of every ray of a set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayKind {
    /// The nearest hit (format kind 0).
    ClosestHit,
    /// Whether anything is hit at all (format kind 1): a shadow ray.
    Occlusion,
}

/// A set of rays read from a `.rays` file.
#[derive(Clone, Debug, PartialEq)]
pub struct RaySet {
    /// What is asked of the rays.
    pub kind: RayKind,
    /// The rays, in file order; their directions are unit length to `f32` rounding
    /// and kept as stored, so that `t` means what it means in the file.
    pub rays: Vec<Ray>,
    /// The end of each ray's interval; a hit at exactly `t_max` counts.
    pub t_max: Vec<Real>,
}

/// Why a `.rays` file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum RaySetError {
    /// The file could not be read.
    #[error("{path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        source: std::io::Error,
    },
    /// The file is not a ray set of a version this program reads.
    #[error("{path}: {message}")]
    Format {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        message: String,
    },
}

/// Size of the header: magic, version, kind, count.
const HEADER: usize = 20;
/// Size of one record: eight `f32`.
const RECORD: usize = 32;

impl RaySet {
    /// Reads the ray set at `path`.
    pub fn read(path: &Path) -> Result<RaySet, RaySetError> {
        let bytes = std::fs::read(path).map_err(|source| RaySetError::Read {
            path: path.to_owned(),
            source,
        })?;
        RaySet::parse(&bytes).map_err(|message| RaySetError::Format {
            path: path.to_owned(),
            message,
        })
    }

    /// The ray set held in `bytes`: the 20-byte header (`RAYS`, version 1, kind,
    /// count) and `count` records of eight little-endian `f32`: origin, direction,
    /// `tmin` and `tmax`. Every ray is traced from `t = 0`, so a record whose `tmin` is
    /// not 0 is refused rather than traced over the wrong interval.
    pub fn parse(bytes: &[u8]) -> Result<RaySet, String> {
        let word = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
        if bytes.len() < HEADER || &bytes[..4] != b"RAYS" {
            return Err("not a ray set (no RAYS header)".into());
        }
        if word(4) != 1 {
            return Err(format!(
                "version {} (this program reads version 1)",
                word(4)
            ));
        }
        let kind = match word(8) {
            0 => RayKind::ClosestHit,
            1 => RayKind::Occlusion,
            k => {
                return Err(format!(
                    "kind {k} (expected 0, closest hit, or 1, occlusion)"
                ));
            }
        };
        let count = u64::from_le_bytes(bytes[12..20].try_into().unwrap());
        let expected = count
            .checked_mul(RECORD as u64)
            .and_then(|b| b.checked_add(HEADER as u64));
        if expected != Some(bytes.len() as u64) {
            return Err(format!(
                "{} bytes, but a header announcing {count} rays needs 20 + 32 x {count}",
                bytes.len()
            ));
        }
        let mut rays = Vec::with_capacity(count as usize);
        let mut t_max = Vec::with_capacity(count as usize);
        for record in bytes[HEADER..].chunks_exact(RECORD) {
            let f =
                |i: usize| f32::from_le_bytes(record[4 * i..4 * i + 4].try_into().unwrap()) as Real;
            let origin = Vec3::new(f(0), f(1), f(2));
            let direction = Vec3::new(f(3), f(4), f(5));
            if !(origin.is_finite() && direction.is_finite() && f(7) >= 0.0) {
                return Err(format!("ray {} is not a finite ray", rays.len()));
            }
            if f(6) != 0.0 {
                return Err(format!(
                    "ray {} starts at tmin = {} (this program traces every ray from \
                     tmin = 0, as the benchmark's sets do)",
                    rays.len(),
                    f(6)
                ));
            }
            rays.push(Ray { origin, direction });
            t_max.push(f(7));
        }
        Ok(RaySet { kind, rays, t_max })
    }
}

/// The checksums of the ray-set format: for closest-hit sets, how many rays hit and
/// the sum of their distances (each rounded to `f32`, added in file order in `f64`,
/// so the sum does not depend on the thread count); for occlusion sets, how many rays
/// are blocked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checksums {
    /// Rays with a hit (closest-hit sets) or blocked (occlusion sets).
    pub hits: u64,
    /// Sum of the hit distances (closest-hit sets; 0 otherwise).
    pub tsum: f64,
}

/// Traces every ray of `set` against `mesh`, in parallel on the current rayon pool,
/// and returns the checksums.
pub fn trace_set(mesh: &Mesh, set: &RaySet) -> Checksums {
    let found: Vec<Option<f32>> = set
        .rays
        .par_iter()
        .zip(&set.t_max)
        .map(|(ray, &t_max)| {
            let limit = t_max.next_up();
            match set.kind {
                RayKind::ClosestHit => mesh.intersect(ray, limit).map(|hit| to_single(hit.at.t)),
                RayKind::Occlusion => mesh.occluded(ray, limit).then_some(0.0),
            }
        })
        .collect();
    Checksums {
        hits: found.iter().flatten().count() as u64,
        tsum: found.iter().flatten().map(|&t| f64::from(t)).sum(),
    }
}

/// The speed of tracing a ray set on some number of threads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// The checksums, the same for every pass.
    pub checksums: Checksums,
    /// Worker threads.
    pub threads: usize,
    /// Millions of rays per second: the median of the timed passes.
    pub mrays: f64,
    /// The slowest and the fastest pass, in millions of rays per second.
    pub range: (f64, f64),
}

/// Traces `set` once to warm the caches, then `passes` more times on `threads`
/// threads, timing each pass (as the Embree benchmark does).
pub fn time_set(
    mesh: &Mesh,
    set: &RaySet,
    threads: usize,
    passes: usize,
) -> Result<Timing, rayon::ThreadPoolBuildError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()?;
    let checksums = pool.install(|| trace_set(mesh, set));
    let mut speeds: Vec<f64> = (0..passes.max(1))
        .map(|_| {
            let start = std::time::Instant::now();
            let again = pool.install(|| trace_set(mesh, set));
            let seconds = start.elapsed().as_secs_f64();
            assert_eq!(again, checksums, "a pass found different hits");
            set.rays.len() as f64 / seconds / 1e6
        })
        .collect();
    speeds.sort_by(f64::total_cmp);
    Ok(Timing {
        checksums,
        threads: pool.current_num_threads(),
        mrays: speeds[speeds.len() / 2],
        range: (speeds[0], speeds[speeds.len() - 1]),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(kind: u32, records: &[[f32; 8]]) -> Vec<u8> {
        let mut bytes = b"RAYS".to_vec();
        bytes.extend(1u32.to_le_bytes());
        bytes.extend(kind.to_le_bytes());
        bytes.extend((records.len() as u64).to_le_bytes());
        for r in records {
            for v in r {
                bytes.extend(v.to_le_bytes());
            }
        }
        bytes
    }

    #[test]
    fn records_are_read_in_order() {
        let bytes = file(0, &[[1.0, 2.0, 3.0, 0.0, 0.0, -1.0, 0.0, f32::INFINITY]]);
        let set = RaySet::parse(&bytes).unwrap();
        assert_eq!(set.kind, RayKind::ClosestHit);
        assert_eq!(set.rays[0].origin, Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(set.rays[0].direction, -Vec3::Z);
        assert_eq!(set.t_max[0], Real::INFINITY);
    }

    #[test]
    fn bad_files_are_refused_with_a_reason() {
        let good = file(1, &[[0.0; 8]]);
        assert!(RaySet::parse(b"RAYX").unwrap_err().contains("RAYS"));
        let mut version = good.clone();
        version[4] = 2;
        assert!(RaySet::parse(&version).unwrap_err().contains("version 2"));
        let mut kind = good.clone();
        kind[8] = 7;
        assert!(RaySet::parse(&kind).unwrap_err().contains("kind 7"));
        assert!(
            RaySet::parse(&good[..good.len() - 1])
                .unwrap_err()
                .contains("bytes")
        );
        let mut huge = good.clone();
        huge[12..20].copy_from_slice(&u64::MAX.to_le_bytes());
        assert!(RaySet::parse(&huge).unwrap_err().contains("bytes"));
        let nan = file(0, &[[f32::NAN, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]]);
        assert!(RaySet::parse(&nan).unwrap_err().contains("ray 0"));
        let late = file(0, &[[0.0; 8], [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5, 1.0]]);
        assert!(
            RaySet::parse(&late)
                .unwrap_err()
                .contains("ray 1 starts at tmin = 0.5")
        );
    }
}
