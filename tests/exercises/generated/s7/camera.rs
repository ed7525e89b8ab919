//! The camera's orientation on generated cameras, aimed off the origin, with `up`
//! of any length and nearly along the view.

use proptest::prelude::*;
use raycourse::camera::Orientation;
use raycourse::maths::{PI, Real, Vec3};

use super::super::s1::{direction, scale};
use super::super::{differs, n, on_generated, ulps, v};
use crate::known::Outcome;
use crate::say;

/// A generated camera, as `aim` is given it.
#[derive(Clone, Copy, Debug)]
struct Camera {
    /// Where the eye is before the plunge.
    eye: Vec3,
    /// The point it looks at.
    target: Vec3,
    /// The vertical, of any length.
    up: Vec3,
    /// How far the eye is raised around the target, in degrees.
    plunge: Real,
}

/// An angle between the view and up, in radians: from `1e-3` to `pi - 1e-3`,
/// square, and close to either end often.
fn angle_to_up() -> impl Strategy<Value = Real> {
    prop_oneof![
        Just(PI / 2.0),
        (-3.0..-1.0 as Real).prop_map(|e| (10.0 as Real).powf(e)),
        (-3.0..-1.0 as Real).prop_map(|e| PI - (10.0 as Real).powf(e)),
        1e-3..PI - 1e-3,
    ]
}

/// A plunge in degrees, from -80 to 80: whole degrees often.
fn plunge() -> impl Strategy<Value = Real> {
    prop_oneof![(-80i32..=80).prop_map(|d| d as Real), -80.0..80.0 as Real]
}

/// The eye's distance to the target, from `1e-3` to `1e4`, powers of ten among them.
fn distance() -> impl Strategy<Value = Real> {
    prop_oneof![
        (-3i32..=4).prop_map(|k| (10.0 as Real).powi(k)),
        (-3.0..4.0 as Real).prop_map(|e| (10.0 as Real).powf(e)),
    ]
}

/// A target off the origin, from a tenth of `distance` to ten times it away.
fn target(distance: Real) -> impl Strategy<Value = Vec3> {
    (direction(), -1.0..1.0 as Real)
        .prop_map(move |(way, e)| (10.0 as Real).powf(e) * distance * way)
}

/// A camera aimed at a target off the origin, with `up` of any length and at any
/// angle to the view, down to `1e-3` radians before the plunge or after it (the
/// plunge adds to the angle between the view and up).
fn aimed() -> impl Strategy<Value = Camera> {
    let angles = (angle_to_up(), any::<bool>(), plunge()).prop_filter_map(
        "1e-3 radians from up, before and after the plunge",
        |(angle, after, plunge)| {
            let before = if after {
                angle - plunge.to_radians()
            } else {
                angle
            };
            let far_from_up = |a: Real| a.sin() >= 1e-3;
            (far_from_up(before) && far_from_up(before + plunge.to_radians()))
                .then_some((before, plunge))
        },
    );
    let view = (direction(), direction(), 0.1..10.0 as Real);
    (
        distance().prop_flat_map(|d| (Just(d), target(d))),
        view,
        angles,
    )
        .prop_map(
            |((distance, target), (up, across, length), (angle, plunge))| {
                let side = (across - across.dot(up) * up).normalize_or(up.any_orthonormal_vector());
                let offset = distance * (angle.sin() * side - angle.cos() * up);
                Camera {
                    eye: target + offset,
                    target,
                    up: length * up,
                    plunge,
                }
            },
        )
}

/// A camera looking exactly along `up`, both on one axis: it has no frame.
fn along() -> impl Strategy<Value = Camera> {
    let axes = [Vec3::X, Vec3::Y, Vec3::Z];
    let target = distance().prop_flat_map(|d| (Just(d), target(d)));
    (0usize..3, any::<bool>(), scale(), target, plunge()).prop_map(
        move |(axis, opposite, length, (distance, target), plunge)| {
            let up = if opposite { -length } else { length } * axes[axis];
            Camera {
                eye: target + distance * axes[axis],
                target,
                up,
                plunge,
            }
        },
    )
}

/// Generated cameras: aimed ones, and a tenth looking exactly along `up`.
fn cameras() -> impl Strategy<Value = Camera> {
    prop_oneof![9 => aimed(), 1 => along()]
}

/// An aimed camera's eye and frame, `[right, up', back]`; the fixed camera's
/// frame is `x`, `y`, `z`.
type Frame = (Vec3, [Vec3; 3]);

/// The frame of the student's camera.
fn frame((eye, orientation): (Vec3, Orientation)) -> Frame {
    match orientation {
        Orientation::Fixed => (eye, [Vec3::X, Vec3::Y, Vec3::Z]),
        Orientation::Aimed { right, up, back } => (eye, [right, up, back]),
    }
}

/// The course's camera of `camera`, plunged by `plunge` degrees.
fn course_aim(camera: Camera, plunge: Real) -> Option<Frame> {
    use course::camera::Orientation as CourseOrientation;
    let (eye, orientation) =
        course::camera::aim::aim(camera.eye, camera.target, camera.up, plunge)?;
    Some(match orientation {
        CourseOrientation::Fixed => (eye, [Vec3::X, Vec3::Y, Vec3::Z]),
        CourseOrientation::Aimed { right, up, back } => (eye, [right, up, back]),
    })
}

