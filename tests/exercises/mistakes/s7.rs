//! Session 7's mistakes: the texture lookup, the camera's orientation.

use raycourse::camera::Orientation;
use raycourse::camera::aim::aim;
use raycourse::materials::texture::{Filter, Texture};
use raycourse::maths::{Colour, Quat, Real, Vec3};

use super::Mistake;
use crate::generated::{self, Round, course_texture, lookup_at};

/// Session 7's mistakes.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        exercise: "s7.1",
        what: "rows counted from the bottom, y = v H",
        run: || {
            generated::texture_colour(|t, [u, v]| {
                read(t, [u * width(t), v * height(t)], FLOOR, true)
            })
        },
        rule: "rule-s7-1-y-1-v-h-not",
    },
    Mistake {
        exercise: "s7.1",
        what: "W and H swapped",
        run: || {
            generated::texture_colour(|t, [u, v]| {
                read(t, [u * height(t), (1.0 - v) * width(t)], FLOOR, true)
            })
        },
        rule: "rule-s7-1-yours-swaps-u-and-v",
    },
    Mistake {
        exercise: "s7.1",
        what: "y cast to an integer, truncated towards zero",
        run: || {
            generated::texture_colour(|t, [u, v]| {
                read(
                    t,
                    [u * width(t), (1.0 - v) * height(t)],
                    [Real::floor, Real::trunc],
                    true,
                )
            })
        },
        rule: "rule-s7-1-towards-minus-infinity",
    },
    Mistake {
        exercise: "s7.1",
        what: "bilinear without the half-texel shift",
        run: || {
            generated::texture_colour(|t, [u, v]| {
                read(t, [u * width(t), (1.0 - v) * height(t)], FLOOR, false)
            })
        },
        rule: "rule-s7-1-by-half-a-texel",
    },
    Mistake {
        exercise: "s7.2",
        what: "the camera aimed at the origin",
        run: || generated::aim(|eye, _, up, plunge| aim(eye, Vec3::ZERO, up, plunge)),
        rule: "rule-s7-2-not-at-the-origin",
    },
    Mistake {
        exercise: "s7.2",
        what: "right = up x forward",
        run: || generated::aim(|e, t, up, p| aim_with(e, t, up, p, Aim::Mirrored)),
        rule: "rule-s7-2-which-mirrors-the-image",
    },
    Mistake {
        exercise: "s7.2",
        what: "back = forward",
        run: || generated::aim(|e, t, up, p| aim_with(e, t, up, p, Aim::BackForward)),
        rule: "rule-s7-2-back-forward",
    },
    Mistake {
        exercise: "s7.2",
        what: "the plunge taken as radians",
        run: || generated::aim(|e, t, up, p| aim_with(e, t, up, p, Aim::Radians)),
        rule: "rule-s7-2-the-plunge-is-in-degrees",
    },
    Mistake {
        exercise: "s7.2",
        what: "the eye raised around the origin",
        run: || generated::aim(|e, t, up, p| aim_with(e, t, up, p, Aim::AroundOrigin)),
        rule: "rule-s7-2-keeps-its-distance-to-it",
    },
    Mistake {
        exercise: "s7.2",
        what: "right not normalised",
        run: || generated::aim(|e, t, up, p| aim_with(e, t, up, p, Aim::RightLong)),
        rule: "rule-s7-2-right-normalize-forward-x-up",
    },
    Mistake {
        exercise: "s7.2",
        what: "no frame within a hundredth of up",
        run: || generated::aim(|e, t, up, p| aim_with(e, t, up, p, Aim::NearUp)),
        rule: "rule-s7-2-only-a-camera-looking-exactly",
    },
];

/// The chapter's rounding to a texel, `floor`, on both axes.
const FLOOR: [Round; 2] = [Real::floor, Real::floor];

/// A texture's width, in texels.
fn width(texture: &Texture) -> Real {
    texture.width as Real
}

/// A texture's height, in texels.
fn height(texture: &Texture) -> Real {
    texture.height as Real
}

/// The lookup at the texel-space `point` with `round`, and the half-texel shift
/// of a bilinear filter when `shifted`.
fn read(texture: &Texture, point: [Real; 2], round: [Round; 2], shifted: bool) -> Colour {
    let shift = if shifted && texture.filter == Filter::Bilinear {
        0.5
    } else {
        0.0
    };
    lookup_at(&course_texture(texture), point, round, shift)
}

/// A mistake in aiming the camera.
#[derive(Clone, Copy, PartialEq)]
enum Aim {
    /// `right = up x forward`.
    Mirrored,
    /// `back = forward`.
    BackForward,
    /// The plunge given to the rotation as if in radians.
    Radians,
    /// The eye turned around the origin rather than the target.
    AroundOrigin,
    /// `right = forward x up`, not normalised.
    RightLong,
    /// No frame where `|forward x up| < 1e-2`, rather than only at 0.
    NearUp,
}

/// The chapter's `aim` with `mistake`.
fn aim_with(
    eye: Vec3,
    target: Vec3,
    up: Vec3,
    plunge: Real,
    mistake: Aim,
) -> Option<(Vec3, Orientation)> {
    let offset = eye - target;
    let axis = offset.cross(up).try_normalize()?;
    let angle = if mistake == Aim::Radians {
        plunge
    } else {
        plunge.to_radians()
    };
    let turn = Quat::from_axis_angle(axis, angle);
    let eye = if mistake == Aim::AroundOrigin {
        turn * eye
    } else {
        target + turn * offset
    };
    let forward = (target - eye).try_normalize()?;
    let across = match mistake {
        Aim::Mirrored => up.cross(forward),
        _ => forward.cross(up),
    };
    if mistake == Aim::NearUp && across.length() < 1e-2 {
        return None;
    }
    let right = if mistake == Aim::RightLong {
        across
    } else {
        across.try_normalize()?
    };
    let back = if mistake == Aim::BackForward {
        forward
    } else {
        -forward
    };
    Some((
        eye,
        Orientation::Aimed {
            right,
            up: right.cross(forward),
            back,
        },
    ))
}
