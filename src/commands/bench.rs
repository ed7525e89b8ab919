//! `raycourse bench`: the stages at the course's settings, timed with the course's
//! code beside the times the course reported on its own machine; beyond the course,
//! with the fast engine too.

use clap::{ArgMatches, FromArgMatches, Parser};
use raycourse::messages::language::Language;
use raycourse::{Overrides, Scene, Stage, stages};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::job::Job;
use crate::commands::options::{RenderArgs, WorkArgs};
use crate::commands::output::{Timed, timed_render};

/// Render the stages at the course's settings and print a table of their times by
/// the course's code, beside the course's own times (every stage of this build, or
/// those of the sessions given); beyond the course, by the fast engine too, which
/// must give the same image.
#[derive(Parser)]
#[command(name = "bench")]
struct BenchArgs {
    /// Sessions whose stages are timed (default: all of this build's).
    sessions: Vec<u32>,
    #[command(flatten)]
    work: WorkArgs,
}

/// The `bench` command.
pub const VERB: Verb = Verb {
    rank: 4,
    command: <BenchArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = BenchArgs::from_arg_matches(matches)?;
    let options = RenderArgs {
        work: args.work.clone(),
        ..RenderArgs::default()
    };
    let header = "| stage | settings | course's code | rays | Mrays/s | course |";
    let rule = "|---|---|---|---|---|---|";
    #[cfg(feature = "beyond")]
    let (header, rule) = (
        format!("{header} `--fast` | speed-up |"),
        format!("{rule}---|---|"),
    );
    println!("{header}\n{rule}");
    let chosen = |session: u32| args.sessions.is_empty() || args.sessions.contains(&session);
    for stage in stages().filter(|s| chosen(s.session)) {
        let job = Job::of_stage(stage, &Overrides::default(), &options)?;
        let course = timed_render(stage.name, &job, &options)?;
        let row = row(stage, &job.scene, &course);
        #[cfg(feature = "beyond")]
        let row = row + &crate::commands::beyond::fast_columns(stage, &course, &options)?;
        println!("{row}");
    }
    Ok(())
}

/// The table's row of `stage`: its settings, its time by the course's code, its
/// rays, and the course's time.
fn row(stage: &Stage, scene: &Scene, course: &Timed) -> String {
    format!(
        "| `{}` ({}) | {} | {:.2} s | {} | {:.2} | {} |",
        stage.name,
        stage.figure.map_or("-".into(), |f| f.to_string()),
        scene.summary(Language::English),
        course.seconds,
        course.result.rays,
        course.result.rays as f64 / course.seconds / 1e6,
        stage.course_time.unwrap_or("-")
    )
}
