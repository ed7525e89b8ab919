//! Session 7: the texture lookup and the camera's orientation.

use raycourse::camera::Orientation;
use raycourse::camera::aim::aim;
use raycourse::materials::texture::{Filter, Texture};
use raycourse::maths::{Colour, Real, Vec3};

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, close_vec, ensure, vec};
use crate::say;
use crate::words::{decimal, separator};

/// Session 7's exercises, in the book's order.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "s7.1",
        name: "s7_1_texture_colour",
        shown_by: "textures",
        needs: &[],
        check: lookup,
    },
    Exercise {
        id: "s7.2",
        name: "s7_2_aim",
        shown_by: "camera",
        needs: &[],
        check: orientation,
    },
];

const RED: Colour = Colour::new(1.0, 0.0, 0.0);
const GREEN: Colour = Colour::new(0.0, 1.0, 0.0);
const BLUE: Colour = Colour::new(0.0, 0.0, 1.0);

/// A 2 x 2 texture, rows from the top: red, green / blue, white. `u` runs left to
/// right and `v` bottom to top, so `(0.25, 0.75)` is the top-left texel's centre
/// (red) and `(0.75, 0.25)` the bottom right's (white); the texture repeats, so
/// `(1.25, 0.75)` is red again, and `(-0.25, 0.75)` green, by the Euclidean
/// remainder of a negative address. Bilinear at a texel's centre is that texel, and at
/// the texture's centre the mean of the four, `(0.5, 0.5, 0.5)`.
fn lookup() -> Outcome {
    let texture = |filter| Texture {
        width: 2,
        height: 2,
        texels: vec![RED, GREEN, BLUE, Colour::ONE],
        filter,
    };
    let cases = [
        (
            Filter::Nearest,
            [0.25, 0.75],
            RED,
            say!("s7-case-the-top-left-texel-s-centre"),
        ),
        (
            Filter::Nearest,
            [0.75, 0.25],
            Colour::ONE,
            say!("s7-case-the-bottom-right-texel-s-centre"),
        ),
        (
            Filter::Nearest,
            [0.9, 0.9],
            GREEN,
            say!("s7-case-near-the-top-right-corner"),
        ),
        (
            Filter::Nearest,
            [1.25, 0.75],
            RED,
            say!("s7-case-one-texture-to-the-right-of"),
        ),
        (
            Filter::Nearest,
            [-0.25, 0.75],
            GREEN,
            say!("s7-case-a-quarter-of-a-texture-left"),
        ),
        (
            Filter::Bilinear,
            [0.25, 0.75],
            RED,
            say!("s7-case-the-top-left-texel-s-centre-2"),
        ),
        (
            Filter::Bilinear,
            [0.5, 0.5],
            Colour::splat(0.5),
            say!("s7-case-the-texture-s-centre"),
        ),
        (
            Filter::Bilinear,
            [0.5, 0.75],
            Colour::new(0.5, 0.5, 0.0),
            say!("s7-case-between-the-two-top-texels"),
        ),
    ];
    for (filter, uv, expected, what) in cases {
        let lookup = match filter {
            Filter::Nearest => say!("checklist-filter-nearest"),
            Filter::Bilinear => say!("checklist-filter-bilinear"),
        };
        let [u, v] = uv.map(|x| decimal(x.to_string()));
        let s = separator();
        close_vec(
            &say!(
                "s7-a-2-x-2-texture-red",
                filter_debug = format!("{:?}", filter),
                u = u,
                v = v,
                what = what,
                lookup = lookup,
                s = s
            ),
            texture(filter).colour(uv),
            expected,
            1e-6,
        )?;
    }
    generated::texture_colour(Texture::colour)
}

/// From `(0, 0, 10)` at the origin, `y` up: the fixed camera's frame, right
/// `(1, 0, 0)`, up `(0, 1, 0)`, back `(0, 0, 1)`. From `(10, 0, 0)`: right
/// `forward x up = (-1, 0, 0) x (0, 1, 0) = (0, 0, -1)`, back `(1, 0, 0)`. Raised by
/// 45 degrees: the eye at `(0, 7.071, 7.071)`, back `(0, 0.7071, 0.7071)`, up
/// `(0, 0.7071, -0.7071)`. Looking straight down along `up`: no frame.
fn orientation() -> Outcome {
    let h = (0.5 as Real).sqrt();
    let cases = [
        (
            Vec3::new(0.0, 0.0, 10.0),
            0.0,
            Vec3::new(0.0, 0.0, 10.0),
            [Vec3::X, Vec3::Y, Vec3::Z],
        ),
        (
            Vec3::new(10.0, 0.0, 0.0),
            0.0,
            Vec3::new(10.0, 0.0, 0.0),
            [-Vec3::Z, Vec3::Y, Vec3::X],
        ),
        (
            Vec3::new(0.0, 0.0, 10.0),
            45.0,
            Vec3::new(0.0, 10.0 * h, 10.0 * h),
            [Vec3::X, Vec3::new(0.0, h, -h), Vec3::new(0.0, h, h)],
        ),
    ];
    for (eye, plunge, expected_eye, [right, up, back]) in cases {
        let what = {
            let plunge = decimal(plunge.to_string());
            say!(
                "s7-the-camera-at-looking-at-the",
                vec_eye = vec(eye),
                vec = vec(Vec3::Y),
                plunge = plunge
            )
        };
        let Some((
            gave_eye,
            Orientation::Aimed {
                right: r,
                up: u,
                back: b,
            },
        )) = aim(eye, Vec3::ZERO, Vec3::Y, plunge)
        else {
            return Err(say!("s7-gave-no-aimed-orientation", what = what));
        };
        close_vec(
            &say!("s7-the-eye", what = what),
            gave_eye,
            expected_eye,
            1e-4,
        )?;
        close_vec(
            &say!("s7-right-forward-x-up-normalised-the", what = what),
            r,
            right,
            1e-5,
        )?;
        close_vec(&say!("s7-up", what = what), u, up, 1e-5)?;
        close_vec(&say!("s7-back", what = what), b, back, 1e-5)?;
    }
    let down = aim(Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, Vec3::Y, 0.0);
    ensure(down.is_none(), || {
        say!(
            "s7-the-camera-at-looking-straight-down",
            vec_new = vec(Vec3::new(0.0, 10.0, 0.0)),
            vec_eye = down.map_or(say!("s7-none"), |(eye, _)| say!(
                "s7-a-camera-at",
                vec_eye = vec(eye)
            ))
        )
    })?;
    generated::aim(aim)
}
