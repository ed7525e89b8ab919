//! What a render shows and leaves: a progress bar on stderr, a closing line, and
//! files written whole or not at all.

use std::path::{Path, PathBuf};
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use raycourse::inspect::aov::{Aov, see};
use raycourse::inspect::false_colour::label as label_of;
use raycourse::messages::catalogue::decimals;
use raycourse::messages::language::Language;
use raycourse::messages::said::Said;
use raycourse::messages::{Argument, say};
use raycourse::render::png::encode_rgb8;
use raycourse::{Render, Scene, encode_png};

use crate::commands::failure::Failure;
use crate::commands::job::Job;
use crate::commands::options::RenderArgs;

/// A progress bar of `length` steps labelled `label`, hidden when `quiet` (and by
/// indicatif when stderr is not a terminal).
pub fn progress_bar(length: u64, label: &str, quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let style = ProgressStyle::with_template("{msg} [{bar:40}] {percent}%, {eta} left")
        .expect("the template is valid")
        .progress_chars("=> ");
    ProgressBar::new(length)
        .with_style(style)
        .with_message(label.to_owned())
}

/// A render and how it went.
pub struct Timed {
    /// The film and the rays it took.
    pub result: Render,
    /// Wall-clock seconds.
    pub seconds: f64,
    /// Worker threads.
    pub threads: usize,
}

/// Renders `job` on `--threads` threads with a progress bar (unless quiet).
pub fn timed_render(label: &str, job: &Job, options: &RenderArgs) -> Result<Timed, Failure> {
    let scene = &job.scene;
    let pool = options.work.pool()?;
    let samples = u64::from(scene.settings.samples);
    let bar = progress_bar(
        u64::from(scene.camera.height) * samples,
        label,
        options.work.quiet,
    );
    let start = Instant::now();
    let result = pool.install(|| job.render_reporting(&|done| bar.inc(done)));
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    Ok(Timed {
        result,
        seconds,
        threads: pool.current_num_threads(),
    })
}

/// Writes `bytes` to `path` without leaving half a file. A symbolic link is written
/// through (the file it leads to is replaced, the link kept); a path that names
/// something other than a regular file (a folder, a device, a pipe) is refused as a
/// bad input, since replacing it by a file would lose what it is.
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    let target = through_links(path)?;
    raycourse::render::write_atomically(&target, bytes).map_err(|e| Failure::write(path, e))
}

/// Where writing `path` lands: the end of its chain of symbolic links, or `path`
/// itself; refused when that exists and is not a regular file.
fn through_links(path: &Path) -> Result<PathBuf, Failure> {
    let mut target = path.to_path_buf();
    // As many links as Linux follows before it gives up (ELOOP).
    for _ in 0..40 {
        let Ok(metadata) = std::fs::symlink_metadata(&target) else {
            return Ok(target);
        };
        if metadata.is_file() {
            return Ok(target);
        }
        if !metadata.file_type().is_symlink() {
            return Err(refused_path("command-not-a-file", path));
        }
        let link = std::fs::read_link(&target).map_err(|e| Failure::write(path, e))?;
        target = target.parent().unwrap_or(Path::new("")).join(link);
    }
    Err(refused_path("command-link-loop", path))
}

/// The bad input of the message `id` about the file at `path`.
fn refused_path(id: &'static str, path: &Path) -> Failure {
    Failure::Refused(Said::new(id).with("file", path.display().to_string()))
}

/// Renders `job` into a PNG (`options.out`, or `default_out`) and prints the
/// closing line: settings, time, rays and Mrays/s.
pub fn render_to_file(
    label: &str,
    job: &Job,
    options: &RenderArgs,
    default_out: PathBuf,
) -> Result<(), Failure> {
    let scene = &job.scene;
    if let Some(aov) = options.aov {
        #[cfg(feature = "beyond")]
        refuse_cost_of_fast(label, aov, &job.beyond)?;
        let name = format!("{label}-{}.png", aov.name());
        let out = options
            .out
            .clone()
            .unwrap_or(default_out.with_file_name(name));
        return aov_to_file(label, scene, aov, options, &out);
    }
    let out = options.out.clone().unwrap_or(default_out);
    let timed = timed_render(label, job, options)?;
    write(&out, &encode_png(&timed.result.film, scene.settings.gamma))?;
    #[cfg(feature = "beyond")]
    options
        .beyond
        .write_noise_map(label, scene, &timed.result.samples, options.language())?;
    println!(
        "{}",
        closing_line(label, job, &timed, &out, options.language())
    );
    Ok(())
}

