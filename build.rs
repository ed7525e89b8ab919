//! Tells the crate which course session it is built for, as the environment
//! variable `RAYCOURSE_SESSION` (read by `src/scene_file/features.rs`): the highest
//! of the session features (`s1`, `s2`, ..., as `Cargo.toml` names them) that Cargo
//! enabled, or, in a session view, which has no session features, the highest
//! `sessions/sN` folder it holds. And, as
//! `RAYCOURSE_MADE`, what the crate is: the course's crate (`features`), a session
//! view (`view`) or a student's exercise crate (`exercises`, marked so in its
//! `Cargo.toml`), so that a message about a later session reads right in each;
//! an exercise crate also gets the cfg `course_answers`, under which its checklist
//! takes the course's answers from its dev-dependency `course`.
//! It also writes the list of the course's stages (`stages.rs` in `OUT_DIR`), one
//! for each scene file of `sessions/sN/`, from the file's `[stage]` table; and
//! sets the cfg `processor_has_avx` where the processor building the crate for
//! itself has AVX, so that the fast engine's AVX tests run there and are reported
//! ignored, with the reason, where it has none.

use std::path::{Path, PathBuf};

fn main() {
    // The folder Cargo runs this script for, read when it runs: a copy of the crate
    // built into the same target folder may share this script's compiled binary.
    let root = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let manifest = std::fs::read_to_string(root.join("Cargo.toml"))
        .ok()
        .and_then(|text| text.parse::<toml::Table>().ok())
        .unwrap_or_default();
    let enabled = sessions_named(manifest.get("features").and_then(toml::Value::as_table))
        .filter(|n| std::env::var_os(format!("CARGO_FEATURE_S{n}")).is_some())
        .max();
    let folders: Vec<u32> = std::fs::read_dir(root.join("sessions"))
        .map(|entries| sessions_named_in(entries.flatten().map(|e| e.file_name())))
        .unwrap_or_default();
    let session = enabled.unwrap_or_else(|| folders.iter().copied().max().unwrap_or(1));
    let made = if enabled.is_some() {
        "features"
    } else if marked_exercises(&manifest) {
        "exercises"
    } else {
        "view"
    };
    write_stages(&root, &folders);
    println!("cargo::rustc-env=RAYCOURSE_SESSION={session}");
    println!("cargo::rustc-env=RAYCOURSE_MADE={made}");
    // In an exercise crate the checklist compares the student's functions with the
    // course's, a dev-dependency named `course`; elsewhere the crate is the course.
    println!("cargo::rustc-check-cfg=cfg(course_answers)");
    if made == "exercises" {
        println!("cargo::rustc-cfg=course_answers");
    }
    println!("cargo::rustc-check-cfg=cfg(processor_has_avx)");
    if builds_for_an_avx_processor() {
        println!("cargo::rustc-cfg=processor_has_avx");
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
}

/// The sessions among the features `features`: those named `sN`.
fn sessions_named(features: Option<&toml::Table>) -> impl Iterator<Item = u32> + '_ {
    features
        .into_iter()
        .flat_map(|table| table.keys())
        .filter_map(|name| name.strip_prefix('s')?.parse().ok())
}

/// The sessions among folder names: those named `sN`.
fn sessions_named_in(names: impl Iterator<Item = std::ffi::OsString>) -> Vec<u32> {
    names
        .filter_map(|name| name.to_str()?.strip_prefix('s')?.parse().ok())
        .collect()
}

/// Whether the manifest marks the crate as a student's exercise crate:
/// `[package.metadata.raycourse] exercises = true`.
fn marked_exercises(manifest: &toml::Table) -> bool {
    let marked = manifest
        .get("package")
        .and_then(|p| p.get("metadata"))
        .and_then(|m| m.get("raycourse"))
        .and_then(|r| r.get("exercises"));
    marked.and_then(toml::Value::as_bool) == Some(true)
}

/// Writes `stages.rs` into `OUT_DIR`: a `Stage` for every scene file of the
/// `sessions` folders of `root` (each `sessions/sN` of `folders`), in course order
/// (by session, then figure, the extra stages last, by name), each with its text
/// included from the folder of the crate being compiled (`CARGO_MANIFEST_DIR`), not
/// from this script's: a copy of the crate built into the same target folder shares
/// this output, and the copy may be gone by the next build.
fn write_stages(root: &Path, folders: &[u32]) {
    let mut found: Vec<Found> = folders.iter().flat_map(|&n| stages_of(root, n)).collect();
    assert!(!found.is_empty(), "no stage's file in sessions/sN");
    found.sort_by_key(|s| (s.session, s.figure.unwrap_or(u32::MAX), s.name.clone()));
    let mut text = String::from("&[\n");
    for s in &found {
        text += &format!(
            "    Stage {{ session: {}, figure: {:?}, name: {:?}, title: {:?}, course_time: {:?}, \
             path: \"sessions/s{n}/{name}.toml\", \
             source: include_str!(concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/sessions/s{n}/{name}.toml\")) }},\n",
            s.session,
            s.figure,
            s.name,
            s.title,
            s.course_time,
            n = s.session,
            name = s.name,
        );
    }
    text += "]\n";
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    std::fs::write(out.join("stages.rs"), text).expect("OUT_DIR can be written");
}

/// The stages of `sessions/sN`, in no order; a file without a `[stage]` table with a
/// title stops the build, naming the file.
fn stages_of(root: &Path, session: u32) -> Vec<Found> {
    let folder = root.join(format!("sessions/s{session}"));
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
        });
    }
    found
}

/// Whether the crate is built for this very processor (no cross-compiling), and it
/// has AVX: then the tests that run the fast engine on AVX lanes can run here.
fn builds_for_an_avx_processor() -> bool {
    let same = std::env::var("HOST").ok() == std::env::var("TARGET").ok();
    #[cfg(target_arch = "x86_64")]
    let avx = std::arch::is_x86_feature_detected!("avx");
    #[cfg(not(target_arch = "x86_64"))]
    let avx = false;
    same && avx
}
