//! The camera: where each pixel's rays start and which way they go.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`pinhole`] | 1 | the pinhole camera: one ray from the eye through each pixel |
//! | [`pixel_filter`] | 3 | where in its pixel a ray aims: a Gaussian around the centre |
//! | [`jitter`] | 3 | rays through random points of the pixel (antialiasing) |
//! | [`lens`] | 4 | the thin lens: rays from random points of an aperture (depth of field) |
//! | [`aim`] | 7 | a camera placed anywhere and aimed at a point |

pub mod pinhole;

#[cfg(feature = "s3")]
pub mod jitter;
#[cfg(feature = "s3")]
pub mod pixel_filter;

#[cfg(feature = "s4")]
pub mod lens;

#[cfg(feature = "s7")]
pub mod aim;

pub use pinhole::Camera;

#[cfg(feature = "s3")]
pub use pixel_filter::PixelFilter;

#[cfg(feature = "s4")]
pub use lens::{Lens, ThinLens};

#[cfg(feature = "s7")]
pub use aim::Orientation;
