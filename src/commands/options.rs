//! The options of a render, shared by every command that renders.

use std::num::{NonZeroU32, NonZeroUsize};
use std::path::PathBuf;

use clap::Args;
use raycourse::Overrides;
use raycourse::inspect::aov::Aov;
use raycourse::messages::language::Language;
use raycourse::messages::said::Said;

use crate::commands::failure::Failure;

/// The scene-file settings that change what a pixel's path is: the image's size,
/// the samples, the bounce limit and the seed.
#[derive(Args, Clone, Debug, Default)]
pub struct SceneArgs {
    /// Image width in pixels.
    #[arg(long)]
    pub width: Option<NonZeroU32>,
    /// Image height in pixels.
    #[arg(long)]
    pub height: Option<NonZeroU32>,
    /// Samples per pixel.
    #[arg(long)]
    pub spp: Option<NonZeroU32>,
    /// Bounce limit for mirrors, glass and indirect light.
    #[arg(long)]
    pub bounces: Option<u32>,
    /// Seed of the random generators.
    #[arg(long)]
    pub seed: Option<u64>,
}

impl SceneArgs {
    /// The scene-file settings these options replace.
    pub fn overrides(&self) -> Overrides {
        Overrides {
            width: self.width,
            height: self.height,
            samples: self.spp,
            bounces: self.bounces,
            seed: self.seed,
            ..Overrides::default()
        }
    }
}

/// How a command does its work, whatever it renders: its worker threads and its
/// progress bar. Every command that renders takes these two options.
#[derive(Args, Clone, Debug, Default)]
pub struct WorkArgs {
    /// Worker threads (default: one per core; at most 1024).
    #[arg(long)]
    pub threads: Option<NonZeroUsize>,
    /// Hide the progress bar.
    #[arg(long, short)]
    pub quiet: bool,
}

impl WorkArgs {
    /// The thread pool of `--threads` ([`thread_pool`]).
    pub fn pool(&self) -> Result<rayon::ThreadPool, Failure> {
        thread_pool(self.threads)
    }
}

/// Settings that replace the scene file's for one render.
#[derive(Args, Clone, Debug, Default)]
pub struct RenderArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub work: WorkArgs,
    /// Output PNG (default: out/<name>.png).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Settings beyond the course: adaptive sampling, the fast engine.
    #[cfg(feature = "beyond")]
    #[command(flatten)]
    pub beyond: crate::commands::beyond_options::BeyondArgs,
    /// Instead of the render, an image of what the renderer sees through each
    /// pixel's centre: the normal, the depth, the albedo, the object, or the cost
    /// (spheres, boxes and triangles tested), into `out/<name>-<kind>.png`.
    #[arg(long, value_parser = aov_parser())]
    pub aov: Option<Aov>,
    #[command(flatten)]
    pub lang: LanguageArgs,
}

/// The language a command speaks: its closing line and its errors.
#[derive(Args, Clone, Debug, Default)]
pub struct LanguageArgs {
    /// The language of the messages, `en` or `fr` (default: the locale's, from
    /// `LC_ALL`, `LC_MESSAGES` or `LANG`; English unless it is French).
    #[arg(long, value_parser = ["en", "fr"])]
    pub lang: Option<String>,
}

impl LanguageArgs {
    /// The language asked for: `--lang`, or the environment's.
    pub fn language(&self) -> Language {
        self.lang
            .as_deref()
            .map_or_else(Language::from_environment, Language::from_locale)
    }
}

/// The kinds of `--aov`, by name.
fn aov_parser() -> impl clap::builder::TypedValueParser<Value = Aov> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(Aov::ALL.map(Aov::name))
        .map(|name| Aov::from_name(&name).expect("clap accepts only the kinds' names"))
}

impl RenderArgs {
    /// The scene-file settings these options replace (those beyond the course
    /// aside: `commands/beyond.rs`).
    pub fn overrides(&self) -> Overrides {
        self.scene.overrides()
    }

    /// The language of the render's messages (`--lang`, or the environment's).
    pub fn language(&self) -> Language {
        self.lang.language()
    }
}

/// The most worker threads a command starts: far more than any machine's cores,
/// far fewer than would exhaust its memory with their stacks.
pub const MOST_THREADS: usize = 1024;

/// A thread pool of `threads` workers, one per core if `None`; more than
/// [`MOST_THREADS`] are refused as a bad input.
pub fn thread_pool(threads: Option<NonZeroUsize>) -> Result<rayon::ThreadPool, Failure> {
    let threads = threads.map_or(0, NonZeroUsize::get);
    if threads > MOST_THREADS {
        let said = Said::new("command-too-many-threads")
            .with("threads", threads as u64)
            .with("most", MOST_THREADS as u64);
        return Err(Failure::Refused(said));
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| {
            let said = Said::new("command-cannot-start-threads")
                .with("threads", threads as u64)
                .with("why", e.to_string());
            Failure::Broke(said)
        })
}
