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
            Self::Scene(_) => ExitCode::from(2),
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
        ProgressBar::new(u64::from(scene.camera.height)).with_style(
            ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} rows, {eta} left")
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
        BvhKind::Sah => Search::Bvh(Bvh::build_sah(&mesh, leaf.into())),
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
