//! `raycourse probe STAGE X Y`: one sample of one pixel, followed ray by ray
//! ([`raycourse::inspect::probe`]), as text in the book's notation or as JSON.

use std::io::Write;
use std::path::PathBuf;

use clap::{ArgMatches, FromArgMatches, Parser};
use raycourse::inspect::probe::probe;
use raycourse::messages::language::Language;
use raycourse::messages::said::Said;
use raycourse::messages::{Argument, say};
use raycourse::stages;

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::job::Job;
use crate::commands::options::RenderArgs;
use crate::commands::options::{LanguageArgs, SceneArgs};

/// Follow one sample of one pixel ray by ray: each hit, the light, the next
/// direction and what each ray adds, computed by the renderer's own functions.
#[derive(Parser)]
#[command(name = "probe")]
struct ProbeArgs {
    /// The stage (`raycourse list` names them); with `--scene`, the pixel's X.
    #[arg(value_name = "STAGE")]
    first: String,
    /// The pixel's X, from the left; with `--scene`, its Y.
    #[arg(value_name = "X")]
    second: String,
    /// The pixel's Y, from the top (none with `--scene`).
    #[arg(value_name = "Y")]
    third: Option<String>,
    /// A scene file instead of a stage.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// The sample to follow, from 0.
    #[arg(long, default_value_t = 0)]
    sample: u32,
    /// Print one JSON document instead of text.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    scene_options: SceneArgs,
    #[command(flatten)]
    lang: LanguageArgs,
}

/// The `probe` command.
pub const VERB: Verb = Verb {
    rank: 10,
    command: <ProbeArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = ProbeArgs::from_arg_matches(matches)?;
    let language = args.lang.language();
    let refused =
        |id: &str, arguments: &[(&str, Argument)]| Failure::Input(say(language, id, arguments));
    let overrides = args.scene_options.overrides();
    let options = RenderArgs::default();
    let (first, second) = (&args.first, &args.second);
    let (job, pixel) = match (&args.scene, &args.third) {
        (Some(file), None) => (Job::of_file(file, &overrides, &options)?, [first, second]),
        (None, Some(third)) => {
            let (name, x, y) = (first, second, third);
            let stage = stages().find(|s| s.name == name.as_str()).ok_or_else(|| {
                let names: Vec<&str> = stages().map(|s| s.name).collect();
                let names = names.join(", ");
                refused(
                    "probe-no-stage",
                    &[("name", name.as_str().into()), ("names", names.into())],
                )
            })?;
            (Job::of_stage(stage, &overrides, &options)?, [x, y])
        }
        (Some(_), _) => return Err(refused("probe-scene-and-stage", &[])),
        (None, _) => return Err(refused("probe-give-stage", &[])),
    };
    let [x, y] = pixel.map(|v| coordinate(v, language));
    #[cfg(feature = "beyond")]
    if let Some(what) = job.beyond.beyond_the_course() {
        return Err(refused("probe-beyond-the-course", &[("what", what.into())]));
    }
    let found =
        probe(&job.scene, x?, y?, args.sample).map_err(|e| Failure::Input(e.say(language)))?;
    let text = if args.json {
        serde_json::to_string_pretty(&found).map_err(|e| broke("probe-cannot-write-json", e))?
            + "\n"
    } else {
        found.text(language)
    };
    // A reader that stops early (`| head`) is not a failure.
    match std::io::stdout().write_all(text.as_bytes()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(broke("probe-cannot-write-output", e))
        }
        _ => Ok(()),
    }
}

/// The failure of the machine the message `id` names, `error` saying why.
fn broke(id: &'static str, error: impl std::fmt::Display) -> Failure {
    Failure::Broke(Said::new(id).with("why", error.to_string()))
}

/// A pixel coordinate: a whole number from 0; refused in `language` otherwise.
fn coordinate(text: &str, language: Language) -> Result<u32, Failure> {
    text.parse().map_err(|_| {
        let why = say(language, "probe-not-a-coordinate", &[("text", text.into())]);
        Failure::Input(why)
    })
}
