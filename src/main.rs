//! The `raycourse` command: list the course's stages, render one, or render any
//! scene file.

use std::num::{NonZeroU32, NonZeroUsize};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::builder::PossibleValuesParser;
use clap::{Args, Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use raycourse::{Overrides, Render, Scene, SceneError, Stage, encode_png, render, stages};

/// Ray tracing, one course session at a time. With no command, renders the last
/// stage of this build into `out/` (the render options apply to it).
#[derive(Parser)]
#[command(version, about, args_conflicts_with_subcommands = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    options: RenderArgs,
}

#[derive(Subcommand)]
enum Command {
    /// List the stages of this build: session, figure, name, title, settings.
    List,
    /// Render a stage of session 1.
    S1 {
        /// The stage.
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(1)))]
        stage: String,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a stage of session 2.
    #[cfg(feature = "s2")]
    S2 {
        /// The stage.
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(2)))]
        stage: String,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a stage of session 3.
    #[cfg(feature = "s3")]
    S3 {
        /// The stage.
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(3)))]
        stage: String,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a stage of session 4.
    #[cfg(feature = "s4")]
    S4 {
        /// The stage.
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(4)))]
        stage: String,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a stage of session 5.
    #[cfg(feature = "s5")]
    S5 {
        /// The stage.
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(5)))]
        stage: String,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a stage of session 6.
    #[cfg(feature = "s6")]
    S6 {
        /// The stage.
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(6)))]
        stage: String,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a stage of session 7.
    #[cfg(feature = "s7")]
    S7 {
        /// The stage.
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(7)))]
        stage: String,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a scene file.
    Render {
        /// The scene file (TOML).
        scene: PathBuf,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render a stage's camera move, the eye rising around the point it looks at,
    /// into an animated GIF (or numbered PNG frames if `--out` ends in `.png`).
    #[cfg(feature = "s7")]
    Animate {
        /// The stage (its camera must have a `look_at` point).
        #[arg(value_parser = PossibleValuesParser::new(raycourse::stage_names(7)))]
        stage: String,
        /// Number of frames.
        #[arg(long, default_value = "24")]
        frames: NonZeroU32,
        /// Plunge angle of the first frame, degrees.
        #[arg(long, default_value_t = 0.0)]
        from: raycourse::Real,
        /// Plunge angle of the last frame, degrees.
        #[arg(long, default_value_t = 30.0)]
        to: raycourse::Real,
        #[command(flatten)]
        options: RenderArgs,
    },
    /// Render the mesh stages (figures 13 to 18) at the course's settings and print
    /// a table of their times beside the course's own.
    #[cfg(feature = "s5")]
    Bench {
        /// Worker threads (default: one per core).
        #[arg(long)]
        threads: Option<NonZeroUsize>,
    },
    /// Trace ray sets (`.rays` files of the Embree benchmark) against a mesh on one
    /// thread and on all, and print Mrays/s with the format's checksums.
    #[cfg(feature = "s6")]
    Rays {
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
    },
    /// Measure how fast a stage's error falls: render a reference (cached), then the
    /// sample counts 1, 2, 4, ... up to `--max-spp`, timing each and measuring its
    /// error; write `<out>.csv` and a log-log plot `<out>.png`, print the fitted
    /// slopes and each variant's efficiency 1 / (RMSE^2 x seconds).
    Converge {
        /// A stage's name (see `list`) or a scene file.
        scene: String,
        /// Largest sample count of the ladder.
        #[arg(long, default_value = "256")]
        max_spp: NonZeroU32,
        /// Samples per pixel of the reference image.
        #[arg(long, default_value = "4096")]
        reference_spp: NonZeroU32,
        /// A built-in comparison of variants.
        #[arg(long, value_parser = PossibleValuesParser::new(raycourse::COMPARISONS))]
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
        /// Worker threads (default: one per core).
        #[arg(long)]
        threads: Option<NonZeroUsize>,
        /// Hide the progress bar.
        #[arg(long, short)]
        quiet: bool,
    },
    /// Plot the rows of one or more CSV files written by `converge` on one log-log
    /// plot (for instance the same study from the double- and single-precision
    /// builds).
    Plot {
        /// The CSV files.
        #[arg(required = true)]
        csv: Vec<PathBuf>,
        /// The PNG to write.
        #[arg(long)]
        out: PathBuf,
        /// The plot's title.
        #[arg(long, default_value = "")]
        title: String,
    },
    /// Render every stage of this build at the course's settings into a folder, as
    /// `<stage>.png`: the book's figures.
    Figures {
        /// The folder.
        #[arg(default_value = "book/src/figures")]
        dir: PathBuf,
        /// Hide the progress bars.
        #[arg(long, short)]
        quiet: bool,
    },
}

