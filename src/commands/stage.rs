//! `raycourse s1 <stage>` to `raycourse s7 <stage>`: one subcommand per session of
//! the build, each rendering one of that session's stages.

use std::path::Path;

use clap::builder::PossibleValuesParser;
use clap::{Arg, ArgMatches, Args, FromArgMatches};
use raycourse::{Stage, find_stage, scene_file::stage_names};

use crate::commands::failure::Failure;
use crate::commands::job::Job;
use crate::commands::options::RenderArgs;
use crate::commands::output::render_to_file;

/// The subcommand `sN` of session `session`: its stage's name, then the render
/// options.
pub fn command(session: u32) -> clap::Command {
    let stage = Arg::new("stage")
        .required(true)
        .help("The stage")
        .value_parser(PossibleValuesParser::new(stage_names(session)));
    RenderArgs::augment_args(clap::Command::new(format!("s{session}")).arg(stage))
        .about(format!("Render a stage of session {session}"))
}

/// The session of subcommand `name` (`s3` is 3), if it is one.
pub fn session_of(name: &str) -> Option<u32> {
    name.strip_prefix('s')?.parse().ok()
}

/// Runs `sN <stage>` with the arguments `matches`.
pub fn run(session: u32, matches: &ArgMatches) -> Result<(), Failure> {
    let name: &String = matches.get_one("stage").expect("the stage is required");
    let stage = find_stage(session, name).expect("clap only accepts this build's stages");
    render_stage(stage, &RenderArgs::from_arg_matches(matches)?)
}

/// Renders `stage` at its course settings, but for `options`, into
/// `out/<stage>.png` unless `options.out` says otherwise.
pub fn render_stage(stage: &Stage, options: &RenderArgs) -> Result<(), Failure> {
    let job = Job::of_stage(stage, &options.overrides(), options)?;
    let out = Path::new("out").join(format!("{}.png", stage.name));
    render_to_file(stage.name, &job, options, out)
}
