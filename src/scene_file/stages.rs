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
    /// The scene file's path in the repository.
    pub path: &'static str,
    /// The scene file's text.
    pub source: &'static str,
}

macro_rules! stage {
    ($session:literal, $figure:expr, $name:literal, $title:literal) => {
        Stage {
            session: $session,
            figure: $figure,
            name: $name,
            title: $title,
            path: concat!("sessions/s", $session, "/", $name, ".toml"),
            source: include_str!(concat!("../../sessions/s", $session, "/", $name, ".toml")),
        }
    };
}

/// Every stage of the course written so far, in course order.
const ALL: &[Stage] = &[
    stage!(
        1,
        Some(1),
        "white-disk",
        "camera rays and a sphere: white where hit"
    ),
    stage!(1, Some(2), "shading", "Lambert shading under a point light"),
    stage!(
        1,
        Some(3),
        "spheres",
        "several spheres, the nearest hit wins"
    ),
    stage!(2, Some(4), "gamma", "gamma correction"),
    stage!(2, Some(5), "shadows", "shadow rays"),
    stage!(2, Some(6), "mirror", "a mirror sphere: recursive radiance"),
    stage!(
        2,
        Some(7),
        "glass",
        "glass: refraction, total internal reflection"
    ),
    stage!(
        3,
        Some(8),
        "indirect",
        "indirect lighting by Monte Carlo path tracing"
    ),
    stage!(
        3,
        Some(9),
        "antialiasing",
        "Gaussian jitter of camera rays (Box-Muller)"
    ),
    stage!(
        4,
        Some(10),
        "soft-shadows",
        "a sphere light found by indirect rays only"
    ),
    stage!(
        4,
        Some(11),
        "light-sampling",
        "direct light by sampling the light sphere"
    ),
    stage!(
        4,
        Some(12),
        "depth-of-field",
        "a thin lens: aperture and focus distance"
    ),
    stage!(4, None, "fresnel", "extra: glass with Fresnel reflection"),
    stage!(
        4,
        None,
        "russian-roulette",
        "extra: Russian roulette past the bounce limit"
    ),
    stage!(
        5,
        Some(13),
        "mesh",
        "a triangle mesh from an OBJ file, brute force"
    ),
    stage!(
        5,
        Some(14),
        "mesh-bbox",
        "the mesh's bounding box tested first"
    ),
    stage!(6, Some(15), "bvh", "a bounding volume hierarchy"),
    stage!(6, Some(16), "smooth-normals", "interpolated vertex normals"),
    stage!(
        7,
        Some(17),
        "textures",
        "texture coordinates and texture lookup"
    ),
    stage!(
        7,
        Some(18),
        "camera",
        "a camera placed and aimed: the plunging view"
    ),
];

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