/// The hierarchies the `rays` command can time.
#[cfg(feature = "s6")]
#[derive(Clone, Copy, clap::ValueEnum)]
enum BvhKind {
    /// The course's: split in the middle of the longest side.
    Midpoint,
    /// Splits by the surface area heuristic, the course's nodes and traversal.
    Sah,
    /// Splits by the surface area heuristic, compact nodes, triangles in leaf order.
    Fast,
}

/// Settings that replace the scene file's for one render.
#[derive(Args, Default)]
struct RenderArgs {
    /// Image width in pixels.
    #[arg(long)]
    width: Option<NonZeroU32>,
    /// Image height in pixels.
    #[arg(long)]
    height: Option<NonZeroU32>,
    /// Samples per pixel.
    #[arg(long)]
    spp: Option<NonZeroU32>,
    /// Bounce limit for mirrors, glass and indirect light.
    #[arg(long)]
    bounces: Option<u32>,
    /// Seed of the random generators.
    #[arg(long)]
    seed: Option<u64>,
    /// Worker threads (default: one per core).
    #[arg(long)]
    threads: Option<NonZeroUsize>,
    /// Output PNG (default: out/<name>.png).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Hide the progress bar.
    #[arg(long, short)]
    quiet: bool,
}

impl RenderArgs {
    fn overrides(&self) -> Overrides {
        Overrides {
            width: self.width,
            height: self.height,
            samples: self.spp,
            bounces: self.bounces,
            seed: self.seed,
            plunge: None,
        }
    }
}

#[derive(Debug, thiserror::Error)]
enum Failure {
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error("cannot start {threads} worker threads: {source}")]
    Threads {
        threads: usize,
        source: rayon::ThreadPoolBuildError,
    },
    #[cfg(feature = "s7")]
    #[error("stage {0} has no aimed camera (`look_at`) to move")]
    NotAimed(String),
    #[cfg(feature = "s7")]
    #[error("cannot encode the animation: {0}")]
    Gif(image::ImageError),
    #[cfg(feature = "s6")]
    #[error("{}: cannot load the mesh: {message}", path.display())]
    Mesh { path: PathBuf, message: String },
    #[cfg(feature = "s6")]
    #[error(transparent)]
    RaySet(#[from] raycourse::RaySetError),
    #[error(transparent)]
    Variant(#[from] raycourse::VariantError),
    #[error("{}: {message}", path.display())]
    Csv { path: PathBuf, message: String },
    #[error("{0}")]
    Usage(String),
    #[error("{}: cannot write the image: {source}", path.display())]
    Write {
        path: PathBuf,
        source: std::io::Error,
    },
}

impl Failure {
    /// 2 for bad input (as clap's usage errors), 1 for a failure of the machine.
    fn exit_code(&self) -> ExitCode {
        match self {
            Self::Scene(_) | Self::Variant(_) | Self::Csv { .. } | Self::Usage(_) => {
                ExitCode::from(2)
            }
            #[cfg(feature = "s6")]
            Self::Mesh { .. } | Self::RaySet(_) => ExitCode::from(2),
            #[cfg(feature = "s7")]
            Self::NotAimed(_) => ExitCode::from(2),
            _ => ExitCode::FAILURE,
        }
    }
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            eprintln!("error: {failure}");
            failure.exit_code()
        }
    }
}

