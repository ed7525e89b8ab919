//! Session 7 on generated inputs: the texture lookup, the camera's orientation.

mod camera;
mod texture;

pub use camera::aim;
pub use texture::texture_colour;
// What the catalogue of mistakes reads a texture with, in the course's crate alone.
#[cfg(not(course_answers))]
pub use texture::{Round, course_texture, lookup_at};
