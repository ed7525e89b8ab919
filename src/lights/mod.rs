//! Light sources.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`light`] | 1 | the point light of the course and Lambert's law |
//! | [`sphere_light`] | 4 | a glowing sphere: soft shadows, and the cone it is seen under |

pub mod light;

#[cfg(feature = "s4")]
pub mod sphere_light;

pub use light::{Light, PointLight};

#[cfg(feature = "s4")]
pub use sphere_light::{Cone, SphereLight};