fn run(cli: Cli) -> Result<(), Failure> {
    match cli.command {
        None => {
            let stage = stages().last().expect("every build has session 1's stages");
            render_stage(stage, &cli.options)
        }
        Some(Command::List) => {
            list();
            Ok(())
        }
        Some(Command::S1 { stage, options }) => render_named(1, &stage, &options),
        #[cfg(feature = "s2")]
        Some(Command::S2 { stage, options }) => render_named(2, &stage, &options),
        #[cfg(feature = "s3")]
        Some(Command::S3 { stage, options }) => render_named(3, &stage, &options),
        #[cfg(feature = "s4")]
        Some(Command::S4 { stage, options }) => render_named(4, &stage, &options),
        #[cfg(feature = "s5")]
        Some(Command::S5 { stage, options }) => render_named(5, &stage, &options),
        #[cfg(feature = "s6")]
        Some(Command::S6 { stage, options }) => render_named(6, &stage, &options),
        #[cfg(feature = "s7")]
        Some(Command::S7 { stage, options }) => render_named(7, &stage, &options),
        Some(Command::Render { scene, options }) => {
            let loaded = raycourse::load_scene(&scene, &options.overrides())?;
            let name = scene
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy());
            let out = Path::new("out").join(format!("{name}.png"));
            render_to_file(&name, &loaded, &options, out)
        }
        #[cfg(feature = "s7")]
        Some(Command::Animate {
            stage,
            frames,
            from,
            to,
            options,
        }) => animate(&stage, frames.get(), (from, to), &options),
        #[cfg(feature = "s5")]
        Some(Command::Bench { threads }) => bench(threads),
        #[cfg(feature = "s6")]
        Some(Command::Rays {
            mesh,
            sets,
            passes,
            threads,
            bvh,
            leaf,
        }) => rays(&mesh, &sets, passes, &threads, (bvh, leaf)),
        Some(Command::Converge {
            scene,
            max_spp,
            reference_spp,
            compare,
            variant,
            reference,
            label,
            cache,
            out,
            width,
            height,
            threads,
            quiet,
        }) => {
            let study = Study {
                ladder: raycourse::sample_ladder(max_spp.get()),
                reference_spp,
                cache,
                overrides: Overrides {
                    width,
                    height,
                    ..Overrides::default()
                },
                threads,
                quiet,
            };
            let out = out.unwrap_or_else(|| Path::new("out/converge").join(&scene));
            converge(&scene, (compare, variant, reference, label), &study, &out)
        }
        Some(Command::Plot { csv, out, title }) => plot(&csv, &out, &title),
        Some(Command::Figures { dir, quiet }) => stages().try_for_each(|stage| {
            let options = RenderArgs {
                out: Some(dir.join(format!("{}.png", stage.name))),
                quiet,
                ..RenderArgs::default()
            };
            render_stage(stage, &options)
        }),
    }
}

fn list() {
    println!(
        "{:<8} {:<7} {:<15} {:<58} settings",
        "session", "figure", "stage", "title"
    );
    for stage in stages() {
        let settings = stage
            .scene(&Overrides::default())
            .map_or_else(|e| format!("invalid scene file: {e}"), |s| s.summary());
        println!(
            "{:<8} {:<7} {:<15} {:<58} {settings}",
            format!("s{}", stage.session),
            stage.figure.map_or("-".into(), |f| f.to_string()),
            stage.name,
            stage.title
        );
    }
}

fn render_named(session: u32, name: &str, options: &RenderArgs) -> Result<(), Failure> {
    let stage = raycourse::find_stage(session, name)
        .expect("clap only accepts the names of this build's stages");
    render_stage(stage, options)
}

