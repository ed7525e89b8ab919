//! The student's crate of a session: `cargo xtask exercise sN DIR`.
//!
//! It is the session's view with the bodies of that session's exercises stubbed
//! (see [`crate::exercise`]) and one test, the checklist `tests/exercises/`, which
//! runs in the course's order: each exercise's known answers and its comparison
//! with the course's own function on generated inputs (the course's answers sit in
//! `tests/course/`, see [`crate::course`]), then each stage's image against the
//! reference image that ships beside it. The view's other tests
//! (snapshots to the byte, the unit tests inside the files) pin the course's own
//! code and would fail for a right answer written another way, so they are left out,
//! and so is the checklist's catalogue of mistakes, which runs against the course's
//! crate itself.

use std::fs;
use std::path::Path;

use toml_edit::DocumentMut;

use crate::course::{depend_on_course, write_course};
use crate::exercise::{Marker, Stub, stub_folder};
use crate::view::write_view;

/// What to stub: the exercises of the session, or one of them.
pub struct Choice<'a> {
    /// The session, 1 to 7.
    pub session: u32,
    /// One exercise only, such as `s3.2` (a teacher's or CI's choice).
    pub only: Option<&'a str>,
    /// Stubs to write, or switches for CI (every exercise of the build).
    pub how: Stub,
}

/// Writes the exercise crate of `choice.session` of the crate at `root` into `out`,
/// which must be absent or empty: a student's work is never written over. Returns
/// the exercises stubbed.
pub fn write_exercises(root: &Path, choice: &Choice, out: &Path) -> Result<Vec<Marker>, String> {
    if fs::read_dir(out).is_ok_and(|mut entries| entries.next().is_some()) {
        return Err(format!(
            "{}: the folder is not empty; an exercise crate is written only into a new folder, so that nobody's work is lost",
            out.display()
        ));
    }
    write_view(root, choice.session, out)?;
    write_course(out)?;
    for left_out in [
        "tests/suite",
        "tests/snapshots",
        "tests/bad-input",
        "tests/exercises/mistakes",
    ] {
        remove(&out.join(left_out))?;
    }
    remove(&out.join("tests/stages.rs"))?;
    let chosen = |m: &Marker| match (choice.how, choice.only) {
        (_, Some(id)) => m.id == id,
        (Stub::Todo, None) => m.session == choice.session,
        (Stub::Switch, None) => true,
    };
    let mut stubbed = stub_folder(&out.join("src"), &chosen, choice.how)?;
    stubbed.sort_by_key(|m| crate::exercise::order(&m.id));
    if stubbed.is_empty() {
        return Err(match choice.only {
            Some(id) => format!("no exercise {id} in session {}", choice.session),
            None => format!("session {} has no exercise", choice.session),
        });
    }
    let manifest = out.join("Cargo.toml");
    let text = fs::read_to_string(&manifest).map_err(|e| e.to_string())?;
    fs::write(&manifest, exercise_manifest(&text)?).map_err(|e| e.to_string())?;
    fs::write(out.join("README.md"), readme(choice.session, &stubbed))
        .map_err(|e| e.to_string())?;
    Ok(stubbed)
}

/// The manifest with the library's and the binary's own tests off and the suite's
/// target gone (only the checklist runs), the course's answers as a dev-dependency, marked as an exercise crate for the build script
/// (`[package.metadata.raycourse] exercises = true`).
fn exercise_manifest(text: &str) -> Result<String, String> {
    let mut doc: DocumentMut = text.parse().map_err(|e| format!("Cargo.toml: {e}"))?;
    let mut lib = toml_edit::Table::new();
    lib["test"] = toml_edit::value(false);
    lib["doctest"] = toml_edit::value(false);
    doc["lib"] = toml_edit::Item::Table(lib);
    let mut bin = toml_edit::Table::new();
    bin["name"] = toml_edit::value("raycourse");
    bin["path"] = toml_edit::value("src/main.rs");
    bin["test"] = toml_edit::value(false);
    let mut bins = toml_edit::ArrayOfTables::new();
    bins.push(bin);
    doc["bin"] = toml_edit::Item::ArrayOfTables(bins);
    // The suite's folder is left out of an exercise crate, and its target with it.
    if let Some(tests) = doc
        .get_mut("test")
        .and_then(toml_edit::Item::as_array_of_tables_mut)
    {
        tests.retain(|t| t.get("name").and_then(toml_edit::Item::as_str) != Some("suite"));
    }
    let mut marked = toml_edit::Table::new();
    marked["exercises"] = toml_edit::value(true);
    let mut metadata = toml_edit::Table::new();
    metadata.set_implicit(true);
    metadata["raycourse"] = toml_edit::Item::Table(marked);
    doc["package"]["metadata"] = toml_edit::Item::Table(metadata);
    depend_on_course(&mut doc);
    Ok(doc.to_string())
}

/// Removes a file or folder if it is there.
fn remove(path: &Path) -> Result<(), String> {
    let removed = if path.is_dir() {
        fs::remove_dir_all(path)
    } else if path.exists() {
        fs::remove_file(path)
    } else {
        Ok(())
    };
    removed.map_err(|e| format!("{}: {e}", path.display()))
}

/// The exercise crate's README: the exercises, the loop, where the answers are.
fn readme(session: u32, stubbed: &[Marker]) -> String {
    let list: String = stubbed
        .iter()
        .map(|m| format!("- **{}**, {} ({})\n", m.id, m.title, m.book))
        .collect();
    format!(
        "# raycourse, session {session}: the exercises\n\n\
         This crate is `raycourse` as it stands after session {session}, with the body of \
         each of the session's exercises replaced by `todo!(...)`. Everything else (scene \
         files and their reading, the commands, the images' output, the sessions before) \
         is complete: write the functions below, in this order.\n\n{list}\n\
         Each function's doc comment says what it computes and carries its marker; the \
         panic of its stub names it too.\n\n\
         ```sh\n\
         cargo test                          # the checklist, in the course's order\n\
         cargo test -- s{session}_2                # the tests whose name contains s{session}_2\n\
         cargo run --release -- s{session} <stage>   # render a stage with your code\n\
         ```\n\n\
         `cargo test` runs each exercise's known answers (worked out by hand in the \
         book) and compares it with the course's own function on generated inputs that \
         reach the awkward cases (odd image sizes, far and tiny spheres, ties, grazing \
         rays, poles, degenerate triangles, non-square textures), printing the simplest input that differs with the rule it breaks; then \
         it renders each stage at an odd, non-square size and compares it with the \
         reference image in `tests/exercises/references/`: within a few display levels \
         for one sample per pixel, within the noise for Monte Carlo stages, whatever \
         formula you chose and whatever order you draw your random numbers in. A stage \
         that differs is followed ray by ray, with your code and the course's, to the \
         first call whose result differs. Its last line says how far you are. The course's answers are in `tests/course/`, which only the checklist \
         compiles (your `src/` never calls it), and in the course's crate: `cargo xtask \
         view s{session} DIR` writes the finished session.\n"
    )
}
