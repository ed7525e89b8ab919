//! `raycourse bench`: the stages at the course's settings, timed with the course's
//! code and (from session 3) with the fast engine, beside the times the course
//! reported on its own machine.

use std::num::NonZeroUsize;

use clap::{ArgMatches, FromArgMatches, Parser};
use raycourse::scene_file::SESSION;
use raycourse::{Overrides, Scene, Stage, stages};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::options::RenderArgs;
use crate::commands::output::{Timed, timed_render};

/// Render the stages at the course's settings and print a table of their times,
/// by the course's code and (from session 3) by the fast engine, which must give
/// the same image, beside the course's own times (every stage of this build, or
/// those of the sessions given).
#[derive(Parser)]
#[command(name = "bench")]
struct BenchArgs {
    /// Sessions whose stages are timed (default: all of this build's).
    sessions: Vec<u32>,
    /// Worker threads (default: one per core).
    #[arg(long)]
    threads: Option<NonZeroUsize>,
}

/// The `bench` command.
pub const VERB: Verb = Verb {
    rank: 4,
    session: 1,
    command: <BenchArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

/// The time the course reported for the stage of figure `figure` on its own machine.
fn course_time(figure: Option<u32>) -> &'static str {
    match figure {
        Some(1..=7) => "under 1 s",
        Some(8..=9) => "under 10 s",
        Some(11) => "about 15 s",
        Some(13) => "35 s",
        Some(14) => "15 s",
        Some(15..=18) => "about 60 s",
        _ => "-",
    }
}

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = BenchArgs::from_arg_matches(matches)?;
    let options = RenderArgs {
        threads: args.threads,
        quiet: true,
        ..RenderArgs::default()
    };
    println!(
        "| stage | settings | course's code | `--fast` | speed-up | rays | Mrays/s | course |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    let chosen = |session: u32| args.sessions.is_empty() || args.sessions.contains(&session);
    for stage in stages().filter(|s| chosen(s.session)) {
        let scene = stage.scene(&Overrides::default())?;
        let course = timed_render(stage.name, &scene, &options)?;
        let fast = fast_render(stage, &options)?;
        if let Some(fast) = &fast
            && fast.result.film != course.result.film
        {
            return Err(Failure::Machine(format!(
                "{}: the fast engine's image differs from the course's code's",
                stage.name
            )));
        }
        println!("{}", row(stage, &scene, &course, fast.as_ref()));
    }
    Ok(())
}

/// `stage` rendered by the fast engine, from session 3 (`None` before).
fn fast_render(stage: &Stage, options: &RenderArgs) -> Result<Option<Timed>, Failure> {
    if SESSION < 3 {
        return Ok(None);
    }
    let fast = Overrides {
        fast: true,
        ..Overrides::default()
    };
    let scene = stage.scene(&fast)?;
    timed_render(stage.name, &scene, options).map(Some)
}

/// The table's row of `stage`: its settings, its times by the course's code and the
/// fast engine, its rays, and the course's time.
fn row(stage: &Stage, scene: &Scene, course: &Timed, fast: Option<&Timed>) -> String {
    let (time, speed_up) = match fast {
        Some(f) => (
            format!("{:.2} s", f.seconds),
            format!("{:.2}x", course.seconds / f.seconds),
        ),
        None => ("-".into(), "-".into()),
    };
    format!(
        "| `{}` ({}) | {} | {:.2} s | {time} | {speed_up} | {} | {:.2} | {} |",
        stage.name,
        stage.figure.map_or("-".into(), |f| f.to_string()),
        scene.summary(),
        course.seconds,
        course.result.rays,
        course.result.rays as f64 / course.seconds / 1e6,
        course_time(stage.figure)
    )
}
