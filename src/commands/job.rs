//! What a command renders: a scene, at the course's settings but for the options'.
//! A build that goes beyond the course adds the settings beyond it that the scene
//! file and the options ask for, read with the scene: each build has its own
//! `Job::parse` and `Job::render_reporting` (the course's below, the other in
//! `beyond.rs`), and both read a job from a file or a stage alike.

use std::path::Path;

use raycourse::scene_file::load::read_source;
use raycourse::{Overrides, Scene, Stage};

use crate::commands::failure::Failure;
use crate::commands::options::RenderArgs;

/// A scene to render, and how.
pub struct Job {
    /// The scene, at the course's settings but for the options'.
    pub scene: Scene,
    /// What its render uses beyond the course.
    #[cfg(feature = "beyond")]
    pub beyond: raycourse::scene::beyond::Beyond,
}

impl Job {
    /// The scene file at `path` with `overrides`, and what `options` ask for.
    pub fn of_file(
        path: &Path,
        overrides: &Overrides,
        options: &RenderArgs,
    ) -> Result<Job, Failure> {
        Job::parse(&read_source(path)?, path, overrides, options)
    }

    /// The scene of `stage` with `overrides`, and what `options` ask for.
    pub fn of_stage(
        stage: &Stage,
        overrides: &Overrides,
        options: &RenderArgs,
    ) -> Result<Job, Failure> {
        Job::parse(stage.source, &stage.file(), overrides, options)
    }
}

/// How a job is read and rendered by the course's code alone.
#[cfg(not(feature = "beyond"))]
mod course {
    use std::path::Path;

    use raycourse::{Overrides, Render};

    use crate::commands::failure::Failure;
    use crate::commands::job::Job;
    use crate::commands::options::RenderArgs;

    impl Job {
        /// The scene file's text `source` (read from `path`) with `overrides`;
        /// `_options` asks for nothing more in this build.
        pub(super) fn parse(
            source: &str,
            path: &Path,
            overrides: &Overrides,
            _options: &RenderArgs,
        ) -> Result<Job, Failure> {
            let scene = raycourse::parse_scene(source, path, overrides)?;
            Ok(Job { scene })
        }

        /// The scene rendered by the course's code on the current thread pool,
        /// `progress` told of each row's samples as they are done.
        pub fn render_reporting(&self, progress: &(dyn Fn(u64) + Sync)) -> Render {
            raycourse::render_reporting(&self.scene, progress)
        }
    }
}
