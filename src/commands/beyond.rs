//! What the command line does beyond the course: a job read with its settings beyond
//! the course, adaptive sampling's map, and the fast engine, with the checks that it
//! gives the course's bytes. The options themselves are in `beyond_options.rs`.

use std::path::Path;

use raycourse::check::compare::same_picture;
use raycourse::messages::language::Language;
use raycourse::messages::said::Said;
use raycourse::messages::say;
use raycourse::render::png::encode_rgb8;
use raycourse::scene_file::beyond::{BeyondOverrides, parse_with_beyond, stage_with_beyond};
use raycourse::{Disk, Overrides, Render, Scene, Stage};

use crate::commands::beyond_options::BeyondArgs;
use crate::commands::failure::Failure;
use crate::commands::job::Job;
use crate::commands::options::RenderArgs;
use crate::commands::output::{Timed, timed_render, write};

impl Job {
    /// The scene file's text `source` (read from `path`) with `overrides`, and the
    /// settings beyond the course that it and `options` ask for.
    pub(super) fn parse(
        source: &str,
        path: &Path,
        overrides: &Overrides,
        options: &RenderArgs,
    ) -> Result<Job, Failure> {
        let beyond = options.beyond.overrides();
        let (scene, beyond) = parse_with_beyond(source, path, overrides, &beyond, &Disk)?;
        Ok(Job { scene, beyond })
    }

    /// The scene rendered on the current thread pool by the engine its settings
    /// beyond the course choose, `progress` told of each row's samples as they are
    /// done.
    pub fn render_reporting(&self, progress: &(dyn Fn(u64) + Sync)) -> Render {
        raycourse::engines::render_reporting(&self.scene, &self.beyond, progress)
    }
}

impl BeyondArgs {
    /// Writes the map of the samples each pixel of `scene` took (`taken`), if
    /// `--noise-map` asks for it, and says so.
    pub fn write_noise_map(
        &self,
        label: &str,
        scene: &Scene,
        taken: &[u32],
        language: Language,
    ) -> Result<(), Failure> {
        let Some(map) = &self.noise_map else {
            return Ok(());
        };
        write(map, &sample_map(taken, scene))?;
        let (fewest, most) = (taken.iter().min(), taken.iter().max());
        let arguments = [
            ("label", label.into()),
            ("fewest", (*fewest.unwrap_or(&0)).into()),
            ("most", (*most.unwrap_or(&0)).into()),
            ("out", map.display().to_string().into()),
        ];
        println!("{}", say(language, "render-noise-map", &arguments));
        Ok(())
    }
}

/// A grey image of the samples each pixel took, black for the fewest.
fn sample_map(taken: &[u32], scene: &Scene) -> Vec<u8> {
    let fewest = taken.iter().copied().min().unwrap_or(0);
    let most = taken.iter().copied().max().unwrap_or(0);
    let span = f64::from((most - fewest).max(1));
    let grey: Vec<u8> = taken
        .iter()
        .flat_map(|&n| [(255.0 * f64::from(n - fewest) / span).round() as u8; 3])
        .collect();
    encode_rgb8(&grey, scene.camera.width, scene.camera.height)
}

/// The last columns of `bench`'s row of `stage`: its time by the fast engine and the
/// speed-up over the course's code (`course`), whose picture it must show
/// ([`same_picture`]).
pub fn fast_columns(
    stage: &Stage,
    course: &Timed,
    options: &RenderArgs,
) -> Result<String, Failure> {
    let fast = BeyondOverrides {
        fast: true,
        ..BeyondOverrides::default()
    };
    let (scene, beyond) = stage_with_beyond(stage, &Overrides::default(), &fast)?;
    let (gamma, samples) = (scene.settings.gamma, scene.settings.samples);
    let fast = timed_render(stage.name, &Job { scene, beyond }, options)?;
    if !same_picture(&course.result.film, &fast.result.film, gamma, samples) {
        return Err(differs(stage));
    }
    let speed_up = course.seconds / fast.seconds;
    Ok(format!(" {:.2} s | {speed_up:.2}x |", fast.seconds))
}

/// Renders `stage` with `options` by the course's code and by the fast engine, and
/// fails unless the two show the same picture ([`same_picture`]).
pub fn same_picture_by_the_fast_engine(
    stage: &Stage,
    mut options: RenderArgs,
) -> Result<(), Failure> {
    let course = Job::of_stage(stage, &options.overrides(), &options)?;
    options.beyond.fast = true;
    let fast = Job::of_stage(stage, &options.overrides(), &options)?;
    let settings = &course.scene.settings;
    let by_course = timed_render(stage.name, &course, &options)?.result.film;
    let by_fast = timed_render(stage.name, &fast, &options)?.result.film;
    match same_picture(&by_course, &by_fast, settings.gamma, settings.samples) {
        true => Ok(()),
        false => Err(differs(stage)),
    }
}

/// The failure of a fast engine whose picture of `stage` is not the course's: a bug
/// of the machine, since the two must show the same picture.
fn differs(stage: &Stage) -> Failure {
    Failure::Broke(Said::new("command-fast-differs").with("stage", stage.name))
}
