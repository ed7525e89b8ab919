//! The camera: the pinhole of session 1, the thin lens of session 4, the aimed camera of session 7.

#[cfg(feature = "s7")]
pub mod aim;
#[cfg(feature = "s4")]
pub mod lens;
pub mod pinhole;

#[cfg(feature = "s7")]
pub use aim::*;
#[cfg(feature = "s4")]
pub use lens::*;
pub use pinhole::*;
