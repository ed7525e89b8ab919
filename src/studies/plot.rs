//! Log-log plots of a convergence study, drawn with plotters into a PNG. The font is
//! built in, so plotting needs no system fonts.

use std::sync::Once;

use plotters::prelude::*;
use plotters::style::FontStyle;

use crate::maths::numbers::to_double;
use crate::render::png::encode_rgb8;
use crate::studies::convergence::Rung;

/// Width and height of a plot, in pixels: two panels side by side.
const SIZE: (u32, u32) = (1200, 500);

/// DejaVu Sans (see `assets/fonts/DejaVuSans.LICENSE`).
const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Makes the built-in font plotters' `sans-serif`, once.
fn register_font() {
    static REGISTER: Once = Once::new();
    REGISTER.call_once(|| {
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
            .unwrap_or_else(|_| panic!("the built-in font is a valid TrueType font"));
    });
}

// ANCHOR: plot
/// A PNG of the rungs' RMSE against samples per pixel (left) and against seconds
/// (right), both axes logarithmic, one line per variant in order of appearance.
/// Rungs with no error (an exact image) have no logarithm and are left out; `None`
/// when no rung is left.
pub fn plot_rungs(title: &str, rungs: &[Rung]) -> Option<Vec<u8>> {
    let shown: Vec<&Rung> = rungs.iter().filter(|r| r.error.rmse > 0.0).collect();
    if shown.is_empty() {
        return None;
    }
    register_font();
    let mut variants: Vec<&str> = vec![];
    for rung in &shown {
        if !variants.contains(&rung.variant.as_str()) {
            variants.push(&rung.variant);
        }
    }
    let samples = |r: &Rung| f64::from(r.samples);
    let seconds = |r: &Rung| to_double(r.seconds).max(1e-4);
    let mut pixels = vec![0u8; (SIZE.0 * SIZE.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, SIZE).into_drawing_area();
        root.fill(&WHITE).ok()?;
        let root = root.titled(title, ("sans-serif", 24)).ok()?;
        let (left, right) = root.split_horizontally(SIZE.0 / 2);
        for (area, x_of, x_name) in [
            (left, &samples as &dyn Fn(&Rung) -> f64, "samples per pixel"),
            (right, &seconds, "seconds"),
        ] {
            let range = |f: &dyn Fn(&Rung) -> f64| {
                let values = shown.iter().map(|r| f(r));
                let low = values.clone().fold(f64::INFINITY, f64::min);
                let high = values.fold(0.0, f64::max);
                low / 1.5..high * 1.5
            };
            let rmse = |r: &Rung| to_double(r.error.rmse);
            let mut chart = ChartBuilder::on(&area)
                .margin(16)
                .x_label_area_size(44)
                .y_label_area_size(72)
                .build_cartesian_2d(range(x_of).log_scale(), range(&rmse).log_scale())
                .ok()?;
            chart
                .configure_mesh()
                .x_label_formatter(&|v| tick(*v))
                .y_label_formatter(&|v| tick(*v))
                .x_desc(x_name)
                .y_desc("RMSE (linear radiance)")
                .label_style(("sans-serif", 15))
                .draw()
                .ok()?;
            for (i, variant) in variants.iter().enumerate() {
                let colour = Palette99::pick(i).to_rgba();
                let points: Vec<(f64, f64)> = shown
                    .iter()
                    .filter(|r| r.variant == *variant)
                    .map(|r| (x_of(r), rmse(r)))
                    .collect();
                chart
                    .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
                    .ok()?
                    .label(*variant)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(2))
                    });
                chart
                    .draw_series(points.iter().map(|p| Circle::new(*p, 4, colour.filled())))
                    .ok()?;
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .label_font(("sans-serif", 15))
                .background_style(WHITE.mix(0.9))
                .border_style(BLACK)
                .draw()
                .ok()?;
        }
        root.present().ok()?;
    }
    Some(encode_rgb8(&pixels, SIZE.0, SIZE.1))
}
// ANCHOR_END: plot

/// A tick label: plain for everyday magnitudes, `1e5` style otherwise.
fn tick(v: f64) -> String {
    if (0.01..10_000.0).contains(&v) {
        format!("{}", (v * 1e4).round() / 1e4)
    } else {
        format!("{v:.0e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maths::numbers::Real;
    use crate::studies::convergence::ImageError;

    fn rung(variant: &str, samples: u32, rmse: Real) -> Rung {
        Rung {
            variant: variant.into(),
            samples,
            seconds: samples as Real * 0.01,
            error: ImageError { rmse, rel_mse: 0.0 },
        }
    }

    #[test]
    fn plots_are_pngs_of_the_plot_size_with_two_colours_of_lines() {
        let rungs: Vec<Rung> = [1, 2, 4, 8]
            .iter()
            .flat_map(|&n| [rung("a", n, 1.0 / n as Real), rung("b", n, 2.0 / n as Real)])
            .collect();
        let png = plot_rungs("test", &rungs).unwrap();
        let image = image::load_from_memory(&png).unwrap().to_rgb8();
        assert_eq!(image.dimensions(), SIZE);
        let colour = |i: usize| {
            let c = Palette99::pick(i).to_rgba();
            [c.0, c.1, c.2]
        };
        for i in 0..2 {
            let count = image.pixels().filter(|p| p.0 == colour(i)).count();
            assert!(count > 500, "variant {i}: {count} pixels of its colour");
        }
        let text = image.pixels().filter(|p| p.0 == [0, 0, 0]).count();
        assert!(text > 1000, "{text} black pixels: labels and frames drawn");
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick(100000.0), "1e5");
        assert_eq!(tick(20.0), "20");
        assert_eq!(tick(0.1), "0.1");
        assert_eq!(tick(0.001), "1e-3");
    }

    #[test]
    fn exact_images_have_no_plot() {
        assert_eq!(plot_rungs("exact", &[rung("a", 1, 0.0)]), None);
    }
}
