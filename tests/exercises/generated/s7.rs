//! Session 7 on generated inputs: the texture lookup, the camera's orientation.

mod camera;
mod texture;

pub use camera::aim;
pub use texture::{Round, course_texture, lookup_at, texture_colour};
