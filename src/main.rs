//! The `raycourse` command: list the course's stages, render one, render any scene
//! file, check an image, follow a pixel's path; beyond the course, the studies of
//! speed and accuracy. Each command is a file of
//! `src/commands/`; this file builds the command line and dispatches.

#![deny(unsafe_code)]

mod commands;

use std::process::ExitCode;

use clap::{ArgMatches, Args, FromArgMatches};
use raycourse::messages::language::Language;
use raycourse::scene_file::SESSION;
use raycourse::stages;

use commands::failure::Failure;
use commands::options::RenderArgs;
use commands::{Verb, pipe, stage, verbs};

/// The command line: the sessions' subcommands `s1` to `sN` of this build, every
/// other command of this build, and the render options, which apply to the last
/// stage when no command is given.
fn command(verbs: &[Verb]) -> clap::Command {
    let about = "Ray tracing, one course session at a time. With no command, renders the \
                 last stage of this build into `out/` (the render options apply to it).";
    let command = clap::Command::new("raycourse")
        .version(env!("CARGO_PKG_VERSION"))
        .args_conflicts_with_subcommands(true);
    // After the render options, whose own doc comment would otherwise be the about.
    let mut command = RenderArgs::augment_args(command).about(about);
    for session in 1..=SESSION {
        command = command.subcommand(stage::command(session));
    }
    verbs.iter().fold(command, |command, verb| {
        command.subcommand((verb.command)())
    })
}

/// Runs the command that `matches` names.
fn dispatch(verbs: &[Verb], matches: &ArgMatches) -> Result<(), Failure> {
    let Some((name, arguments)) = matches.subcommand() else {
        let last = stages().last().expect("every build has session 1's stages");
        return stage::render_stage(last, &RenderArgs::from_arg_matches(matches)?);
    };
    if let Some(session) = stage::session_of(name) {
        return stage::run(session, arguments);
    }
    let verb = verbs
        .iter()
        .find(|v| (v.command)().get_name() == name)
        .expect("clap only accepts the commands it was given");
    (verb.run)(arguments)
}

/// The language of the command's messages: its `--lang`, for a command that has
/// one (`render`, `sN`, `probe`, `check`), otherwise the environment's.
fn language(matches: &ArgMatches) -> Language {
    let command = matches.subcommand().map_or(matches, |(_, m)| m);
    let lang = command.try_get_one::<String>("lang").ok().flatten();
    lang.map_or_else(Language::from_environment, |l| Language::from_locale(l))
}

fn main() -> ExitCode {
    let verbs = verbs();
    let matches = command(&verbs).get_matches();
    // A reader that closed the output early (`| head`) ends the command quietly.
    let Some(outcome) = pipe::quiet_when_closed(|| dispatch(&verbs, &matches)) else {
        return ExitCode::SUCCESS;
    };
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Differs) => Failure::Differs.exit_code(),
        Err(failure) => {
            eprintln!("{}", failure.said(language(&matches)));
            failure.exit_code()
        }
    }
}
