//! `raycourse plot <csv...>`: the rows of convergence studies on one log-log plot,
//! drawn with plotters into a PNG. The font is built in, so plotting needs no
//! system fonts.

use std::path::PathBuf;
use std::sync::Once;

use clap::{ArgMatches, FromArgMatches, Parser};
use plotters::prelude::*;
use plotters::style::FontStyle;
use raycourse::maths::to_double;
use raycourse::messages::language::Language;
use raycourse::messages::say;
use raycourse::render::png::encode_rgb8;
use raycourse::studies::convergence::{Rung, axis_label, read_rungs};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::output::write;

/// Plot the rows of one or more CSV files written by `converge` on one log-log
/// plot (for instance the same study from the double- and single-precision
/// builds).
#[derive(Parser)]
#[command(name = "plot")]
struct PlotArgs {
    /// The CSV files.
    #[arg(required = true)]
    csv: Vec<PathBuf>,
    /// The PNG to write.
    #[arg(long)]
    out: PathBuf,
    /// The plot's title.
    #[arg(long, default_value = "")]
    title: String,
    /// The language of the axes and the legend, `en` or `fr` (the variants' labels
    /// translated word by word, numbers with a decimal comma), for the book's
    /// French edition.
    #[arg(long, value_parser = ["en", "fr"], default_value = "en")]
    lang: String,
}

/// The `plot` command.
pub const VERB: Verb = Verb {
    rank: 7,
    command: <PlotArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = PlotArgs::from_arg_matches(matches)?;
    let mut rungs = vec![];
    for path in &args.csv {
        let text = std::fs::read_to_string(path)
            .map_err(|e| Failure::Input(format!("{}: cannot read: {e}", path.display())))?;
        let rows =
            read_rungs(&text).map_err(|m| Failure::Input(format!("{}: {m}", path.display())))?;
        rungs.extend(rows);
    }
    let png = plot_rungs(&args.title, &rungs, Language::from_locale(&args.lang))
        .ok_or_else(|| Failure::Input("no row has an error above 0: nothing to plot".into()))?;
    write(&args.out, &png)?;
    println!("{} rows -> {}", rungs.len(), args.out.display());
    Ok(())
}

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

/// A plot's drawing area: one panel.
type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;

/// One variant's points on a panel: its label and `(x, RMSE)` pairs.
type Line = (String, Vec<(f64, f64)>);

// ANCHOR: plot
/// A PNG of the rungs' RMSE against samples per pixel (left) and against seconds
/// (right), both axes logarithmic, one line per variant in order of appearance, and
/// a grey guide of slope -1/2, the rate of an unbiased Monte Carlo estimate. Rungs
/// with no error (an exact image) have no logarithm and are left out; `None` when
/// no rung is left. Its words and numbers are in `language`.
pub fn plot_rungs(title: &str, rungs: &[Rung], language: Language) -> Option<Vec<u8>> {
    let shown: Vec<&Rung> = rungs.iter().filter(|r| r.error.rmse > 0.0).collect();
    if shown.is_empty() {
        return None;
    }
    register_font();
    let samples = |r: &Rung| f64::from(r.samples);
    let seconds = |r: &Rung| to_double(r.seconds).max(1e-4);
    let mut pixels = vec![0u8; (SIZE.0 * SIZE.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, SIZE).into_drawing_area();
        root.fill(&WHITE).ok()?;
        let root = root.titled(title, ("sans-serif", 24)).ok()?;
        let (left, right) = root.split_horizontally(SIZE.0 / 2);
        let samples_name = say(language, "plot-samples", &[]);
        let seconds_name = say(language, "plot-seconds", &[]);
        draw_panel(
            &left,
            &lines(&shown, &samples, language),
            &samples_name,
            language,
        )?;
        draw_panel(
            &right,
            &lines(&shown, &seconds, language),
            &seconds_name,
            language,
        )?;
        root.present().ok()?;
    }
    Some(encode_rgb8(&pixels, SIZE.0, SIZE.1))
}
// ANCHOR_END: plot

/// The rungs as one line per variant, in order of appearance, with `x_of` as `x`,
/// each labelled in `language`.
fn lines(shown: &[&Rung], x_of: &dyn Fn(&Rung) -> f64, language: Language) -> Vec<Line> {
    let mut lines: Vec<(&str, Vec<(f64, f64)>)> = vec![];
    for rung in shown {
        let point = (x_of(rung), to_double(rung.error.rmse));
        match lines.iter_mut().find(|(label, _)| *label == rung.variant) {
            Some((_, points)) => points.push(point),
            None => lines.push((&rung.variant, vec![point])),
        }
    }
    lines
        .into_iter()
        .map(|(label, points)| (variant_label(label, language), points))
        .collect()
}

