//! Tells the crate which course session it is built for, as the environment
//! variable `RAYCOURSE_SESSION` (read by `src/scene_file/features.rs`): the highest
//! of the features `s1`..`s7` that Cargo enabled, or, in a session view, which has
//! no session features, the highest `sessions/sN` folder it holds. And, as
//! `RAYCOURSE_MADE`, what the crate is: the course's crate (`features`), a session
//! view (`view`) or a student's exercise crate (`exercises`, marked so in its
//! `Cargo.toml`), so that a message about a later session reads right in each.

use std::path::Path;

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
    println!("cargo::rustc-env=RAYCOURSE_SESSION={session}");
    println!("cargo::rustc-env=RAYCOURSE_MADE={made}");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=Cargo.toml");
    println!("cargo::rerun-if-changed=sessions");
}
