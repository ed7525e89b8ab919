//! `raycourse figures [dir]`: every stage of the build at the course's settings.

use std::path::PathBuf;

use clap::{ArgMatches, FromArgMatches, Parser};
use raycourse::stages;

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::options::RenderArgs;
use crate::commands::stage::render_stage;

/// Render every stage of this build at the course's settings into a folder, as
/// `<stage>.png`: the book's figures.
#[derive(Parser)]
#[command(name = "figures")]
struct FiguresArgs {
    /// The folder.
    #[arg(default_value = "book/src/figures")]
    dir: PathBuf,
    /// Hide the progress bars.
    #[arg(long, short)]
    quiet: bool,
}

/// The `figures` command.
pub const VERB: Verb = Verb {
    rank: 3,
    session: 1,
    command: <FiguresArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = FiguresArgs::from_arg_matches(matches)?;
    stages().try_for_each(|stage| {
        let options = RenderArgs {
            out: Some(args.dir.join(format!("{}.png", stage.name))),
            quiet: args.quiet,
            ..RenderArgs::default()
        };
        render_stage(stage, &options)
    })
}
