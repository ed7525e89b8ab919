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

/// The radiance of each sample of pixel (`row`, `column`), in order, drawn as the
/// course's pixel loop draws them (`render/samples.rs`): one path per sample from a
/// random point of the pixel, with the pixel's own random numbers.
#[cfg(feature = "s3")]
pub fn pixel_samples(
    tracer: &mut raycourse::integrator::Tracer,
    row: u32,
    column: u32,
) -> Vec<raycourse::maths::Colour> {
    let scene = tracer.scene;
    let index = u64::from(row) * u64::from(scene.camera.width) + u64::from(column);
    tracer.rng = raycourse::maths::random::pixel_rng(scene.settings.seed, index);
    (0..scene.settings.samples)
        .map(|_| {
            let ray = scene.camera.sample_ray(row, column, &mut tracer.rng);
            tracer.radiance(&ray, scene.settings.bounces)
        })
        .collect()
}
