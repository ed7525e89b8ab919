//! What surfaces do with light: diffuse from session 1, mirror and glass from session 2, Fresnel glass from session 4, textures from session 7.

#[cfg(feature = "s4")]
pub mod fresnel;
pub mod material;
#[cfg(feature = "s2")]
pub mod optics;
#[cfg(feature = "s7")]
pub mod texture;

#[cfg(feature = "s4")]
pub use fresnel::*;
pub use material::*;
#[cfg(feature = "s2")]
pub use optics::*;
#[cfg(feature = "s7")]
pub use texture::*;
