//! `raycourse figures [dir]`: every stage of the build at the course's settings, by
//! the course's code; beyond the course, with `--fast` by the fast engine too, to
//! the same picture.

use std::path::PathBuf;

use clap::{ArgMatches, FromArgMatches, Parser};
use raycourse::stages;

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::options::{RenderArgs, WorkArgs};
use crate::commands::stage::render_stage;

/// Render every stage of this build at the course's settings into a folder, as
/// `<stage>.png`: the book's figures, by the course's code.
#[derive(Parser)]
#[command(name = "figures")]
struct FiguresArgs {
    /// The folder.
    #[arg(default_value = "book/src/figures")]
    dir: PathBuf,
    /// Render each stage with the fast engine too and check that it shows the same
    /// picture: the same bytes, or `check`'s "matches".
    #[cfg(feature = "beyond")]
    #[arg(long)]
    fast: bool,
    #[command(flatten)]
    work: WorkArgs,
}

/// The `figures` command.
pub const VERB: Verb = Verb {
    rank: 3,
    command: <FiguresArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = FiguresArgs::from_arg_matches(matches)?;
    stages().try_for_each(|stage| {
        let options = RenderArgs {
            out: Some(args.dir.join(format!("{}.png", stage.name))),
            work: args.work.clone(),
            ..RenderArgs::default()
        };
        render_stage(stage, &options)?;
        #[cfg(feature = "beyond")]
        if args.fast {
            crate::commands::beyond::same_picture_by_the_fast_engine(stage, options)?;
        }
        Ok(())
    })
}
