//! `raycourse figures [dir]`: every stage of the build at the course's settings, by
//! the course's code; with `--fast` by the fast engine too, to the same bytes.

use std::path::{Path, PathBuf};

use clap::{ArgMatches, FromArgMatches, Parser};
use raycourse::{Stage, stages};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::options::RenderArgs;
use crate::commands::stage::render_stage;

/// Render every stage of this build at the course's settings into a folder, as
/// `<stage>.png`: the book's figures, by the course's code.
#[derive(Parser)]
#[command(name = "figures")]
struct FiguresArgs {
    /// The folder.
    #[arg(default_value = "book/src/figures")]
    dir: PathBuf,
    /// Render each stage with the fast engine too, check that it gives the same
    /// bytes, and print both closing lines (session 3).
    #[arg(long, hide = raycourse::scene_file::SESSION < 3)]
    fast: bool,
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
        let out = args.dir.join(format!("{}.png", stage.name));
        let options = RenderArgs {
            out: Some(out.clone()),
            quiet: args.quiet,
            ..RenderArgs::default()
        };
        render_stage(stage, &options)?;
        if args.fast {
            same_bytes_by_the_fast_engine(stage, options, &out)?;
        }
        Ok(())
    })
}

/// Renders `stage` with `options` by the fast engine, beside `course` (the course's
/// render), and fails unless the two files have the same bytes.
fn same_bytes_by_the_fast_engine(
    stage: &Stage,
    options: RenderArgs,
    course: &Path,
) -> Result<(), Failure> {
    let fast = course.with_extension("fast.png");
    let options = RenderArgs {
        out: Some(fast.clone()),
        fast: true,
        ..options
    };
    render_stage(stage, &options)?;
    let read = |path: &Path| {
        std::fs::read(path)
            .map_err(|e| Failure::Machine(format!("{}: cannot read the file: {e}", path.display())))
    };
    let same = read(course)? == read(&fast)?;
    std::fs::remove_file(&fast).map_err(|e| Failure::write(&fast, e))?;
    match same {
        true => Ok(()),
        false => Err(Failure::Machine(format!(
            "{}: the fast engine's image differs from the course's code's",
            stage.name
        ))),
    }
}
