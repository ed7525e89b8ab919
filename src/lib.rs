//! # raycourse
//!
//! A ray tracer written to be read alongside a seven-session course on ray tracing:
//! from a white disk on black to a path-traced, textured triangle mesh seen by a
//! moving camera. Each module is one concept of the course.
//!
//! ## Features
//!
//! The Cargo features `s1` to `s7` are the course's sessions. Each enables the one
//! before it, so `--no-default-features --features s3` is the crate a student has
//! after the third session. The default is `s7`, the whole course.
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

#![warn(missing_docs)]

#[cfg(not(feature = "s1"))]
compile_error!("raycourse needs at least the first session: enable feature s1 (or a later one)");

#[cfg(feature = "s6")]
pub mod acceleration;
pub mod camera;
pub mod geometry;
pub mod integrator;
pub mod lights;
pub mod materials;
pub mod maths;
#[cfg(feature = "s5")]
pub mod meshes;
pub mod render;
pub mod scene;
pub mod scene_file;
pub mod studies;

#[cfg(feature = "s6")]
pub use acceleration::*;
pub use camera::*;
pub use geometry::*;
pub use integrator::*;
pub use lights::*;
pub use materials::*;
pub use maths::*;
#[cfg(feature = "s5")]
pub use meshes::*;
pub use render::*;
pub use scene::*;
pub use scene_file::*;
pub use studies::*;
