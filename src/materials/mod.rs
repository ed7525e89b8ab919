//! Materials: what a surface does with the light that reaches it.
//!
//! The laws of reflection and refraction live here as plain functions; how the
//! renderer follows a ray through each material lives in the
//! [integrator](crate::integrator).
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`material`] | 1 | the kinds of surface: diffuse (1), mirror and glass (2), Fresnel glass (4) |
//! | [`optics`] | 2 | the laws of reflection and refraction (Snell-Descartes) |
//! | [`fresnel`] | 4 | how much light glass reflects: the Fresnel equations |
//! | [`texture`] | 7 | an albedo read from a picture |

pub mod material;

#[cfg(feature = "s2")]
pub mod optics;

#[cfg(feature = "s4")]
pub mod fresnel;

#[cfg(feature = "s7")]
pub mod texture;

pub use material::Material;
