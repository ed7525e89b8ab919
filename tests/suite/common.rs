//! Helpers shared by the tests that run the `raycourse` command.

use std::path::Path;
use std::process::Output;

use assert_cmd::cargo::cargo_bin_cmd;

/// Runs `raycourse` with `args` in `dir` and returns what it printed and its status.
pub fn run<S: AsRef<std::ffi::OsStr>>(args: &[S], dir: &Path) -> Output {
    cargo_bin_cmd!("raycourse")
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

/// Printed bytes as text, for messages and `contains` checks.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}
