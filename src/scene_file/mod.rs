//! Scene files: the TOML format, its checks and errors, the loader session by
//! session, and the course's stages.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`format`](mod@format) | 1 | every key of the format, for every session |
//! | [`error`] | 1 | errors that name the file, the key and what was expected |
//! | [`features`] | 1 | which session this build was compiled for |
//! | [`sessions`] | 1 | which session brings each key: "needs feature s2" |
//! | [`consistency`] | 1 | values that do not go together |
//! | [`load`] | 1 | reading a file: parsed, checked, and built by the latest session |
//! | [`session1`] | 1 | the camera, the spheres, a point light and the settings |
//! | [`session3`] | 3 | antialiasing |
//! | [`session4`] | 4 | the sphere light and the thin lens |
//! | [`session5`] | 5 | triangle meshes |
//! | [`session6`] | 6 | hierarchies and smooth normals |
//! | [`session7`] | 7 | textures and the aimed camera |
//! | [`beyond`](mod@beyond) | `beyond` | the sampler, adaptive sampling and the fast engine, on top of the course's scene |
//! | [`field_names`] | `beyond` | a struct's keys, asked of serde rather than listed again |
//! | [`stages`](mod@stages) | 1 | the course's stages, one scene file each |

pub mod consistency;
pub mod error;
pub mod features;
pub mod format;
pub mod load;
pub mod session1;
pub mod sessions;
pub mod stages;

#[cfg(feature = "s3")]
pub mod session3;
#[cfg(feature = "s4")]
pub mod session4;
#[cfg(feature = "s5")]
pub mod session5;
#[cfg(feature = "s6")]
pub mod session6;
#[cfg(feature = "s7")]
pub mod session7;

#[cfg(feature = "beyond")]
pub mod beyond;
#[cfg(feature = "beyond")]
pub mod field_names;

pub use error::{SceneError, one_line};
pub use features::SESSION;
pub use load::{Overrides, load_scene, parse_scene, parse_scene_from};
pub use stages::{Stage, crate_folder, find_stage, stage_names, stages};
