//! Aiming the camera: a frame built from where it is, what it looks at and which way
//! is up.

use crate::maths::{Quat, Real, Vec3};

/// Which way the camera looks.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Orientation {
    /// Down `-z`, with `y` up: the camera of the first six sessions.
    #[default]
    Fixed,
    /// Along any direction: camera-space `x`, `y`, `z` become `right`, `up` and
    /// `back` (minus the viewing direction).
    Aimed {
        /// Unit vector to the right of the image.
        right: Vec3,
        /// Unit vector to the top of the image.
        up: Vec3,
        /// Unit vector from the scene towards the eye.
        back: Vec3,
    },
}

impl Orientation {
    /// The world vector of camera-space `v`.
    pub fn to_world(&self, v: Vec3) -> Vec3 {
        match *self {
            Orientation::Fixed => v,
            Orientation::Aimed { right, up, back } => v.x * right + v.y * up + v.z * back,
        }
    }
}

// ANCHOR: aim
/// The eye position and orientation of a camera at `eye` looking at `target`, with
/// `up` giving the vertical, after raising the eye by `plunge` degrees around the
/// target (it keeps its distance and keeps looking at the target). The frame:
/// `forward = normalize(target - eye)`, `right = normalize(forward x up)`,
/// `up' = right x forward`, and camera-space `z` is `back = -forward`. `None` if
/// the camera looks along `up` or at its own position.
///
/// Exercise s7.2, the camera's orientation: book session 7, "The camera".
pub fn aim(eye: Vec3, target: Vec3, up: Vec3, plunge: Real) -> Option<(Vec3, Orientation)> {
    let offset = eye - target;
    let axis = offset.cross(up).try_normalize()?;
    let raised = Quat::from_axis_angle(axis, plunge.to_radians()) * offset;
    let forward = (-raised).try_normalize()?;
    let right = forward.cross(up).try_normalize()?;
    let orientation = Orientation::Aimed {
        right,
        up: right.cross(forward),
        back: -forward,
    };
    Some((target + raised, orientation))
}
// ANCHOR_END: aim

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unplunged_aim_down_minus_z_is_the_fixed_camera() {
        let (eye, o) = aim(Vec3::new(0.0, 0.0, 55.0), Vec3::ZERO, Vec3::Y, 0.0).unwrap();
        assert_eq!(eye, Vec3::new(0.0, 0.0, 55.0));
        let v = Vec3::new(0.3, -0.2, -1.0);
        assert!((o.to_world(v) - v).length() < 4.0 * Real::EPSILON);
    }

    #[test]
    fn plunging_raises_the_eye_and_looks_at_the_target() {
        let target = Vec3::new(1.0, 2.0, 3.0);
        let (eye, o) = aim(target + Vec3::new(0.0, 0.0, 50.0), target, Vec3::Y, 30.0).unwrap();
        assert!(
            ((eye - target).length() - 50.0).abs() < 1e-12,
            "same distance"
        );
        assert!(
            (eye.y - target.y - 25.0).abs() < 1e-12,
            "raised by 50 sin 30"
        );
        let centre_ray = o.to_world(-Vec3::Z);
        assert!((centre_ray - (target - eye).normalize()).length() < 1e-15);
        let up = o.to_world(Vec3::Y);
        assert!(up.y > 0.0 && up.dot(centre_ray).abs() < 1e-15);
    }

    #[test]
    fn looking_along_up_is_refused() {
        assert!(aim(Vec3::Y, Vec3::ZERO, Vec3::Y, 0.0).is_none());
        assert!(aim(Vec3::ZERO, Vec3::ZERO, Vec3::Y, 0.0).is_none());
    }
}
