//! Helpers shared by the tests that run the `raycourse` command.

use std::path::Path;
use std::process::{Command, Output};

/// Runs `raycourse` (the binary Cargo built for these tests) with `args` in `dir`
/// and returns what it printed and its status.
pub fn run<S: AsRef<std::ffi::OsStr>>(args: &[S], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raycourse"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

/// Printed bytes as text, for messages and `contains` checks.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}
