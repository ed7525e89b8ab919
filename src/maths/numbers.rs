//! The number types of the whole renderer, named in one place.
//!
//! Every other module says `Real`, `Vec3` and `Colour` rather than `f64` or
//! `glam::DVec3`, so the precision of the renderer is chosen here and nowhere else:
//! double precision ([`crate::maths::double`]), or single precision with the `f32`
//! feature.

#[cfg(not(feature = "f32"))]
pub use crate::maths::double::*;
#[cfg(feature = "f32")]
pub use crate::maths::single::*;

/// Linear radiance in red, green and blue, on the course's scale (see [`crate::render::Film`]).
pub type Colour = Vec3;

/// The machine epsilon of [`Real`] halved: the largest relative error of one
/// correctly rounded operation, the unit roundoff `u` of floating-point analysis.
pub const UNIT_ROUNDOFF: Real = Real::EPSILON * 0.5;

/// The bound `delta_n = n u / (1 - n u)` (Higham's `gamma_n`) on the relative error
/// accumulated by `n` successive rounded operations; used to bound the error of a
/// hit point.
pub const fn error_bound(n: u32) -> Real {
    let nu = n as Real * UNIT_ROUNDOFF;
    nu / (1.0 - nu)
}
