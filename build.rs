//! Tells the crate which course session it is built for, as the environment
//! variable `RAYCOURSE_SESSION` (read by `src/scene_file/features.rs`): the highest
//! of the features `s1`..`s7` that Cargo enabled, or, in a session view, which has
//! no session features, the highest `sessions/sN` folder it holds. And, as
//! `RAYCOURSE_MADE`, what the crate is: the course's crate (`features`), a session
//! view (`view`) or a student's exercise crate (`exercises`, marked so in its
//! `Cargo.toml`), so that a message about a later session reads right in each;
//! an exercise crate also gets the cfg `course_answers`, under which its checklist
//! takes the course's answers from its dev-dependency `course`.
//! It also writes the list of the course's stages (`stages.rs` in `OUT_DIR`), one
//! for each scene file of `sessions/sN/`, from the file's `[stage]` table.

use std::path::{Path, PathBuf};

fn main() {
    let enabled = (1..=7)
        .filter(|n| std::env::var_os(format!("CARGO_FEATURE_S{n}")).is_some())
        .max();
    let session = enabled.unwrap_or_else(|| {
        (1..=7)
            .filter(|n| Path::new(&format!("sessions/s{n}")).is_dir())
            .max()
            .unwrap_or(1)
    });
    let manifest = std::fs::read_to_string("Cargo.toml").unwrap_or_default();
    let made = if enabled.is_some() {
        "features"
    } else if manifest
        .lines()
        .skip_while(|l| l.trim() != "[package.metadata.raycourse]")
        .any(|l| l.trim() == "exercises = true")
    {
        "exercises"
    } else {
        "view"
    };
    write_stages();
    println!("cargo::rustc-env=RAYCOURSE_SESSION={session}");
    println!("cargo::rustc-env=RAYCOURSE_MADE={made}");
    // In an exercise crate the checklist compares the student's functions with the
    // course's, a dev-dependency named `course`; elsewhere the crate is the course.
    println!("cargo::rustc-check-cfg=cfg(course_answers)");
    if made == "exercises" {
        println!("cargo::rustc-cfg=course_answers");
    }
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=Cargo.toml");
    println!("cargo::rerun-if-changed=sessions");
}

/// One stage, as its scene file's `[stage]` table describes it.
struct Found {
    session: u32,
    figure: Option<u32>,
    name: String,
    title: String,
    course_time: Option<String>,
    path: PathBuf,
}

/// Writes `stages.rs` into `OUT_DIR`: a `Stage` for every scene file of
/// `sessions/s1` to `sessions/s7`, in course order (by session, then figure, the
/// extra stages last, by name), each with its text included.
fn write_stages() {
    let mut found: Vec<Found> = (1..=7).flat_map(stages_of).collect();
    assert!(
        !found.is_empty(),
        "no stage's file in sessions/s1 to sessions/s7"
    );
    found.sort_by_key(|s| (s.session, s.figure.unwrap_or(u32::MAX), s.name.clone()));
    let mut text = String::from("&[\n");
    for s in &found {
        text += &format!(
            "    Stage {{ session: {}, figure: {:?}, name: {:?}, title: {:?}, course_time: {:?}, \
             path: \"sessions/s{}/{}.toml\", source: include_str!({:?}) }},\n",
            s.session, s.figure, s.name, s.title, s.course_time, s.session, s.name, s.path
        );
    }
    text += "]\n";
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    std::fs::write(out.join("stages.rs"), text).expect("OUT_DIR can be written");
}

/// The stages of `sessions/sN`, in no order; a file without a `[stage]` table with a
/// title stops the build, naming the file.
fn stages_of(session: u32) -> Vec<Found> {
    // The folder Cargo runs this script for, read when it runs: a copy of the crate
    // built into the same target folder may share this script's compiled binary.
    let root = std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let folder = Path::new(&root).join(format!("sessions/s{session}"));
    let Ok(entries) = std::fs::read_dir(&folder) else {
        return vec![];
    };
    let mut found = vec![];
    for path in entries.flatten().map(|e| e.path()) {
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("a stage's file can be read");
        let table: toml::Table = text
            .parse()
            .unwrap_or_else(|e| panic!("{}: not TOML: {e}", path.display()));
        let stage = table.get("stage").and_then(toml::Value::as_table);
        let field = |key: &str| stage.and_then(|s| s.get(key));
        let title = field("title")
            .and_then(toml::Value::as_str)
            .unwrap_or_else(|| {
                panic!(
                    "{}: a stage's file needs a [stage] table with its title",
                    path.display()
                )
            });
        found.push(Found {
            session,
            figure: field("figure")
                .and_then(toml::Value::as_integer)
                .map(|f| f as u32),
            name: path
                .file_stem()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned(),
            title: title.to_owned(),
            course_time: field("course_time")
                .and_then(toml::Value::as_str)
                .map(str::to_owned),
            path: path.clone(),
        });
    }
    found
}
