//! The probe as text, in the book's notation: one block per ray of the path.

use std::fmt::{self, Display, Formatter};

use crate::inspect::path::{Direct, Level, Next, Probe};
use crate::maths::Real;

impl Display for Probe {
    fn fmt(&self, f: &mut Formatter) -> fmt::Result {
        writeln!(
            f,
            "pixel (x {}, y {}), sample {} of {} (from 0)",
            self.x, self.y, self.sample, self.samples
        )?;
        for (k, level) in self.levels.iter().enumerate() {
            let name = if k == 0 {
                "the camera ray".to_owned()
            } else {
                format!("bounce {k}")
            };
            writeln!(f, "\nlevel {k}: {name}")?;
            write_level(f, level)?;
        }
        writeln!(f, "\nsample radiance  L = {}", triple(self.radiance))?;
        writeln!(
            f,
            "pixel            mean of {} {} {} -> gamma {} -> ({}, {}, {})",
            self.samples,
            if self.samples == 1 {
                "sample"
            } else {
                "samples"
            },
            triple(self.pixel),
            self.gamma,
            self.shown[0],
            self.shown[1],
            self.shown[2]
        )
    }
}

/// One level's block.
fn write_level(f: &mut Formatter, level: &Level) -> fmt::Result {
    writeln!(
        f,
        "  ray      O = {}  d = {}",
        triple(level.origin),
        triple(level.direction)
    )?;
    if let Some(hit) = &level.hit {
        writeln!(
            f,
            "  hit      t = {:.4}  P = {}  N = {}",
            hit.t,
            triple(hit.point),
            triple(hit.normal)
        )?;
        let face = if hit.front_face {
            "front face"
        } else {
            "back face (from inside)"
        };
        writeln!(
            f,
            "           {} (object {}), {}, {face}",
            hit.shape, hit.object, hit.material
        )?;
        let glow = if level.glow_not_counted {
            " (not counted: light sampling counted it at the last hit)"
        } else {
            ""
        };
        writeln!(f, "  emitted  Le = {}{glow}", triple(level.emitted))?;
    }
    if let Some(direct) = &level.direct {
        write_direct(f, direct)?;
    }
    if let Some(next) = &level.next {
        write_next(f, next, level.bounces_left)?;
    }
    if let Some(end) = &level.end {
        writeln!(f, "  end      {end}")?;
    }
    writeln!(
        f,
        "  arriving L = {}   adds {} x (Le + direct) = {}",
        triple(level.arriving),
        triple(level.throughput),
        triple(level.adds)
    )
}

/// The light source's part.
fn write_direct(f: &mut Formatter, direct: &Direct) -> fmt::Result {
    match &direct.shadow_ray {
        Some(ray) => {
            writeln!(
                f,
                "  {}  shadow ray O = {}  d = {}",
                direct.light,
                triple(ray.origin),
                triple(ray.direction)
            )?;
            let distance = ray.distance.map_or("-".to_owned(), |d| format!("{d:.4}"));
            let blocked = match (ray.blocked_by, ray.blocked_at) {
                (Some(object), Some(t)) => format!("blocked by object {object} at t = {t:.3e}"),
                _ => "not blocked".to_owned(),
            };
            writeln!(f, "           distance {distance}, {blocked}")?;
        }
        None => writeln!(f, "  {}  no shadow ray traced", direct.light)?,
    }
    writeln!(f, "  direct   {}", triple(direct.brings))
}

/// How the path goes on.
fn write_next(f: &mut Formatter, next: &Next, bounces_left: u32) -> fmt::Result {
    writeln!(
        f,
        "  next     {}: d' = {}",
        next.kind,
        triple(next.direction)
    )?;
    if let (Some(cos), Some(pdf)) = (next.cos, next.pdf) {
        writeln!(
            f,
            "           cos(theta) = {cos:.4}, pdf = cos(theta) / pi = {pdf:.4}"
        )?;
    }
    if let Some(fresnel) = next.fresnel {
        writeln!(f, "           F = {fresnel:.4}")?;
    }
    match next.survival {
        Some(s) => writeln!(
            f,
            "           past the bounce limit: Russian roulette let it go on (probability {s}), weight x 1/{s}"
        )?,
        None => writeln!(f, "           bounces still allowed: {bounces_left}")?,
    }
    writeln!(f, "           weight {}", triple(next.weight))
}

/// Three numbers as the probe writes them: `(0.800, 0.200, 0.200)`.
pub fn triple(v: [Real; 3]) -> String {
    format!("({:.4}, {:.4}, {:.4})", v[0], v[1], v[2])
}
