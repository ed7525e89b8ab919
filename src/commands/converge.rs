//! `raycourse converge <stage>`: how fast a stage's error falls, against samples and
//! against time, measured against a converged reference.

use std::num::NonZeroU32;
use std::path::{Path, PathBuf};

use clap::builder::PossibleValuesParser;
use clap::{ArgMatches, FromArgMatches, Parser};
use indicatif::ProgressBar;
use raycourse::engines::render_reporting;
use raycourse::maths::Real;
use raycourse::render::Film;
use raycourse::render::cache::{Folder, cached_render, reference_file};
use raycourse::scene::beyond::Beyond;
use raycourse::scene_file::beyond::{BeyondOverrides, parse_with_beyond};
use raycourse::studies::convergence::{Rung, climb, fitted_slope, sample_ladder};
use raycourse::studies::variant::{Edit, Variant, comparison, comparison_names};
use raycourse::{Disk, Overrides, Scene, stages};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::options::WorkArgs;
use crate::commands::output::{progress_bar, write};
use crate::commands::plot::plot_rungs;
use raycourse::messages::language::Language;

/// Measure how fast a stage's error falls: render a reference (cached), then the
/// sample counts 1, 2, 4, ... up to `--max-spp`, timing each and measuring its
/// error; write `<out>.csv` and a log-log plot `<out>.png`, print the fitted
/// slopes and each variant's efficiency 1 / (RMSE^2 x seconds).
#[derive(Parser)]
#[command(name = "converge")]
struct ConvergeArgs {
    /// A stage's name (see `list`) or a scene file.
    scene: String,
    /// Largest sample count of the ladder.
    #[arg(long, default_value = "256")]
    max_spp: NonZeroU32,
    /// Samples per pixel of the reference image.
    #[arg(long, default_value = "4096")]
    reference_spp: NonZeroU32,
    /// A built-in comparison of variants.
    #[arg(long, value_parser = PossibleValuesParser::new(comparison_names()))]
    compare: Option<String>,
    /// A variant to compare, `label:key=value,...` with scene-file keys such as
    /// `render.bounces=2` (repeat for more).
    #[arg(long)]
    variant: Vec<String>,
    /// Edits of the reference, `key=value,...` (default: the scene as it is, or
    /// the comparison's own).
    #[arg(long)]
    reference: Option<String>,
    /// Label of the rows when there are no variants (default: the scene's name).
    #[arg(long)]
    label: Option<String>,
    /// Folder of cached reference images.
    #[arg(long, default_value = "out/reference")]
    cache: PathBuf,
    /// Output files without extension (default: out/converge/<scene>).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Image width in pixels.
    #[arg(long)]
    width: Option<NonZeroU32>,
    /// Image height in pixels.
    #[arg(long)]
    height: Option<NonZeroU32>,
    #[command(flatten)]
    work: WorkArgs,
    /// Render with the fast engine, beyond the course: the same images, in less
    /// time.
    #[arg(long)]
    fast: bool,
}

/// The `converge` command.
pub const VERB: Verb = Verb {
    rank: 6,
    command: <ConvergeArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

/// Seed of every reference render (the ladder keeps the scene's seed), so that the
/// reference's own remaining noise is independent of the renders it measures.
const REFERENCE_SEED: u64 = 0x5eed_f00d;

/// A study's scene file and how it is rendered.
struct Study<'a> {
    args: &'a ConvergeArgs,
    /// The scene file's text and path.
    source: (String, PathBuf),
}