/// The catalogue's words of the studies' variant labels (`plot-word-...`), the
/// longer first where one holds another.
const WORDS: &[&str] = &[
    "bounces",
    "bounce",
    "brute-force",
    "bounding-box",
    "fast-bvh",
    "light-sampling",
    "naive",
    "limit",
    "leaf",
    "bilinear",
    "nearest",
    "single-fast",
    "double-fast",
    "single",
    "independent",
    "stratified",
    "sobol",
    "adaptive",
];

/// A variant's label in `language`: its words translated and its numbers written
/// as the language writes them (`sobol + adaptive 0.05` reads `Sobol + adaptatif
/// 0,05` in French); names such as `Mitsuba llvm_ad_rgb` are left as they are.
fn variant_label(label: &str, language: Language) -> String {
    let words = WORDS.iter().fold(label.to_owned(), |text, word| {
        let id = format!("plot-word-{word}");
        text.replace(&say(Language::English, &id, &[]), &say(language, &id, &[]))
    });
    numbers_in(&words, language)
}

/// `text` with each decimal number in it (digits, a point, digits) written as
/// `language` writes numbers; the rest as it is (`1e-3`, `2.`).
fn numbers_in(text: &str, language: Language) -> String {
    let mut written = String::new();
    let mut rest = text;
    while let Some(start) = rest.find(|c: char| c.is_ascii_digit()) {
        written.push_str(&rest[..start]);
        let length = rest[start..]
            .find(|c: char| !c.is_ascii_digit() && c != '.')
            .unwrap_or(rest.len() - start);
        let token = rest[start..start + length].trim_end_matches('.');
        let value = token.parse::<f64>().ok().filter(|_| token.contains('.'));
        match value {
            Some(value) => {
                written.push_str(&say(language, "plot-number", &[("value", value.into())]))
            }
            None => written.push_str(token),
        }
        rest = &rest[start + token.len()..];
    }
    written + rest
}

/// The range of a logarithmic axis holding `values`, with some room around them.
fn axis(values: impl Iterator<Item = f64> + Clone) -> std::ops::Range<f64> {
    let low = values.clone().fold(f64::INFINITY, f64::min);
    let high = values.fold(0.0, f64::max);
    low / 1.5..high * 1.5
}

/// Draws `lines` on `area`: log-log axes, a guide of slope -1/2 through the first
/// line's first point, each line in its own colour, and the legend, in `language`.
fn draw_panel(area: &Area, lines: &[Line], x_name: &str, language: Language) -> Option<()> {
    let tick = |v: &f64| numbers_in(&axis_label(*v), language);
    let points = || lines.iter().flat_map(|(_, p)| p.iter().copied());
    let (x_range, y_range) = (axis(points().map(|p| p.0)), axis(points().map(|p| p.1)));
    let mut chart = ChartBuilder::on(area)
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(72)
        .build_cartesian_2d(x_range.clone().log_scale(), y_range.log_scale())
        .ok()?;
    chart
        .configure_mesh()
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .x_desc(x_name)
        .y_desc(say(language, "plot-error", &[]))
        .label_style(("sans-serif", 15))
        .draw()
        .ok()?;
    let (x0, y0) = lines[0].1[0];
    let guide = [x_range.start, x_range.end].map(|x| (x, y0 * (x / x0).powf(-0.5)));
    let grey = RGBColor(150, 150, 150);
    chart
        .draw_series(DashedLineSeries::new(guide, 6, 4, grey.stroke_width(1)))
        .ok()?
        .label(say(language, "plot-slope", &[]))
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], grey));
    for (i, (label, points)) in lines.iter().enumerate() {
        let colour = Palette99::pick(i).to_rgba();
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
            .ok()?
            .label(label.as_str())
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
        .ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every variant label of the book's studies reads in French, words and
    /// numbers, and in English as it is.
    #[test]
    fn variant_labels_read_in_french() {
        let cases = [
            ("1 bounce", "1 rebond"),
            ("8 bounces", "8 rebonds"),
            ("fast BVH", "BVH rapide"),
            ("bounding box", "boîte englobante"),
            ("limit 2 + roulette", "limite 2 + roulette"),
            ("single-fast", "simple, moteur rapide"),
            ("single", "simple"),
            ("sobol + adaptive 0.05", "Sobol + adaptatif 0,05"),
            ("Mitsuba llvm_ad_rgb", "Mitsuba llvm_ad_rgb"),
        ];
        for (english, french) in cases {
            assert_eq!(variant_label(english, Language::French), french);
            assert_eq!(variant_label(english, Language::English), english);
        }
    }

    /// Only a number with a point between two digits is written in French.
    #[test]
    fn decimal_numbers_are_written_as_the_language_writes_them() {
        let text = "0.05, 1e-3, 12.5 and 2.";
        assert_eq!(
            numbers_in(text, Language::French),
            "0,05, 1e-3, 12,5 and 2."
        );
        assert_eq!(numbers_in(text, Language::English), text);
        assert_eq!(numbers_in("1234.5", Language::French), "1234,5");
    }
}
