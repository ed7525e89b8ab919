//! The course's stages: one scene file per figure, built into the binary so that it
//! runs from any folder.

use std::path::Path;

use crate::files::{Disk, Files};
use crate::scene::Scene;
use crate::scene_file::features::SESSION;
use crate::scene_file::{Overrides, SceneError, parse_scene_from};

/// One stage of the course: a figure of the course notes and the scene file that
/// renders it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stage {
    /// The session that teaches it, 1 to 7.
    pub session: u32,
    /// The figure of the course it reproduces; `None` for an extra stage that goes
    /// beyond the course's figures.
    pub figure: Option<u32>,
    /// Its name on the command line, such as `glass`.
    pub name: &'static str,
    /// What the stage adds, in a few words.
    pub title: &'static str,
    /// The time the course reported for it on its own machine, where it did.
    pub course_time: Option<&'static str>,
    /// The scene file's path in the repository.
    pub path: &'static str,
    /// The scene file's text.
    pub source: &'static str,
}

/// Every stage of the course written so far, in course order: one for each scene
/// file of `sessions/sN/`, as the build script (`build.rs`) reads its `[stage]`
/// table.
const ALL: &[Stage] = include!(concat!(env!("OUT_DIR"), "/stages.rs"));

/// The stages of this build: those of the sessions its features enable.
pub fn stages() -> impl Iterator<Item = &'static Stage> {
    ALL.iter().filter(|s| s.session <= SESSION)
}

/// The names of the stages of `session`, in course order.
pub fn stage_names(session: u32) -> Vec<&'static str> {
    stages()
        .filter(|s| s.session == session)
        .map(|s| s.name)
        .collect()
}

/// The stage of `session` called `name`, if this build has it.
pub fn find_stage(session: u32, name: &str) -> Option<&'static Stage> {
    stages().find(|s| s.session == session && s.name == name)
}

impl Stage {
    /// The stage's scene, at the course's settings but for `overrides`. Files the
    /// scene refers to (meshes, textures) are read from this crate's folder.
    pub fn scene(&self, overrides: &Overrides) -> Result<Scene, SceneError> {
        self.scene_from(overrides, &Disk)
    }

    /// The stage's scene, at the course's settings but for `overrides`, the files it
    /// refers to read from `files` under the names [`Stage::file`] gives them.
    pub fn scene_from(
        &self,
        overrides: &Overrides,
        files: &dyn Files,
    ) -> Result<Scene, SceneError> {
        parse_scene_from(self.source, &self.file(), overrides, files)
    }

    /// The scene file's path in this crate's folder, next to which the files it
    /// refers to are found.
    pub fn file(&self) -> std::path::PathBuf {
        crate_folder().join(self.path)
    }
}

/// The folder of this crate, where the stages' scene files and the assets they name
/// are: `crate_folder().join("assets/spot/spot.obj")` is the name under which a
/// stage reads the cow.
pub fn crate_folder() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}