impl Study<'_> {
    /// The scene with `edits`, `samples` per pixel and `seed` (the file's if
    /// `None`), and the edited file's text.
    fn scene(
        &self,
        edits: Vec<Edit>,
        samples: NonZeroU32,
        seed: Option<u64>,
    ) -> Result<((Scene, Beyond), String), Failure> {
        let (source, path) = &self.source;
        let text = Variant {
            label: String::new(),
            edits,
        }
        .apply(source)
        .map_err(Failure::input)?;
        let overrides = Overrides {
            width: self.args.width,
            height: self.args.height,
            samples: Some(samples),
            seed,
            ..Overrides::default()
        };
        let beyond = BeyondOverrides {
            fast: self.args.fast,
            ..BeyondOverrides::default()
        };
        let scene = parse_with_beyond(&text, path, &overrides, &beyond, &Disk)?;
        Ok((scene, text))
    }

    /// The variants to climb, and the edits that make the reference.
    fn variants(&self) -> Result<(Vec<Variant>, Vec<Edit>), Failure> {
        let args = self.args;
        let (mut chosen, mut reference) = args
            .compare
            .as_deref()
            .and_then(comparison)
            .unwrap_or_default();
        for text in &args.variant {
            chosen.push(Variant::parse(text).map_err(Failure::input)?);
        }
        if let Some(text) = &args.reference {
            reference = Variant::parse(&format!("reference:{text}"))
                .map_err(Failure::input)?
                .edits;
        }
        if chosen.is_empty() {
            let label = args.label.clone().unwrap_or_else(|| args.scene.clone());
            chosen.push(Variant {
                label,
                edits: vec![],
            });
        }
        Ok((chosen, reference))
    }
}

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = ConvergeArgs::from_arg_matches(matches)?;
    let study = Study {
        args: &args,
        source: scene_source(&args.scene)?,
    };
    let (variants, reference_edits) = study.variants()?;
    // Every variant's scene is read before the reference is rendered, so that a bad
    // one is refused at once.
    let scenes = variants
        .iter()
        .map(|v| {
            study
                .scene(v.edits.clone(), NonZeroU32::MIN, None)
                .map(|s| s.0)
        })
        .collect::<Result<Vec<(Scene, Beyond)>, Failure>>()?;
    let pool = args.work.pool()?;
    let ladder = sample_ladder(args.max_spp.get());
    let (truth, text) = study.scene(reference_edits, args.reference_spp, Some(REFERENCE_SEED))?;
    let truth = (&truth.0, &truth.1);
    let rows = u64::from(truth.0.camera.height);
    let work = ladder.iter().map(|&n| u64::from(n)).sum::<u64>() * variants.len() as u64;
    let bar = progress_bar(
        rows * (work + u64::from(args.reference_spp.get())),
        "",
        args.work.quiet,
    );
    let reference = pool.install(|| reference(&args, truth, &text, &bar))?;
    let mut rungs = vec![];
    for (variant, scene) in variants.iter().zip(scenes) {
        bar.set_message(variant.label.clone());
        let progress = |done| bar.inc(done);
        rungs.extend(pool.install(|| climb(&variant.label, scene, &ladder, &reference, &progress)));
    }
    bar.finish_and_clear();
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| Path::new("out/converge").join(&args.scene));
    println!(
        "{}: {}x{}, reference {} spp ({}), {} threads -> {}",
        args.scene,
        truth.0.camera.width,
        truth.0.camera.height,
        args.reference_spp,
        reference_file(&args.cache, &text, truth.0).display(),
        pool.current_num_threads(),
        out.with_extension("csv").display()
    );
    report(&args, &variants, &rungs, &out)
}

/// The scene file text of `name` (a stage or a `.toml` file) and its path.
fn scene_source(name: &str) -> Result<(String, PathBuf), Failure> {
    if let Some(stage) = stages().find(|s| s.name == name) {
        return Ok((stage.source.to_owned(), stage.file()));
    }
    let path = PathBuf::from(name);
    if path.extension().is_none_or(|e| e != "toml") {
        return Err(Failure::Input(format!(
            "`{name}` is neither a stage of this build (see `raycourse list`) nor a .toml scene file"
        )));
    }
    let source = raycourse::scene_file::load::read_source(&path)?;
    Ok((source, path))
}

/// The reference image of `truth` (its file's `text`), from the cache when it is
/// there, rendered and cached otherwise ([`cached_render`]); a cache that cannot be
/// written is said, and the study goes on. The cache key holds nothing that prints
/// differently in single precision, so both builds share a reference.
fn reference(
    args: &ConvergeArgs,
    (truth, beyond): (&Scene, &Beyond),
    text: &str,
    bar: &ProgressBar,
) -> Result<Film, Failure> {
    bar.set_message(format!("reference, {} spp", truth.settings.samples));
    let progress = |done| bar.inc(done);
    let render = |progress: &(dyn Fn(u64) + Sync)| render_reporting(truth, beyond, progress).film;
    let (film, saved) = cached_render(&Folder(&args.cache), text, truth, &progress, render);
    if let Err(e) = saved {
        eprintln!(
            "warning: {}: cannot keep the reference, so the next run renders it again: {e}",
            args.cache.display()
        );
    }
    Ok(film)
}

/// Writes the rungs as `<out>.csv` and a plot `<out>.png`, and prints each
/// variant's error, slopes and efficiency.
fn report(
    args: &ConvergeArgs,
    variants: &[Variant],
    rungs: &[Rung],
    out: &Path,
) -> Result<(), Failure> {
    let mut csv = format!("{}\n", Rung::CSV_HEADER);
    for rung in rungs {
        csv += &rung.csv();
        csv.push('\n');
    }
    write(&out.with_extension("csv"), csv.as_bytes())?;
    for variant in variants {
        let mine: Vec<&Rung> = rungs
            .iter()
            .filter(|r| r.variant == variant.label)
            .collect();
        let last = mine.last().expect("the ladder has at least one rung");
        let slope = |x: &dyn Fn(&Rung) -> Real| {
            let points: Vec<_> = mine.iter().map(|r| (x(r), r.error.rmse)).collect();
            fitted_slope(&points).map_or("-".into(), |s| format!("{s:.3}"))
        };
        println!(
            "  {}: RMSE {:.4e} at {} spp in {:.3} s; slope {} against samples, {} against time; efficiency {:.4e}",
            variant.label,
            last.error.rmse,
            last.samples,
            last.seconds,
            slope(&|r| r.samples as Real),
            slope(&|r| r.seconds),
            last.efficiency()
        );
    }
    let title = match &args.compare {
        Some(comparison) => format!(
            "{} ({comparison}): error against samples and time",
            args.scene
        ),
        None => format!("{}: error against samples and time", args.scene),
    };
    match plot_rungs(&title, rungs, Language::English) {
        Some(png) => {
            write(&out.with_extension("png"), &png)?;
            println!("  plot -> {}", out.with_extension("png").display());
        }
        None => println!("  every image equals the reference: nothing to plot"),
    }
    Ok(())
}
