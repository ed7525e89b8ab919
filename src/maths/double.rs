//! The number types in double precision: the renderer's own.

// ANCHOR: types
/// The scalar type of every distance, angle and radiance value.
pub type Real = f64;

/// A point or a direction in space (x right, y up, z towards the viewer).
pub type Vec3 = glam::DVec3;

/// A 3x3 matrix: the rotation that places a mesh.
pub type Mat3 = glam::DMat3;

/// A rotation as a unit quaternion: the camera's plunge.
pub type Quat = glam::DQuat;

/// The constant pi at the precision of [`Real`].
pub const PI: Real = std::f64::consts::PI;
// ANCHOR_END: types

/// `x` rounded to single precision, as files of `f32` values hold it.
pub fn to_single(x: Real) -> f32 {
    x as f32
}

/// `x` in double precision, as reference images are stored.
pub fn to_double(x: Real) -> f64 {
    x
}
