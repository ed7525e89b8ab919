//! Helpers shared by the tests that run the `raycourse` command.

use std::path::Path;
use std::process::{Command, Output};

/// Runs `raycourse` (the binary Cargo built for these tests) with `args` in `dir`,
/// in the C locale, and returns what it printed and its status.
pub fn run<S: AsRef<std::ffi::OsStr>>(args: &[S], dir: &Path) -> Output {
    run_in_locale(args, dir, "C.UTF-8")
}

/// Runs `raycourse` as [`run`] does, with `LANG` set to `locale` (and `LC_ALL`,
/// `LC_MESSAGES` unset, so that `LANG` decides).
pub fn run_in_locale<S: AsRef<std::ffi::OsStr>>(args: &[S], dir: &Path, locale: &str) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raycourse"))
        .args(args)
        .current_dir(dir)
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", locale)
        .output()
        .unwrap()
}

/// Printed bytes as text, for messages and `contains` checks.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}
