//! The developer and student tasks of `raycourse`:
//!
//! - `cargo xtask view sN DIR`: the crate as it stands after session N, in `DIR`;
//! - `cargo xtask views DIR`: the views of every session, in `DIR/s1`, `DIR/s2`, ...;
//! - `cargo xtask exercise sN DIR`: session N's exercise crate, the view with the
//!   session's exercises to write (`--only sN.K`: one of them; `--switch`: every
//!   exercise of the build kept, stubbed while `RAYCOURSE_STUB` names it, for CI);
//! - `cargo xtask exercises`: every exercise, its function, file and test;
//! - `cargo xtask mdbook-listings`: the book's preprocessor that takes each session
//!   chapter's listings from that session's view (mdBook runs it);
//! - `cargo xtask mdbook-formulas hide|show`: the book's preprocessors that keep its
//!   formulas whole through the translation (mdBook runs them);
//! - `cargo xtask book [--open]`: the live book, the crate compiled to WebAssembly
//!   for its demos and check page, in `book/build/` (`--open`: served and opened);
//! - `cargo xtask serve DIR`: the files of `DIR` served on 127.0.0.1, as `book
//!   --open` serves the book (the browser tests serve it so);
//! - `cargo xtask names DIR`: the names the Rust files under `DIR` define, which
//!   the book's check compares between the crate and each session's view;
//! - `cargo xtask book-tools`: mdBook, its formula preprocessor and its translation
//!   tools, installed where missing at the versions the book is built with (pinned
//!   there alone: CI and the translation check call this);
//! - `cargo xtask messages [--accept]`: the program's message catalogue complete and
//!   current in every language (`--accept`: the translations as they are recorded
//!   as current).

mod book;
#[cfg(test)]
mod calls;
mod cfg;
mod course;
mod directive;
mod exercise;
mod formulas;
mod glossary;
#[cfg(test)]
mod layout;
mod listings;
mod manifest;
// The exercises' markers are read as the checklist reads them, from its own file.
#[path = "../../tests/exercises/marker.rs"]
mod marker;
mod messages;
mod names;
mod preprocessor;
mod prune;
mod serve;
mod source;
mod student;
mod timings;
mod view;
mod words;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The crate's root: the folder above this one.
pub(crate) fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives in the crate's folder")
        .to_owned()
}

/// The session of `sN`, from 1 to the last.
fn session(text: &str) -> Result<u32, String> {
    let last = cfg::last_session();
    text.strip_prefix('s')
        .and_then(|n| n.parse().ok())
        .filter(|n| (1..=last).contains(n))
        .ok_or_else(|| format!("`{text}` is not a session: expected s1 to s{last}"))
}

fn run(args: &[String]) -> Result<(), String> {
    let usage = "usage: cargo xtask view sN DIR | cargo xtask views DIR | \
                 cargo xtask exercise sN DIR [--only sN.K] [--switch] | cargo xtask exercises | \
                 cargo xtask mdbook-listings | cargo xtask mdbook-formulas hide|show | \
                 cargo xtask book [--open] | cargo xtask book-tools | cargo xtask serve DIR | \
                 cargo xtask names DIR | \
                 cargo xtask messages [--accept]";
    match args.iter().map(String::as_str).collect::<Vec<_>>()[..] {
        ["view", n, dir] => {
            let n = session(n)?;
            view::write_view(&root(), n, Path::new(dir))?;
            println!("session {n}'s view -> {dir}");
            Ok(())
        }
        ["views", dir] => (1..=cfg::last_session())
            .try_for_each(|n| view::write_view(&root(), n, &Path::new(dir).join(format!("s{n}")))),
        ["exercise", n, dir, ref more @ ..] => exercise(session(n)?, Path::new(dir), more),
        ["exercises"] => {
            let all = exercise::all(&root())?;
            for (marker, file) in &all {
                println!(
                    "{}\t{}\t{}\t{}",
                    marker.id,
                    marker.function,
                    file,
                    exercise::line_of(&all, &marker.id)
                );
            }
            Ok(())
        }
        ["mdbook-listings", "supports", _] => Ok(()),
        ["mdbook-listings"] => listings::preprocess(&root()),
        ["mdbook-formulas", _, "supports", _] => Ok(()),
        ["mdbook-formulas", mode] => formulas::preprocess(mode),
        ["book"] => book::build(&root(), false),
        ["book", "--open"] => book::build(&root(), true),
        ["book-tools"] => book::install_tools(&root()),
        ["serve", dir] => serve::serve(Path::new(dir), false),
        ["names", dir] => {
            names::defined_under(Path::new(dir))?
                .iter()
                .for_each(|name| println!("{name}"));
            Ok(())
        }
        ["messages"] => messages::check(&root(), false),
        ["messages", "--accept"] => messages::check(&root(), true),
        _ => Err(usage.into()),
    }
}

/// `cargo xtask exercise sN DIR [--only sN.K] [--switch]`.
fn exercise(session: u32, dir: &Path, more: &[&str]) -> Result<(), String> {
    let only = match more.iter().position(|a| *a == "--only") {
        Some(i) => Some(
            *more
                .get(i + 1)
                .ok_or("--only needs an exercise, such as s3.2")?,
        ),
        None => None,
    };
    let how = if more.contains(&"--switch") {
        exercise::Stub::Switch
    } else {
        exercise::Stub::Todo
    };
    let choice = student::Choice { session, only, how };
    let stubbed = student::write_exercises(&root(), &choice, dir)?;
    println!("session {session}'s exercises -> {}", dir.display());
    for marker in &stubbed {
        println!("  {} {} ({})", marker.id, marker.title, marker.function);
    }
    println!("next: cd {} && cargo test", dir.display());
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(2)
        }
    }
}
