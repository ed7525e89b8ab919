//! The samplers' distributions, as every right answer gives them: draws sorted into
//! cells that the chapter's density makes equally likely, and a chi-square test of
//! the counts. Another order of the random numbers, another map from the square,
//! passes; a density that is off fails, with the cell that is the most off named.

use raycourse::maths::random::{pixel_rng, uniform_pair};
use raycourse::maths::{PI, Real};

use super::n;
use crate::say;

/// How many draws each cell receives on average.
const PER_CELL: usize = 80;

/// The bands of a sampler's radial variable (the one its density makes uniform),
/// and as many sectors of azimuth: the cells are a band and a sector.
const BANDS: usize = 8;

/// The cells of a sampler's test.
const CELLS: usize = BANDS * BANDS;

/// How many times a sampler is drawn.
pub const DRAWS: usize = CELLS * PER_CELL;

/// The standard normal quantile of the test's level: a right sampler fails with
/// probability `1e-6`, and since the draws are seeded, a right answer that passes
/// once passes every time.
const Z_OF_LEVEL: f64 = 4.753;

/// The uniform numbers a sampler is tried at beyond its random draws: 0, the
/// smallest positive number, 1/2 and the largest number below 1 (`1 - 2^-53` in
/// double precision), each paired with each.
pub fn end_points() -> Vec<(Real, Real)> {
    let ends = [0.0, Real::MIN_POSITIVE, 0.5, 1.0 - Real::EPSILON / 2.0];
    ends.iter()
        .flat_map(|&u1| ends.iter().map(move |&u2| (u1, u2)))
        .collect()
}

/// `(u1, u2) = (a, b)` as the book writes it, a number next to 1 as `1 - e`.
pub fn at(u1: Real, u2: Real) -> String {
    let s = crate::words::separator();
    let u = |x: Real| {
        if x > 0.999 && x < 1.0 {
            format!("1 - {}", n(1.0 - x))
        } else {
            n(x)
        }
    };
    format!("(u1{s}u2) = ({}{s}{})", u(u1), u(u2))
}

/// The cell, among `bins` equal parts of `[0, 1)`, of `x`; the last for `x = 1`.
fn bin(x: Real, bins: usize) -> usize {
    ((x * bins as Real).max(0.0) as usize).min(bins - 1)
}

/// The cell of an azimuth `phi = atan2(y, x)` among `bins` equal parts of the
/// circle, and the bounds of a cell in degrees.
fn azimuth_bin(y: Real, x: Real, bins: usize) -> usize {
    bin(y.atan2(x) / (2.0 * PI) + 0.5, bins)
}

/// The azimuths of cell `k` among `bins`, in degrees, from -180.
fn azimuths(k: usize, bins: usize) -> (Real, Real) {
    let width = 360.0 / bins as Real;
    (-180.0 + k as Real * width, -180.0 + (k + 1) as Real * width)
}

/// The cell of a draw whose radial variable (uniform on `[0, 1]` under the
/// chapter's density) is `radial` and whose azimuth is `atan2(y, x)`.
pub fn cell(radial: Real, y: Real, x: Real) -> usize {
    bin(radial, BANDS) * BANDS + azimuth_bin(y, x, BANDS)
}

/// The words for cell `k`, the radial variable named `radial`.
pub fn describe(radial: &str, k: usize) -> String {
    let (low, high) = azimuths(k % BANDS, BANDS);
    let band = (k / BANDS) as Real / BANDS as Real;
    say!(
        "generated-sampling-from-to-the-azimuth-from-to",
        band = n(band),
        band2 = n(band + 1.0 / BANDS as Real),
        low = n(low),
        high = n(high),
        radial = radial
    )
}

/// Draws a sampler `DRAWS` times with uniform numbers from a fixed seed; `place`
/// checks a draw (its `Err` says what is wrong with it) and gives its [`cell`]. Fails when the counts are further from equal than chance allows:
/// `X^2 = sum (count - E)^2 / E` above its quantile of level `1e-6` (the
/// Wilson-Hilferty approximation for `CELLS - 1` degrees of freedom), naming the
/// cell the most off through `describe`.
pub fn spread(
    seed: u64,
    mut place: impl FnMut(Real, Real) -> Result<usize, String>,
    describe: impl Fn(usize) -> String,
) -> Result<(), String> {
    let (cells, draws) = (CELLS, DRAWS);
    let mut counts = vec![0usize; cells];
    for k in 0..draws {
        let (u1, u2) = uniform_pair(&mut pixel_rng(seed, k as u64));
        counts[place(u1, u2)?] += 1;
    }
    let expected = PER_CELL as f64;
    let statistic: f64 = counts
        .iter()
        .map(|&c| (c as f64 - expected).powi(2) / expected)
        .sum();
    let df = (cells - 1) as f64;
    let limit = df * (1.0 - 2.0 / (9.0 * df) + Z_OF_LEVEL * (2.0 / (9.0 * df)).sqrt()).powi(3);
    if statistic <= limit {
        return Ok(());
    }
    let worst = (0..cells)
        .max_by(|&a, &b| {
            let off = |c: usize| (counts[c] as f64 - expected).abs();
            off(a).total_cmp(&off(b))
        })
        .unwrap_or(0);
    Err(say!(
        "generated-sampling-of-draws-fell-where-the-chapter",
        counts_worst = counts[worst],
        describe_worst = describe(worst),
        draws = draws,
        PER_CELL = PER_CELL,
        statistic_written = format!("{:.0}", statistic),
        cells = cells,
        limit_written = format!("{:.0}", limit)
    ))
}
