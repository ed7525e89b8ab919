//! Maths: the numbers every other part of the renderer computes with.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`numbers`] | 1 | `Real`, `Vec3`, `Colour`: the number types, named once |
//! | [`double`] | 1 | the types in double precision (`single`: with the `f32` feature) |
//! | [`values`] | 1 | numbers read from scene files, checked against their rule |
//! | [`random`] | 3 | the random numbers of a pixel's samples |
//! | [`sampling`] | 3 | random directions and offsets, each beside its density |
//! | [`frame`] | 3 | an orthonormal frame around a normal |

pub mod numbers;

#[cfg(not(feature = "f32"))]
pub mod double;
#[cfg(feature = "f32")]
pub mod single;
pub mod values;

#[cfg(feature = "s3")]
pub mod frame;
#[cfg(feature = "s3")]
pub mod random;
#[cfg(feature = "s3")]
pub mod sampling;

pub use numbers::*;
#[cfg(feature = "s3")]
pub use random::*;
