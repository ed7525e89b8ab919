//! The scene: camera, objects, light and settings, and the nearest hit among the objects.

pub mod objects;

pub use objects::*;