fn render_stage(stage: &Stage, options: &RenderArgs) -> Result<(), Failure> {
    let scene = stage.scene(&options.overrides())?;
    let out = Path::new("out").join(format!("{}.png", stage.name));
    render_to_file(stage.name, &scene, options, out)
}

/// A render and how it went.
struct Timed {
    result: Render,
    seconds: f64,
    threads: usize,
}

/// Renders `scene` on `options.threads` threads with a progress bar (unless quiet).
fn timed_render(label: &str, scene: &Scene, options: &RenderArgs) -> Result<Timed, Failure> {
    let threads = options.threads.map_or(0, NonZeroUsize::get);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|source| Failure::Threads { threads, source })?;
    let progress = if options.quiet {
        ProgressBar::hidden()
    } else {
        let samples = u64::from(scene.settings.samples);
        ProgressBar::new(u64::from(scene.camera.height) * samples).with_style(
            ProgressStyle::with_template("{msg} [{bar:40}] {percent}%, {eta} left")
                .expect("the template is valid")
                .progress_chars("=> "),
        )
    };
    progress.set_message(label.to_owned());
    let start = Instant::now();
    let result = pool.install(|| render(scene, &progress));
    let seconds = start.elapsed().as_secs_f64();
    progress.finish_and_clear();
    Ok(Timed {
        result,
        seconds,
        threads: pool.current_num_threads(),
    })
}

/// Writes `bytes` to `path` without leaving half a file.
fn write(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    raycourse::write_atomically(path, bytes).map_err(|source| Failure::Write {
        path: path.to_owned(),
        source,
    })
}

fn render_to_file(
    label: &str,
    scene: &Scene,
    options: &RenderArgs,
    default_out: PathBuf,
) -> Result<(), Failure> {
    let out = options.out.clone().unwrap_or(default_out);
    let timed = timed_render(label, scene, options)?;
    write(&out, &encode_png(&timed.result.film, scene.settings.gamma))?;
    let dropped = match timed.result.dropped {
        0 => String::new(),
        n => format!(", {n} non-finite samples dropped"),
    };
    println!(
        "{label}: {}, {:.3} s, {} rays, {:.2} Mrays/s, {} threads{dropped} -> {}",
        scene.summary(),
        timed.seconds,
        timed.result.rays,
        timed.result.rays as f64 / timed.seconds / 1e6,
        timed.threads,
        out.display()
    );
    Ok(())
}

/// Renders `frames` frames of stage `name` with the plunge angle going from
/// `angles.0` to `angles.1`, into a looping GIF or numbered PNG files.
#[cfg(feature = "s7")]
fn animate(
    name: &str,
    frames: u32,
    angles: (raycourse::Real, raycourse::Real),
    options: &RenderArgs,
) -> Result<(), Failure> {
    use image::codecs::gif::{GifEncoder, Repeat};
    use image::{Delay, Frame, RgbaImage};

    let stage = raycourse::find_stage(7, name).expect("clap only accepts stages of session 7");
    let out = options
        .out
        .clone()
        .unwrap_or_else(|| Path::new("out").join(format!("{name}.gif")));
    let as_png = out.extension().is_some_and(|e| e == "png");
    let mut gif = Vec::new();
    let mut encoder = (!as_png).then(|| GifEncoder::new_with_speed(&mut gif, 10));
    if let Some(encoder) = encoder.as_mut() {
        encoder.set_repeat(Repeat::Infinite).map_err(Failure::Gif)?;
    }
    let start = Instant::now();
    for k in 0..frames {
        let step = if frames > 1 {
            k as raycourse::Real / (frames - 1) as raycourse::Real
        } else {
            0.0
        };
        let overrides = Overrides {
            plunge: Some(angles.0 + (angles.1 - angles.0) * step),
            ..options.overrides()
        };
        let scene = stage.scene(&overrides)?;
        if scene.camera.orientation == raycourse::Orientation::Fixed {
            return Err(Failure::NotAimed(name.to_owned()));
        }
        let label = format!("{name} frame {}/{frames}", k + 1);
        let timed = timed_render(&label, &scene, options)?;
        let png = encode_png(&timed.result.film, scene.settings.gamma);
        if let Some(encoder) = encoder.as_mut() {
            let rgb = image::load_from_memory(&png).expect("the PNG was just encoded");
            let delay = Delay::from_numer_denom_ms(100, 1);
            let frame = Frame::from_parts(RgbaImage::from(rgb.to_rgba8()), 0, 0, delay);
            encoder.encode_frame(frame).map_err(Failure::Gif)?;
        } else {
            let stem = out.file_stem().unwrap_or_default().to_string_lossy();
            write(&out.with_file_name(format!("{stem}-{k:03}.png")), &png)?;
        }
        if !options.quiet {
            eprintln!("{label}: {:.2} s", timed.seconds);
        }
    }
    let animated = encoder.is_some();
    drop(encoder);
    if animated {
        write(&out, &gif)?;
    }
    println!(
        "{name}: {frames} frames, plunge {} to {} degrees, {:.1} s -> {}",
        angles.0,
        angles.1,
        start.elapsed().as_secs_f64(),
        out.display()
    );
    Ok(())
}