/// Whether two cameras agree: their eyes within `tolerance` times `distance`
/// (the eye's from the target), their frames within `tolerance`.
fn same_frame(a: Frame, b: Frame, tolerance: Real, distance: Real) -> bool {
    (a.0 - b.0).length() <= tolerance * distance
        && (0..3).all(|k| (a.1[k] - b.1[k]).length() <= tolerance)
}

impl Camera {
    /// The tolerance of a frame, when the course's is `expected`: 64 roundings of
    /// the eye's distance and the target's, over that distance, divided by the
    /// sine of the angle between the view and up, before or after the plunge,
    /// whichever is smaller.
    fn tolerance(&self, expected: Option<Frame>) -> Real {
        let offset = self.eye - self.target;
        let sine = |d: Vec3| {
            d.normalize_or_zero()
                .cross(self.up.normalize_or_zero())
                .length()
        };
        let after = expected.map_or(1.0, |(_, [_, _, back])| sine(back));
        let smallest = sine(offset).min(after).max(1e-6);
        ulps(64.0) * (offset.length() + self.target.length()) / offset.length() / smallest
    }

    /// The camera in the book's notation.
    fn describe(&self) -> String {
        say!(
            "generated-s7-camera-the-camera-at-looking-at-up",
            eye = v(self.eye),
            target = v(self.target),
            up = v(self.up),
            plunge = n(self.plunge)
        )
    }
}

/// A camera's frame in the book's notation.
fn show_frame(frame: Option<Frame>) -> String {
    frame.map_or(say!("generated-s7-camera-no-frame"), |(eye, [r, u, b])| {
        say!(
            "generated-s7-camera-the-eye-at-right-up-back",
            eye = v(eye),
            r = v(r),
            u = v(u),
            b = v(b)
        )
    })
}

/// Exercise s7.2 on generated cameras (see [`cameras`]): the eye and the frame
/// agree with the course's within [`Camera::tolerance`], and there is no frame
/// exactly where the course has none.
pub fn aim(yours: impl Fn(Vec3, Vec3, Vec3, Real) -> Option<(Vec3, Orientation)>) -> Outcome {
    on_generated("aim", cameras(), |camera| {
        let gave = yours(camera.eye, camera.target, camera.up, camera.plunge).map(frame);
        let expected = course_aim(camera, camera.plunge);
        let tolerance = camera.tolerance(expected);
        let distance = (camera.eye - camera.target).length();
        let same = match (gave, expected) {
            (None, None) => true,
            (Some(g), Some(e)) => same_frame(g, e, tolerance, distance),
            _ => false,
        };
        if same {
            return Ok(());
        }
        let why = aim_rule(gave, expected, camera, tolerance);
        Err(differs(
            &camera.describe(),
            &show_frame(gave),
            &show_frame(expected),
            Some(why),
        ))
    })
}

/// The rule of the camera's frame that `gave` breaks, `expected` being the
/// course's.
fn aim_rule(
    gave: Option<Frame>,
    expected: Option<Frame>,
    camera: Camera,
    tolerance: Real,
) -> String {
    let offset = camera.eye - camera.target;
    let (Some(g), Some(e)) = (gave, expected) else {
        return along_rule(gave.is_some(), offset, camera.up);
    };
    let close =
        |other: Option<Frame>| other.is_some_and(|o| same_frame(g, o, tolerance, offset.length()));
    let at_origin = Camera {
        target: Vec3::ZERO,
        ..camera
    };
    let [right, _, back] = g.1;
    if close(course_aim(at_origin, camera.plunge)) {
        say!(
            "generated-s7-camera-the-camera-looks-at-the-target",
            camera_target = v(camera.target)
        )
    } else if close(course_aim(camera, camera.plunge.to_degrees())) {
        say!("generated-s7-camera-the-plunge-is-in-degrees-turn")
    } else if ((g.0 - camera.target).length() - offset.length()).abs() > tolerance * offset.length()
    {
        say!(
            "generated-s7-camera-the-eye-turns-around-the-target",
            offset_length = n(offset.length()),
            target_length = n((g.0 - camera.target).length())
        )
    } else if (g.0 - e.0).length() > tolerance * offset.length() {
        say!("generated-s7-camera-the-eye-rises-around-the-target")
    } else {
        frame_rule(right, back, e.1, camera.up)
    }
}

/// The rule of the frame `right`, `back` breaks, the course's being `expected`.
fn frame_rule(right: Vec3, back: Vec3, expected: [Vec3; 3], up: Vec3) -> String {
    let flipped = |a: Vec3, b: Vec3| (a + b).length() <= 1e-3;
    if flipped(right, expected[0]) {
        say!("generated-s7-camera-right-forward-x-up-not-up")
    } else if (right.length() - 1.0).abs() > 1e-3 {
        say!(
            "generated-s7-camera-right-normalize-forward-x-up-forward",
            up_length = n(up.length()),
            right_length = n(right.length())
        )
    } else if flipped(back, expected[2]) {
        say!("generated-s7-camera-back-forward-camera-space-z-points")
    } else {
        say!("generated-s7-camera-forward-normalize-target-eye-right-normalize")
    }
}

/// The rule of a camera looking along `up` or not: `framed` when yours gave a
/// frame, `offset` the eye's from the target.
fn along_rule(framed: bool, offset: Vec3, up: Vec3) -> String {
    if framed {
        return say!("generated-s7-camera-the-camera-looks-exactly-along-up");
    }
    let angle = offset.cross(up).length().atan2(-offset.dot(up));
    say!(
        "generated-s7-camera-the-view-is-radians-from-up",
        angle = n(angle)
    )
}
