//! The number types in single precision (the `f32` feature): not a course session,
//! but a way to measure what precision costs and buys.

// ANCHOR: single
/// The scalar type in single precision.
pub type Real = f32;

/// A point or a direction in single precision.
pub type Vec3 = glam::Vec3;

/// A rotation matrix in single precision.
pub type Mat3 = glam::Mat3;

/// A rotation quaternion in single precision.
pub type Quat = glam::Quat;

/// The constant pi in single precision.
pub const PI: Real = std::f32::consts::PI;
// ANCHOR_END: single

/// `x` itself: single precision already.
pub fn to_single(x: Real) -> f32 {
    x
}

/// `x` widened to double precision, exactly.
pub fn to_double(x: Real) -> f64 {
    f64::from(x)
}
