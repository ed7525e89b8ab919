//! Tells the crate which course session it is built for, as the environment
//! variable `RAYCOURSE_SESSION` (read by `src/scene_file/features.rs`): the highest
//! of the features `s1`..`s7` that Cargo enabled, or, in a session view, which has
//! no session features, the highest `sessions/sN` folder it holds.

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
    println!("cargo::rustc-env=RAYCOURSE_SESSION={session}");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=sessions");
}