/// The course's reported time for a mesh stage, where it gave one.
#[cfg(feature = "s5")]
fn course_time(stage: &str) -> &'static str {
    match stage {
        "mesh" => "35 s",
        "mesh-bbox" => "15 s",
        _ => "about 60 s",
    }
}

/// Renders figures 13 to 18 at the course's settings and prints the timing table.
#[cfg(feature = "s5")]
fn bench(threads: Option<NonZeroUsize>) -> Result<(), Failure> {
    let options = RenderArgs {
        threads,
        quiet: true,
        ..RenderArgs::default()
    };
    println!("| stage | settings | triangles | time | Mrays/s | course |");
    println!("|---|---|---|---|---|---|");
    for stage in stages().filter(|s| s.session >= 5) {
        let scene = stage.scene(&Overrides::default())?;
        let triangles: usize = scene.meshes.iter().map(|m| m.triangles.len()).sum();
        let timed = timed_render(stage.name, &scene, &options)?;
        println!(
            "| `{}` ({}) | {} | {triangles} | {:.2} s | {:.2} | {} |",
            stage.name,
            stage.figure.map_or("-".into(), |f| f.to_string()),
            scene.summary(),
            timed.seconds,
            timed.result.rays as f64 / timed.seconds / 1e6,
            course_time(stage.name)
        );
    }
    Ok(())
}

