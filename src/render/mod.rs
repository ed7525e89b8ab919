//! The renderer: every pixel's radiance on the film, and the film written as a PNG.

pub mod film;
pub mod png;
pub mod rows;

pub use film::*;
pub use png::*;
pub use rows::*;
