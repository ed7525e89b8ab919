//! `raycourse list`: the stages of this build.

use clap::{ArgMatches, Parser};
use raycourse::messages::language::Language;
use raycourse::{Overrides, stages};

use crate::commands::Verb;
use crate::commands::failure::Failure;

/// List the stages of this build: session, figure, name, title, settings.
#[derive(Parser)]
#[command(name = "list")]
struct ListArgs {}

/// The `list` command.
pub const VERB: Verb = Verb {
    rank: 1,
    command: <ListArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(_: &ArgMatches) -> Result<(), Failure> {
    println!(
        "{:<8} {:<7} {:<15} {:<58} settings",
        "session", "figure", "stage", "title"
    );
    for stage in stages() {
        let settings = stage.scene(&Overrides::default()).map_or_else(
            |e| format!("invalid scene file: {e}"),
            |s| s.summary(Language::English),
        );
        println!(
            "{:<8} {:<7} {:<15} {:<58} {settings}",
            format!("s{}", stage.session),
            stage.figure.map_or("-".into(), |f| f.to_string()),
            stage.name,
            stage.title
        );
    }
    Ok(())
}
