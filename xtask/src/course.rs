//! The course's answers inside a student's exercise crate: `tests/course/`, the
//! session's view as a library of its own (`course`), which the checklist compares
//! the student's functions with on generated inputs and when it traces a stage's
//! differing pixel. It is a dev-dependency: the student's `src/` never calls it, so
//! a student's edit always shows in the next render.

use std::fs;
use std::path::Path;

use toml_edit::{DocumentMut, Item, Table};

use crate::view::{copy, copy_folder};

/// Where the course's crate sits in an exercise crate.
pub const FOLDER: &str = "tests/course";

/// Copies the view at `view` (before its exercises are stubbed) into
/// `view/tests/course`, as the library `course`: its sources, build script, scene
/// files (the build script lists the stages from them) and message catalogue (its
/// sources read it in), with a manifest of its own.
pub fn write_course(view: &Path) -> Result<(), String> {
    let out = view.join(FOLDER);
    copy_folder(&view.join("src"), &out.join("src"))?;
    copy_folder(&view.join("sessions"), &out.join("sessions"))?;
    copy_folder(&view.join("messages"), &out.join("messages"))?;
    copy(&view.join("build.rs"), &out.join("build.rs"))?;
    let text = fs::read_to_string(view.join("Cargo.toml")).map_err(|e| e.to_string())?;
    fs::write(out.join("Cargo.toml"), course_manifest(&text)?).map_err(|e| e.to_string())?;
    fs::write(out.join("README.md"), README).map_err(|e| e.to_string())
}

/// What the folder is, for a student who opens it.
const README: &str = "# The course's answers\n\n\
    This is the course's own code for this session, as a library named `course`. \
    The checklist (`cargo test`) compares each function you write with the course's \
    on a few hundred generated inputs, and follows a stage's differing pixel through \
    both to find the first function whose result differs. Your crate's `src/` never \
    calls it: reading it is reading the answers.\n";

/// The view's manifest as the library `course`: no binary, tests, benchmarks,
/// dev-dependencies or profiles (a workspace member's profiles are ignored), no
/// workspace of its own (it is a member of the exercise crate's).
fn course_manifest(text: &str) -> Result<String, String> {
    let mut doc: DocumentMut = text.parse().map_err(|e| format!("Cargo.toml: {e}"))?;
    for key in [
        "workspace",
        "bin",
        "test",
        "bench",
        "dev-dependencies",
        "profile",
        "lib",
    ] {
        doc.remove(key);
    }
    let package = doc["package"]
        .as_table_mut()
        .ok_or("Cargo.toml: no [package]")?;
    package["name"] = toml_edit::value("raycourse-course");
    package["description"] = toml_edit::value(
        "The course's answers, which a student's checklist compares the student's functions with.",
    );
    package.remove("readme");
    package.remove("include");
    for auto in ["autobins", "autotests", "autobenches", "autoexamples"] {
        package[auto] = toml_edit::value(false);
    }
    let mut lib = Table::new();
    lib["name"] = toml_edit::value("course");
    lib["test"] = toml_edit::value(false);
    lib["doctest"] = toml_edit::value(false);
    doc["lib"] = Item::Table(lib);
    Ok(doc.to_string())
}

/// The dev-dependencies that an exercise crate's tests use: the checklist's
/// proptest and the course, and the unit tests' tempfile (in `src/`); the others
/// serve tests that only the course's crate holds (snapshots, studies), and would
/// lengthen a student's first build.
const CHECKLIST_USES: &[&str] = &["proptest", "course", "tempfile"];

/// The exercise crate's manifest `doc` with the course as a dev-dependency, and
/// no dev-dependency the checklist does not use.
pub fn depend_on_course(doc: &mut DocumentMut) {
    let mut course = toml_edit::InlineTable::new();
    course.insert("package", "raycourse-course".into());
    course.insert("path", FOLDER.into());
    if doc.get("dev-dependencies").is_none() {
        doc["dev-dependencies"] = toml_edit::table();
    }
    doc["dev-dependencies"]["course"] = toml_edit::value(course);
    build_checklist_quickly(doc);
    if let Some(table) = doc["dev-dependencies"].as_table_like_mut() {
        let unused: Vec<String> = table
            .iter()
            .map(|(name, _)| name.to_owned())
            .filter(|name| !CHECKLIST_USES.contains(&name.as_str()))
            .collect();
        for name in unused {
            table.remove(&name);
        }
    }
}

/// The checklist's build, quicker to compile: the student's crate at `opt-level` 2
/// rather than 3 (its stages render small, at about the same speed), and the
/// course's crate without optimisation, which the checklist calls on a few hundred
/// inputs per exercise and never renders with, and which then compiles in a third
/// of the time.
fn build_checklist_quickly(doc: &mut DocumentMut) {
    doc["profile"]["test"]["opt-level"] = toml_edit::value(2);
    let mut course = toml_edit::Table::new();
    course["opt-level"] = toml_edit::value(0);
    let mut packages = toml_edit::Table::new();
    packages.set_implicit(true);
    packages["raycourse-course"] = toml_edit::Item::Table(course);
    doc["profile"]["test"]["package"] = toml_edit::Item::Table(packages);
}

#[cfg(test)]
mod tests {
    use super::*;

    const MANIFEST: &str = "[workspace]\n\n[package]\nname = \"raycourse\"\nversion = \"0.1.0-s3\"\nreadme = \"README.md\"\n\n[dependencies]\nglam = \"0.34\"\n\n[dev-dependencies]\ninsta = \"1\"\nproptest = \"1\"\n\n[[bin]]\nname = \"raycourse\"\npath = \"src/main.rs\"\n\n[[test]]\nname = \"exercises\"\npath = \"tests/exercises/main.rs\"\nharness = false\n\n[profile.test]\nopt-level = 3\n";

    #[test]
    fn the_course_is_a_library_named_course_with_the_dependencies_alone() {
        let text = course_manifest(MANIFEST).unwrap();
        let doc: DocumentMut = text.parse().unwrap();
        assert_eq!(doc["package"]["name"].as_str(), Some("raycourse-course"));
        assert_eq!(doc["lib"]["name"].as_str(), Some("course"));
        assert_eq!(doc["package"]["autobins"].as_bool(), Some(false));
        assert_eq!(doc["dependencies"]["glam"].as_str(), Some("0.34"));
        for gone in ["workspace", "bin", "test", "dev-dependencies", "profile"] {
            assert!(doc.get(gone).is_none(), "{gone} is still there:\n{text}");
        }
    }

    #[test]
    fn the_exercise_crate_depends_on_the_course_for_its_tests_only() {
        let mut doc: DocumentMut = MANIFEST.parse().unwrap();
        depend_on_course(&mut doc);
        let course = doc["dev-dependencies"]["course"].as_inline_table().unwrap();
        assert_eq!(course.get("path").and_then(|p| p.as_str()), Some(FOLDER));
        assert!(doc["dependencies"].get("course").is_none());
        assert!(doc["dev-dependencies"].get("insta").is_none());
        assert!(doc["dev-dependencies"].get("proptest").is_some());
        assert_eq!(
            doc["profile"]["test"]["package"]["raycourse-course"]["opt-level"].as_integer(),
            Some(0)
        );
        assert_eq!(doc["profile"]["test"]["opt-level"].as_integer(), Some(2));
        let text = doc.to_string();
        assert!(
            text.contains("[profile.test.package.raycourse-course]\nopt-level = 0\n"),
            "{text}"
        );
        assert!(!text.contains("[profile.test.package]\n"), "{text}");
    }
}
