//! `raycourse render <scene.toml>`: any scene file.

use std::path::{Path, PathBuf};

use clap::{ArgMatches, FromArgMatches, Parser};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::job::Job;
use crate::commands::options::RenderArgs;
use crate::commands::output::render_to_file;

/// Render a scene file.
#[derive(Parser)]
#[command(name = "render")]
struct RenderFile {
    /// The scene file (TOML).
    scene: PathBuf,
    #[command(flatten)]
    options: RenderArgs,
}

/// The `render` command.
pub const VERB: Verb = Verb {
    rank: 2,
    command: <RenderFile as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = RenderFile::from_arg_matches(matches)?;
    let options = &args.options;
    let job = Job::of_file(&args.scene, &options.overrides(), options)?;
    let name = args
        .scene
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy());
    let out = Path::new("out").join(format!("{name}.png"));
    render_to_file(&name, &job, options, out)
}
