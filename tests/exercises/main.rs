//! The course's exercises as a checklist, in the course's order: for each session,
//! each exercise's known answers (worked out by hand, as the book does), then each
//! of its stages rendered small and compared with the reference image in
//! `references/`.
//!
//! In the course's crate every line passes: the code is the answer. In a student's
//! exercise crate (`cargo xtask exercise sN DIR`) the session's functions are stubs,
//! and the checklist says which one to write next, what it gave and what was
//! expected. It is a test with a harness of its own (`harness = false`), so that its
//! lines come out in the course's order rather than in parallel:
//!
//! ```text
//! cargo test --test exercises                 # the whole checklist
//! cargo test --test exercises -- s3_2         # the lines whose name contains s3_2
//! cargo test --test exercises -- --write-references   # after an intended change
//! cargo test --test exercises -- --lang fr    # in French (or LANG=fr_FR.UTF-8)
//! ```

mod checklist;
mod generated;
mod images;
mod isolation;
mod known;
mod marker;
// The catalogue of mistakes runs against the course crate itself: an exercise crate,
// whose course is a crate of its own, does not build it.
#[cfg(not(course_answers))]
mod mistakes;
mod panics;
mod s1;
#[cfg(feature = "s2")]
mod s2;
#[cfg(feature = "s3")]
mod s3;
#[cfg(feature = "s4")]
mod s4;
#[cfg(feature = "s5")]
mod s5;
#[cfg(feature = "s6")]
mod s6;
#[cfg(feature = "s7")]
mod s7;
mod trace;
mod words;

// The course's own answers, which `generated` compares each exercise with: in a
// student's exercise crate the dev-dependency `course` (its `tests/course/`), in
// the course's crate and its views the crate itself.
#[cfg(not(course_answers))]
extern crate raycourse as course;

use std::process::ExitCode;

/// The exercises of every session of the build, in the course's order.
const SESSIONS: &[&[checklist::Exercise]] = &[
    // One slice per session, each in the order its chapter teaches.
    s1::EXERCISES,
    #[cfg(feature = "s2")]
    s2::EXERCISES,
    #[cfg(feature = "s3")]
    s3::EXERCISES,
    #[cfg(feature = "s4")]
    s4::EXERCISES,
    #[cfg(feature = "s5")]
    s5::EXERCISES,
    #[cfg(feature = "s6")]
    s6::EXERCISES,
    #[cfg(feature = "s7")]
    s7::EXERCISES,
];

/// The memory of the checklist's processes, capped so that a line whose code
/// allocates for ever ends rather than take the machine's memory.
#[global_allocator]
static ALLOCATOR: isolation::Capped = isolation::Capped;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let Err(why) = words::choose(&args) {
        eprintln!("{why}");
        return ExitCode::from(2);
    }
    if let Some(at) = args.iter().position(|a| a == isolation::LINE) {
        return checklist::run_line(SESSIONS, args.get(at + 1).map_or("", String::as_str));
    }
    if args.iter().any(|a| a == "--write-references") {
        return images::write_references();
    }
    let filters: Vec<&str> = args
        .iter()
        .enumerate()
        .filter(|(at, a)| !a.starts_with('-') && (*at == 0 || args[at - 1] != "--lang"))
        .map(|(_, a)| a.as_str())
        .collect();
    checklist::run(SESSIONS, &filters)
}
