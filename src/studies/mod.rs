//! Studies of speed and accuracy: convergence against a reference, variants of a scene, scale sweeps, ray sets.

pub mod convergence;
pub mod plot;
#[cfg(feature = "s6")]
pub mod rayset;
pub mod reference;
pub mod scale;
pub mod variant;

pub use convergence::*;
pub use plot::*;
#[cfg(feature = "s6")]
pub use rayset::*;
pub use reference::*;
pub use variant::*;
