//! The integrator: the radiance arriving along a ray, the course's recursive `radiance`.

#[cfg(feature = "s3")]
pub mod indirect;
pub mod radiance;
pub mod termination;

pub use radiance::*;
pub use termination::*;
