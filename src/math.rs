//! The number types of the whole renderer, named in one place.
//!
//! Every other module says `Real`, `Vec3` and `Colour` rather than `f64` or
//! `glam::DVec3`, so the precision of the renderer is chosen here and nowhere else.

// ANCHOR: types
/// The scalar type of every distance, angle and radiance value.
pub type Real = f64;

/// A point or a direction in space (x right, y up, z towards the viewer).
pub type Vec3 = glam::DVec3;

/// A 3x3 matrix: the rotation that places a mesh.
pub type Mat3 = glam::DMat3;

/// Linear radiance in red, green and blue, on the course's scale (see [`crate::Film`]).
pub type Colour = glam::DVec3;
// ANCHOR_END: types

/// The constant pi at the precision of [`Real`].
pub const PI: Real = std::f64::consts::PI;

/// The machine epsilon of [`Real`] halved: the largest relative error of one
/// correctly rounded operation, the unit roundoff `u` of floating-point analysis.
pub const UNIT_ROUNDOFF: Real = Real::EPSILON * 0.5;

/// Higham's bound `gamma(n) = n u / (1 - n u)` on the relative error accumulated by
/// `n` successive rounded operations; used to bound the error of a hit point.
pub const fn error_bound(n: u32) -> Real {
    let nu = n as Real * UNIT_ROUNDOFF;
    nu / (1.0 - nu)
}
