//! Measuring the trade between speed and accuracy: a render's error against a
//! reference, at a ladder of sample counts, with its time.

use std::time::Instant;

use crate::engines::render_reporting;
use crate::maths::Real;
use crate::render::Film;
use crate::scene::Scene;
use crate::scene::beyond::Beyond;

/// How far an image is from the reference, over every pixel and channel of linear
/// radiance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageError {
    /// Root mean square error, `sqrt(mean((x - r)^2))`: in radiance units, so
    /// bright regions weigh most.
    pub rmse: Real,
    /// Relative mean square error, `mean((x - r)^2 / (r^2 + 0.01))`: every pixel
    /// weighs alike, whatever its brightness (the `0.01` keeps black pixels finite).
    pub rel_mse: Real,
}

// ANCHOR: image_error
/// The error of `image` against `reference`, which must have the same size.
pub fn image_error(image: &Film, reference: &Film) -> ImageError {
    assert_eq!(
        (image.width, image.height),
        (reference.width, reference.height),
        "an image and its reference have the same size"
    );
    let (mut squared, mut relative) = (0.0, 0.0);
    for (x, r) in image.pixels.iter().zip(&reference.pixels) {
        let d = *x - *r;
        squared += (d * d).element_sum();
        relative += (d * d / (*r * *r + 0.01)).element_sum();
    }
    let n = 3.0 * image.pixels.len() as Real;
    ImageError {
        rmse: (squared / n).sqrt(),
        rel_mse: relative / n,
    }
}
// ANCHOR_END: image_error

/// Sample counts `1, 2, 4, ...` up to `max` (included when a power of two).
pub fn sample_ladder(max: u32) -> Vec<u32> {
    std::iter::successors(Some(1u32), |n| n.checked_mul(2))
        .take_while(|&n| n <= max)
        .collect()
}

// ANCHOR: slope
/// The slope of the least-squares line through `(log x, log y)`: the exponent `k`
/// of a power law `y = c x^k`. Points with a zero or negative coordinate have no
/// logarithm and are left out; `None` when fewer than two remain or all `x` agree.
/// Monte Carlo error falls as `n^(-1/2)`: a slope of `-0.5` against samples.
pub fn fitted_slope(points: &[(Real, Real)]) -> Option<Real> {
    let logs: Vec<(Real, Real)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    let n = logs.len() as Real;
    let mean_x = logs.iter().map(|p| p.0).sum::<Real>() / n;
    let mean_y = logs.iter().map(|p| p.1).sum::<Real>() / n;
    let sxx: Real = logs.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    let sxy: Real = logs.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    (logs.len() >= 2 && sxx > 0.0).then(|| sxy / sxx)
}
// ANCHOR_END: slope

/// One render of the ladder: a variant at a sample count, its time and its error.
#[derive(Clone, Debug, PartialEq)]
pub struct Rung {
    /// The variant's label.
    pub variant: String,
    /// Samples per pixel.
    pub samples: u32,
    /// Wall-clock seconds of the render (all worker threads).
    pub seconds: Real,
    /// Its error against the reference.
    pub error: ImageError,
}

impl Rung {
    /// Efficiency, `1 / (RMSE^2 x seconds)`: for an unbiased estimator the variance
    /// falls as `1/n` while the time grows as `n`, so this stays constant along the
    /// ladder and compares methods at equal time. Infinite for an exact image.
    pub fn efficiency(&self) -> Real {
        1.0 / (self.error.rmse * self.error.rmse * self.seconds)
    }

    /// The CSV header matching [`Rung::csv`].
    pub const CSV_HEADER: &'static str = "variant,samples,seconds,rmse,rel_mse,efficiency";

    /// The rung as one CSV line.
    pub fn csv(&self) -> String {
        format!(
            "{},{},{:.6},{:e},{:e},{:e}",
            self.variant,
            self.samples,
            self.seconds,
            self.error.rmse,
            self.error.rel_mse,
            self.efficiency()
        )
    }
}

/// Reads rungs written by [`Rung::csv`] under [`Rung::CSV_HEADER`] (the efficiency
/// column is recomputed, not read). An error names the line and what is wrong.
pub fn read_rungs(text: &str) -> Result<Vec<Rung>, String> {
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, header)) if header.trim() == Rung::CSV_HEADER => {}
        _ => {
            return Err(format!(
                "line 1: expected the header `{}`",
                Rung::CSV_HEADER
            ));
        }
    }
    lines
        .filter(|(_, line)| !line.trim().is_empty())
        .map(|(i, line)| {
            let fields: Vec<&str> = line.split(',').collect();
            let [variant, samples, seconds, rmse, rel_mse, _] = fields[..] else {
                return Err(format!(
                    "line {}: expected 6 fields, found {}",
                    i + 1,
                    fields.len()
                ));
            };
            let number = |name: &str, text: &str| {
                text.trim()
                    .parse::<Real>()
                    .ok()
                    .filter(|v| v.is_finite() && *v >= 0.0)
                    .ok_or_else(|| format!("line {}: {name} `{text}` is not a number >= 0", i + 1))
            };
            Ok(Rung {
                variant: variant.to_owned(),
                samples: samples.trim().parse().map_err(|_| {
                    format!("line {}: samples `{samples}` is not a whole number", i + 1)
                })?,
                seconds: number("seconds", seconds)?,
                error: ImageError {
                    rmse: number("rmse", rmse)?,
                    rel_mse: number("rel_mse", rel_mse)?,
                },
            })
        })
        .collect()
}

