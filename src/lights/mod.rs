//! Light sources: the point light of session 1, the sphere light of session 4.

pub mod light;
#[cfg(feature = "s4")]
pub mod sphere_light;

pub use light::*;
#[cfg(feature = "s4")]
pub use sphere_light::*;
