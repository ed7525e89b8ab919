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

#[cfg(feature = "s5")]
mod aabb;
#[cfg(feature = "s7")]
mod aim;
#[cfg(feature = "s6")]
mod bvh;
mod camera;
mod convergence;
mod error;
#[cfg(feature = "s6")]
mod fast_bvh;
mod features;
mod film;
#[cfg(feature = "s3")]
mod frame;
#[cfg(feature = "s4")]
mod fresnel;
mod hit;
#[cfg(feature = "s3")]
mod indirect;
#[cfg(feature = "s4")]
mod lens;
mod light;
mod material;
mod math;
#[cfg(feature = "s5")]
mod mesh;
#[cfg(feature = "s5")]
mod mesh_file;
#[cfg(feature = "s2")]
mod optics;
mod plot;
mod png;
mod radiance;
mod ray;
#[cfg(feature = "s6")]
mod rayset;
mod reference;
mod render;
mod rng;
#[cfg(feature = "s6")]
mod sah;
#[cfg(feature = "s3")]
mod sampling;
mod scale;
mod scene;
mod scene_file;
#[cfg(feature = "s6")]
mod smooth;
mod sphere;
#[cfg(feature = "s4")]
mod sphere_light;
mod stages;
mod termination;
#[cfg(feature = "s7")]
mod texture;
#[cfg(feature = "s5")]
mod triangle;
#[cfg(feature = "s6")]
mod triangle_group;
mod values;
mod variant;
#[cfg(feature = "s5")]
mod watertight;

#[cfg(feature = "s5")]
pub use aabb::*;
#[cfg(feature = "s7")]
pub use aim::*;
#[cfg(feature = "s6")]
pub use bvh::*;
pub use camera::*;
pub use convergence::*;
pub use error::*;
#[cfg(feature = "s6")]
pub use fast_bvh::*;
pub use features::*;
pub use film::*;
#[cfg(feature = "s3")]
pub use frame::*;
#[cfg(feature = "s4")]
pub use fresnel::*;
pub use hit::*;
#[cfg(feature = "s4")]
pub use lens::*;
pub use light::*;
pub use material::*;
pub use math::*;
#[cfg(feature = "s5")]
pub use mesh::*;
#[cfg(feature = "s5")]
pub use mesh_file::*;
#[cfg(feature = "s2")]
pub use optics::*;
pub use plot::*;
pub use png::*;
pub use radiance::*;
pub use ray::*;
#[cfg(feature = "s6")]
pub use rayset::*;
pub use reference::*;
pub use render::*;
pub use rng::*;
#[cfg(feature = "s3")]
pub use sampling::*;
pub use scene::*;
pub use scene_file::*;
pub use sphere::*;
#[cfg(feature = "s4")]
pub use sphere_light::*;
pub use stages::*;
pub use termination::*;
#[cfg(feature = "s7")]
pub use texture::*;
#[cfg(feature = "s5")]
pub use triangle::*;
pub use values::*;
pub use variant::*;
#[cfg(feature = "s5")]
pub use watertight::*;