/// Loads `mesh`, builds its BVH, and times each ray set on each thread count.
#[cfg(feature = "s6")]
fn rays(
    mesh: &Path,
    sets: &[PathBuf],
    passes: usize,
    threads: &[NonZeroUsize],
    (bvh, leaf): (BvhKind, u16),
) -> Result<(), Failure> {
    use raycourse::{Bvh, Mat3, Mesh, Placement, RayKind, RaySet, Search, Vec3, time_set};

    let data = raycourse::read_obj(mesh).map_err(|message| Failure::Mesh {
        path: mesh.to_owned(),
        message,
    })?;
    let placement = Placement {
        scale: 1.0,
        rotation: Mat3::IDENTITY,
        translation: Vec3::ZERO,
    };
    let mut mesh = Mesh::new(&data, &placement);
    let start = Instant::now();
    mesh.search = match bvh {
        BvhKind::Midpoint => Search::Bvh(Bvh::build(&mesh)),
        BvhKind::Sah => Search::Bvh(Bvh::build_sah(&mesh, leaf.into(), 1)),
        BvhKind::Fast => Search::FastBvh(raycourse::FastBvh::build(&mesh, leaf)),
    };
    println!(
        "build triangles={} ms={:.1}",
        mesh.triangles.len(),
        start.elapsed().as_secs_f64() * 1e3
    );
    let counts: Vec<usize> = if threads.is_empty() {
        vec![1, rayon::current_num_threads()]
    } else {
        threads.iter().map(|t| t.get()).collect()
    };
    for path in sets {
        let set = RaySet::read(path)?;
        let name = path.file_stem().unwrap_or_default().to_string_lossy();
        for &count in &counts {
            let timing =
                time_set(&mesh, &set, count, passes).map_err(|source| Failure::Threads {
                    threads: count,
                    source,
                })?;
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
    }
    Ok(())
}

/// How a convergence study is run.
struct Study {
    /// The sample counts rendered.
    ladder: Vec<u32>,
    /// Samples per pixel of the reference.
    reference_spp: NonZeroU32,
    /// Where references are cached.
    cache: PathBuf,
    /// Image size, when not the scene's.
    overrides: Overrides,
    threads: Option<NonZeroUsize>,
    quiet: bool,
}

/// The scene file text of `name` (a stage or a file) and its path.
fn scene_source(name: &str) -> Result<(String, PathBuf), Failure> {
    if let Some(stage) = stages().find(|s| s.name == name) {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(stage.path);
        return Ok((stage.source.to_owned(), path));
    }
    let path = PathBuf::from(name);
    if path.extension().is_none_or(|e| e != "toml") {
        return Err(Failure::Usage(format!(
            "`{name}` is neither a stage of this build (see `raycourse list`) nor a .toml scene file"
        )));
    }
    let source = std::fs::read_to_string(&path).map_err(|source| SceneError::Read {
        path: path.clone(),
        source,
    })?;
    Ok((source, path))
}

/// Runs a convergence study of the scene `name`: the variants of `compare` and
/// `variants` (or the scene itself, labelled `label`) against a reference.
fn converge(
    name: &str,
    (compare, variants, reference, label): (
        Option<String>,
        Vec<String>,
        Option<String>,
        Option<String>,
    ),
    study: &Study,
    out: &Path,
) -> Result<(), Failure> {
    use raycourse::{Edit, Variant, climb, comparison, fitted_slope, parse_scene};

    let (source, path) = scene_source(name)?;
    let (mut chosen, mut reference_edits): (Vec<Variant>, Vec<Edit>) =
        compare.as_deref().and_then(comparison).unwrap_or_default();
    for text in &variants {
        chosen.push(Variant::parse(text)?);
    }
    if let Some(text) = reference {
        reference_edits = Variant::parse(&format!("reference:{text}"))?.edits;
    }
    if chosen.is_empty() {
        let label = label.unwrap_or_else(|| name.to_owned());
        chosen.push(Variant {
            label,
            edits: vec![],
        });
    }
    let threads = study.threads.map_or(0, NonZeroUsize::get);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|source| Failure::Threads { threads, source })?;
    let scene_of = |edits: Vec<Edit>, samples: NonZeroU32, seed: Option<u64>| {
        let text = Variant {
            label: String::new(),
            edits,
        }
        .apply(&source)?;
        let overrides = Overrides {
            samples: Some(samples),
            seed,
            ..study.overrides
        };
        Ok::<_, Failure>((parse_scene(&text, &path, &overrides)?, text))
    };
    // The reference uses other random numbers than the ladder, so that its own
    // remaining noise is independent of the renders it measures.
    let (truth, text) = scene_of(reference_edits, study.reference_spp, Some(REFERENCE_SEED))?;
    let rows = u64::from(truth.camera.height);
    let work = study.ladder.iter().map(|&n| u64::from(n)).sum::<u64>() * chosen.len() as u64;
    let progress = if study.quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(rows * (work + u64::from(study.reference_spp.get()))).with_style(
            ProgressStyle::with_template("{msg} [{bar:40}] {percent}%, {eta} left")
                .expect("the template is valid")
                .progress_chars("=> "),
        )
    };
    // The key holds nothing that prints differently in single precision, so both
    // builds share a reference (stored in double precision).
    let key = format!(
        "{text}\n{}x{}, {} spp, seed {}",
        truth.camera.width, truth.camera.height, truth.settings.samples, truth.settings.seed
    );
    let cached = raycourse::reference_path(&study.cache, &key);
    let reference = match raycourse::load_reference(&cached) {
        Some(film) => {
            progress.inc(rows * u64::from(study.reference_spp.get()));
            film
        }
        None => {
            progress.set_message(format!("reference, {} spp", study.reference_spp));
            let film = pool.install(|| render(&truth, &progress)).film;
            raycourse::save_reference(&cached, &film).map_err(|source| Failure::Write {
                path: cached.clone(),
                source,
            })?;
            film
        }
    };
    let mut rungs = vec![];
    for variant in &chosen {
        let (scene, _) = scene_of(variant.edits.clone(), NonZeroU32::MIN, None)?;
        progress.set_message(variant.label.clone());
        rungs.extend(
            pool.install(|| climb(&variant.label, scene, &study.ladder, &reference, &progress)),
        );
    }
    progress.finish_and_clear();
    let mut csv = format!("{}\n", raycourse::Rung::CSV_HEADER);
    for rung in &rungs {
        csv += &rung.csv();
        csv.push('\n');
    }
    let csv_path = out.with_extension("csv");
    write(&csv_path, csv.as_bytes())?;
    println!(
        "{name}: {}x{}, reference {} spp, {} threads -> {}",
        truth.camera.width,
        truth.camera.height,
        study.reference_spp,
        pool.current_num_threads(),
        csv_path.display()
    );
    for variant in &chosen {
        let mine: Vec<&raycourse::Rung> = rungs
            .iter()
            .filter(|r| r.variant == variant.label)
            .collect();
        let last = mine.last().expect("the ladder has at least one rung");
        let slope = |x: &dyn Fn(&raycourse::Rung) -> raycourse::Real| {
            let points: Vec<_> = mine.iter().map(|r| (x(r), r.error.rmse)).collect();
            fitted_slope(&points).map_or("-".into(), |s| format!("{s:.3}"))
        };
        println!(
            "  {}: RMSE {:.4e} at {} spp in {:.3} s; slope {} against samples, {} against time; efficiency {:.4e}",
            variant.label,
            last.error.rmse,
            last.samples,
            last.seconds,
            slope(&|r| r.samples as raycourse::Real),
            slope(&|r| r.seconds),
            last.efficiency()
        );
    }
    let title = match &compare {
        Some(comparison) => format!("{name} ({comparison}): error against samples and time"),
        None => format!("{name}: error against samples and time"),
    };
    match raycourse::plot_rungs(&title, &rungs) {
        Some(png) => {
            let png_path = out.with_extension("png");
            write(&png_path, &png)?;
            println!("  plot -> {}", png_path.display());
        }
        None => println!("  every image equals the reference: nothing to plot"),
    }
    Ok(())
}

/// Seed of every reference render (the ladder keeps the scene's seed).
const REFERENCE_SEED: u64 = 0x5eed_f00d;

/// Plots the rows of the CSV files `csv` into `out`.
fn plot(csv: &[PathBuf], out: &Path, title: &str) -> Result<(), Failure> {
    let mut rungs = vec![];
    for path in csv {
        let text = std::fs::read_to_string(path).map_err(|e| Failure::Csv {
            path: path.clone(),
            message: format!("cannot read: {e}"),
        })?;
        rungs.extend(
            raycourse::read_rungs(&text).map_err(|message| Failure::Csv {
                path: path.clone(),
                message,
            })?,
        );
    }
    let png = raycourse::plot_rungs(title, &rungs)
        .ok_or_else(|| Failure::Usage("no row has an error above 0: nothing to plot".into()))?;
    write(out, &png)?;
    println!("{} rows -> {}", rungs.len(), out.display());
    Ok(())
}
