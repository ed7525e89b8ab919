//! # raycourse
//!
//! A ray tracer written to be read alongside a seven-session course on ray tracing:
//! from a white disk on black to a path-traced, textured triangle mesh seen by a
//! moving camera.
//!
//! ## Features
//!
//! The Cargo features `s1` to `s7` are the course's sessions. Each enables the one
//! before it, so `--no-default-features --features s3` is the crate a student has
//! after the third session. The default is `s7`, the whole course, with `beyond`:
//! what goes beyond it (the fast engine, the samplers, the studies), which no
//! session view or exercise crate holds.
//!
//! | feature | session brings |
//! |---|---|
//! | `s1` | camera rays, spheres, nearest hit, Lambert shading with a point light |
//! | `s2` | gamma correction, shadow rays, mirror and glass spheres |
//! | `s3` | Monte Carlo indirect lighting, antialiasing |
//! | `s4` | soft shadows, light sampling, depth of field |
//! | `s5` | triangle meshes (OBJ), bounding box |
//! | `s6` | bounding volume hierarchy, smooth normals |
//! | `s7` | textures, a movable camera |
//!
//! A feature decides what code exists; a scene file decides what a render uses.
//! Session 1 is the least a build can have: without `s1` the crate does not compile.

//! ## The parts of a ray tracer, in the order they depend on each other
//!
//! Each module uses only those above it (`cargo test -p xtask` holds this order, the
//! table's and the `mod` lines' alike).
//!
//! | module | what it does | sessions |
//! |---|---|---|
//! | [`maths`] | number types, random numbers, sampling | 1, 3 |
//! | [`messages`] | what the program says, in English or French, from one catalogue of messages | 1 |
//! | [`files`] | where a scene's meshes and textures are read: the disk, or memory in a web page | 1 |
//! | [`materials`] | diffuse, mirror, glass, Fresnel glass, textures | 1, 2, 4, 7 |
//! | [`geometry`] | rays, hit records, spheres, boxes, triangles | 1, 2, 5 |
//! | [`camera`] | the pinhole, antialiasing, the thin lens, the aimed camera | 1, 3, 4, 7 |
//! | [`lights`] | the point light, the sphere light | 1, 4 |
//! | `meshes` | triangle meshes from OBJ files | 5, 6, 7 |
//! | `acceleration` | the bounding box, the bounding volume hierarchy | 5, 6 |
//! | [`scene`] | everything a render needs, and the nearest hit | 1, 2, 3, 5 |
//! | [`integrator`] | `radiance`: the light arriving along a ray | 1 to 4 |
//! | [`render`](mod@render) | every pixel, in parallel; the film; PNG files | 1, 3 |
//! | `samplers` | beyond the course: better-placed samples, adaptive sampling | `beyond` |
//! | `fast` | beyond the course: the fast engine, the same bytes in less time | `beyond` |
//! | [`scene_file`] | scene files, their checks, the course's stages | 1 to 7 |
//! | [`check`] | an image against the stage's: the comparison (1), a student's image graded with the likely mistake (7) | 1, 7 |
//! | `engines` | beyond the course: which engine renders a scene | `beyond` |
//! | `studies` | beyond the course: error against samples and time, scale sweeps, ray sets | `beyond` |
//! | [`inspect`] | one pixel's path ray by ray; images of normals, depth, objects and cost | 1 |
//!
//! A program starts with a [`Stage`] (or a scene file, [`load_scene`]), renders its
//! [`Scene`] with [`render()`] (the course's code) and writes the [`Film`] with
//! [`encode_png`]. What goes beyond the course reads its own settings with the scene
//! (`scene_file::beyond`) and renders with them (`engines::render`):
//!
//! ```
//! let stage = raycourse::find_stage(1, "shading").unwrap();
//! let scene = stage.scene(&raycourse::Overrides::default()).unwrap();
//! let image = raycourse::render(&scene);
//! let png = raycourse::encode_png(&image.film, scene.settings.gamma);
//! assert!(png.starts_with(b"\x89PNG"));
//! ```

#![warn(missing_docs)]
#![deny(unsafe_code)]
#![warn(clippy::undocumented_unsafe_blocks)]

#[cfg(not(feature = "s1"))]
compile_error!("raycourse needs at least the first session: enable feature s1 (or a later one)");

pub mod maths;

pub mod messages;

pub mod files;

pub mod materials;

pub mod geometry;

pub mod camera;
pub mod lights;

#[cfg(feature = "s5")]
pub mod meshes;

#[cfg(feature = "s5")]
pub mod acceleration;

pub mod scene;

pub mod integrator;

pub mod render;

#[cfg(feature = "beyond")]
pub mod samplers;

#[cfg(feature = "beyond")]
pub mod fast;

pub mod scene_file;

pub mod check;

#[cfg(feature = "beyond")]
pub mod engines;

#[cfg(feature = "beyond")]
pub mod studies;

pub mod inspect;

pub use files::{Disk, Files, InMemory};
pub use render::{Film, Render, encode_png};
pub use render::{render, render_reporting};
pub use scene::Scene;
pub use scene_file::{
    Overrides, SceneError, Stage, find_stage, load_scene, parse_scene, parse_scene_from, stages,
};