/// The closing line of `job`'s render in `language`: its settings, time, rays,
/// Mrays/s and threads, and where the image went.
fn closing_line(label: &str, job: &Job, timed: &Timed, out: &Path, language: Language) -> String {
    let scene = &job.scene;
    let taken = &timed.result.samples;
    let average = taken.iter().map(|&n| f64::from(n)).sum::<f64>() / taken.len() as f64;
    let adaptive = match taken.iter().any(|&n| n != scene.settings.samples) {
        true => say(language, "render-adaptive", &[("average", average.into())]),
        false => String::new(),
    };
    let dropped = match timed.result.dropped {
        0 => String::new(),
        n => say(language, "render-dropped", &[("dropped", n.into())]),
    };
    let rays = timed.result.rays;
    let arguments = [
        ("label", label.into()),
        ("summary", scene.summary(language).into()),
        ("seconds", timed.seconds.into()),
        ("rays", rays.into()),
        ("speed", (rays as f64 / timed.seconds / 1e6).into()),
        ("threads", timed.threads.into()),
        ("adaptive", adaptive.into()),
        ("dropped", dropped.into()),
        ("out", out.display().to_string().into()),
    ];
    say(language, "render-done", &arguments)
}

/// Refuses `--aov cost` with the fast engine: the image counts the tests of the
/// course's searches, and the fast engine's own searches (its hierarchy, session
/// 5's triangles on lanes) count none, so its mean would be the spheres' alone.
#[cfg(feature = "beyond")]
fn refuse_cost_of_fast(
    label: &str,
    aov: Aov,
    beyond: &raycourse::scene::beyond::Beyond,
) -> Result<(), Failure> {
    if aov == Aov::Cost && beyond.fast {
        let said = Said::new("render-cost-not-fast").with("label", label);
        return Err(Failure::Refused(said));
    }
    Ok(())
}

/// Writes the image of `aov` for `scene` to `out` and prints its closing line: the
/// range of the colour scale and, for the cost, the mean.
fn aov_to_file(
    label: &str,
    scene: &Scene,
    aov: Aov,
    options: &RenderArgs,
    out: &Path,
) -> Result<(), Failure> {
    let image = options.work.pool()?.install(|| see(scene, aov));
    write(out, &encode_rgb8(&image.rgb, image.width, image.height))?;
    let language = options.language();
    let range = match image.range {
        Some((low, high)) => say(
            language,
            "render-aov-range",
            &[
                ("low", written(&label_of(low))),
                ("high", written(&label_of(high))),
            ],
        ),
        None => String::new(),
    };
    let mean = match (aov, image.mean) {
        (Aov::Cost, Some(mean)) => {
            let mean = written(&format!("{mean:.1}"));
            say(language, "render-aov-mean", &[("mean", mean)])
        }
        _ => String::new(),
    };
    let arguments = [
        ("label", label.into()),
        ("aov", aov.name().into()),
        ("range", range.into()),
        ("mean", mean.into()),
        ("out", out.display().to_string().into()),
    ];
    println!("{}", say(language, "render-aov-done", &arguments));
    Ok(())
}

/// A number as the program wrote it (`0.25`, `12.5`, `3`), its digits kept and
/// its decimal mark the message's language's.
fn written(text: &str) -> Argument<'static> {
    let places = text.split_once('.').map_or(0, |(_, d)| d.len());
    decimals(text.parse().unwrap_or(f64::NAN), places)
}