/// Renders `scene` with the settings `beyond` at each sample count of `ladder` on
/// the current thread pool and measures each image against `reference`, reporting
/// to `progress` as [`render_reporting`] does.
pub fn climb(
    variant: &str,
    (mut scene, beyond): (Scene, Beyond),
    ladder: &[u32],
    reference: &Film,
    progress: &(dyn Fn(u64) + Sync),
) -> Vec<Rung> {
    ladder
        .iter()
        .map(|&samples| {
            scene.settings.samples = samples;
            let start = Instant::now();
            let image = render_reporting(&scene, &beyond, progress);
            let seconds = start.elapsed().as_secs_f64() as Real;
            Rung {
                variant: variant.to_owned(),
                samples,
                seconds,
                error: image_error(&image.film, reference),
            }
        })
        .collect()
}

/// A number on a plot's logarithmic axis: plain for everyday magnitudes (at most
/// four decimals), `1e5` style otherwise.
pub fn axis_label(v: f64) -> String {
    if (0.01..10_000.0).contains(&v) {
        format!("{}", (v * 1e4).round() / 1e4)
    } else {
        format!("{v:.0e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maths::Colour;

    #[test]
    fn axis_labels_are_short() {
        assert_eq!(axis_label(100000.0), "1e5");
        assert_eq!(axis_label(20.0), "20");
        assert_eq!(axis_label(0.1), "0.1");
        assert_eq!(axis_label(0.001), "1e-3");
    }

    fn film(values: &[Real]) -> Film {
        Film {
            width: values.len() as u32,
            height: 1,
            pixels: values.iter().map(|&v| Colour::splat(v)).collect(),
        }
    }

    #[test]
    fn errors_of_known_differences() {
        let reference = film(&[1.0, 2.0, 0.0, 4.0]);
        let image = film(&[3.0, 2.0, 0.0, 4.0]);
        let error = image_error(&image, &reference);
        // One pixel of four off by 2 in every channel: mean square 4/4 = 1.
        assert_eq!(error.rmse, 1.0);
        assert!((error.rel_mse - 4.0 / 1.01 / 4.0).abs() < 1e-6);
        assert_eq!(image_error(&reference, &reference).rmse, 0.0);
    }

    #[test]
    fn slope_of_a_power_law_is_its_exponent() {
        let points: Vec<(Real, Real)> = sample_ladder(1024)
            .iter()
            .map(|&n| (n as Real, 3.0 * (n as Real).powf(-0.5)))
            .collect();
        assert!((fitted_slope(&points).unwrap() + 0.5).abs() < 1e-5);
        // Zeros are left out; one point has no slope.
        assert_eq!(fitted_slope(&[(1.0, 0.0), (2.0, 1.0)]), None);
        assert_eq!(fitted_slope(&[(2.0, 1.0), (2.0, 3.0)]), None);
    }

    #[test]
    fn rungs_read_back_from_csv() {
        let rung = Rung {
            variant: "light sampling".into(),
            samples: 16,
            seconds: 0.25,
            error: ImageError {
                rmse: 1.5,
                rel_mse: 0.125,
            },
        };
        let text = format!("{}\n{}\n", Rung::CSV_HEADER, rung.csv());
        assert_eq!(read_rungs(&text), Ok(vec![rung]));
        assert_eq!(
            read_rungs("samples\n").unwrap_err(),
            format!("line 1: expected the header `{}`", Rung::CSV_HEADER)
        );
        let bad = format!("{}\na,1,0.5,x,0,0\n", Rung::CSV_HEADER);
        assert_eq!(
            read_rungs(&bad).unwrap_err(),
            "line 2: rmse `x` is not a number >= 0"
        );
        let short = format!("{}\na,1\n", Rung::CSV_HEADER);
        assert_eq!(
            read_rungs(&short).unwrap_err(),
            "line 2: expected 6 fields, found 2"
        );
    }

    #[test]
    fn ladder_doubles_up_to_the_maximum() {
        assert_eq!(sample_ladder(1), vec![1]);
        assert_eq!(sample_ladder(20), vec![1, 2, 4, 8, 16]);
        assert_eq!(sample_ladder(u32::MAX).len(), 32);
    }

    #[test]
    fn efficiency_is_constant_when_variance_halves_as_time_doubles() {
        let rung = |samples: u32| Rung {
            variant: "mc".into(),
            samples,
            seconds: samples as Real * 0.5,
            error: ImageError {
                rmse: (samples as Real).powf(-0.5),
                rel_mse: 0.0,
            },
        };
        assert_eq!(rung(1).efficiency(), 2.0);
        assert!((rung(64).efficiency() - 2.0).abs() < 1e-5);
        assert_eq!(rung(4).csv(), "mc,4,2.000000,5e-1,0e0,2e0");
    }
}
