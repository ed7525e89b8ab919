//! The number types of the whole renderer, named in one place.
//!
//! Every other module says `Real`, `Vec3` and `Colour` rather than `f64` or
//! `glam::DVec3`, so the precision of the renderer is chosen here and nowhere else.

// ANCHOR: types
/// The scalar type of every distance, angle and radiance value.
#[cfg(not(feature = "f32"))]
pub type Real = f64;

/// A point or a direction in space (x right, y up, z towards the viewer).
#[cfg(not(feature = "f32"))]
pub type Vec3 = glam::DVec3;

/// A 3x3 matrix: the rotation that places a mesh.
#[cfg(not(feature = "f32"))]
pub type Mat3 = glam::DMat3;

/// A rotation as a unit quaternion: the camera's plunge.
#[cfg(not(feature = "f32"))]
pub type Quat = glam::DQuat;

/// The constant pi at the precision of [`Real`].
#[cfg(not(feature = "f32"))]
pub const PI: Real = std::f64::consts::PI;
// ANCHOR_END: types

// ANCHOR: single
/// The scalar type in single precision (the `f32` feature).
#[cfg(feature = "f32")]
pub type Real = f32;

/// A point or a direction in single precision.
#[cfg(feature = "f32")]
pub type Vec3 = glam::Vec3;

/// A rotation matrix in single precision.
#[cfg(feature = "f32")]
pub type Mat3 = glam::Mat3;

/// A rotation quaternion in single precision.
#[cfg(feature = "f32")]
pub type Quat = glam::Quat;

/// The constant pi in single precision.
#[cfg(feature = "f32")]
pub const PI: Real = std::f32::consts::PI;
// ANCHOR_END: single

/// `x` rounded to single precision, as files of `f32` values hold it.
#[cfg(not(feature = "f32"))]
pub fn to_single(x: Real) -> f32 {
    x as f32
}

/// `x` itself: single precision already.
#[cfg(feature = "f32")]
pub fn to_single(x: Real) -> f32 {
    x
}

/// `x` in double precision, as reference images are stored.
#[cfg(not(feature = "f32"))]
pub fn to_double(x: Real) -> f64 {
    x
}

/// `x` widened to double precision, exactly.
#[cfg(feature = "f32")]
pub fn to_double(x: Real) -> f64 {
    f64::from(x)
}

/// Linear radiance in red, green and blue, on the course's scale (see [`crate::render::Film`]).
pub type Colour = Vec3;

/// The machine epsilon of [`Real`] halved: the largest relative error of one
/// correctly rounded operation, the unit roundoff `u` of floating-point analysis.
pub const UNIT_ROUNDOFF: Real = Real::EPSILON * 0.5;

/// Higham's bound `gamma(n) = n u / (1 - n u)` on the relative error accumulated by
/// `n` successive rounded operations; used to bound the error of a hit point.
pub const fn error_bound(n: u32) -> Real {
    let nu = n as Real * UNIT_ROUNDOFF;
    nu / (1.0 - nu)
}
