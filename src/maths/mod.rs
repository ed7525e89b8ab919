//! Numbers, random numbers and sampling: the mathematics every other part uses.

#[cfg(feature = "s3")]
pub mod frame;
pub mod numbers;
pub mod random;
#[cfg(feature = "s3")]
pub mod sampling;

#[cfg(feature = "s3")]
pub use frame::*;
pub use numbers::*;
pub use random::*;
#[cfg(feature = "s3")]
pub use sampling::*;
