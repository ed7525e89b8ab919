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
        french: [
            "la lecture de la texture",
            "séance 7, «\u{a0}Textures\u{a0}»",
        ],
    },
    Exercise {
        id: "s7.2",
        name: "s7_2_aim",
        shown_by: "camera",
        needs: &[],
        check: orientation,
        french: [
            "l'orientation de la caméra",
            "séance 7, «\u{a0}Le déplacement de la caméra\u{a0}»",
        ],
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
            [
                "the top-left texel's centre",
                "le centre du texel en haut à gauche",
            ],
        ),
        (
            Filter::Nearest,
            [0.75, 0.25],
            Colour::ONE,
            [
                "the bottom-right texel's centre",
                "le centre du texel en bas à droite",
            ],
        ),
        (
            Filter::Nearest,
            [0.9, 0.9],
            GREEN,
            ["near the top-right corner", "près du coin en haut à droite"],
        ),
        (
            Filter::Nearest,
            [1.25, 0.75],
            RED,
            [
                "one texture to the right of the top-left centre",
                "une largeur de texture à droite du centre du texel en haut à gauche",
            ],
        ),
        (
            Filter::Nearest,
            [-0.25, 0.75],
            GREEN,
            [
                "a quarter of a texture left of its edge, which wraps to the top-right texel (the chapter's Euclidean remainder: -1 wraps to 1, where % gives -1)",
                "un quart de texture à gauche de son bord, qui revient au texel en haut à droite (le reste euclidien du chapitre\u{a0}: -1 revient à 1, là où % donne -1)",
            ],
        ),
        (
            Filter::Bilinear,
            [0.25, 0.75],
            RED,
            [
                "the top-left texel's centre",
                "le centre du texel en haut à gauche",
            ],
        ),
        (
            Filter::Bilinear,
            [0.5, 0.5],
            Colour::splat(0.5),
            ["the texture's centre", "le centre de la texture"],
        ),
        (
            Filter::Bilinear,
            [0.5, 0.75],
            Colour::new(0.5, 0.5, 0.0),
            [
                "between the two top texels",
                "entre les deux texels du haut",
            ],
        ),
    ];
    for (filter, uv, expected, [what, quoi]) in cases {
        let lookup = match filter {
            Filter::Nearest => "au plus proche",
            Filter::Bilinear => "bilinéaire",
        };
        let [u, v] = uv.map(|x| decimal(x.to_string()));
        let s = separator();
        close_vec(
            &say!(
                "a 2 x 2 texture (red, green / blue, white), {filter:?} lookup at (u, v) = ({u}, {v}), {what}",
                "une texture de 2 x 2 (rouge, vert / bleu, blanc), lecture {lookup} ({filter:?}) en (u{s}v) = ({u}{s}{v}), {quoi}"
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
                "the camera at {} looking at the origin, up {}, plunge {plunge} degrees",
                "la caméra en {} regardant l'origine, up {}, plongée de {plunge} degrés",
                vec(eye),
                vec(Vec3::Y)
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
            return Err(say!(
                "{what}: gave no aimed orientation",
                "{what}\u{a0}: ne donne aucune orientation visée (Orientation::Aimed)"
            ));
        };
        close_vec(
            &say!("{what}: the eye", "{what}\u{a0}: l'œil"),
            gave_eye,
            expected_eye,
            1e-4,
        )?;
        close_vec(
            &say!(
                "{what}: right = forward x up, normalised (the cross product's order gives its sign)",
                "{what}\u{a0}: right (vers la droite) = forward x up, normalisé (l'ordre du produit vectoriel en donne le signe)"
            ),
            r,
            right,
            1e-5,
        )?;
        close_vec(
            &say!("{what}: up", "{what}\u{a0}: up (vers le haut)"),
            u,
            up,
            1e-5,
        )?;
        close_vec(
            &say!("{what}: back", "{what}\u{a0}: back (vers l'arrière)"),
            b,
            back,
            1e-5,
        )?;
    }
    let down = aim(Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, Vec3::Y, 0.0);
    ensure(down.is_none(), || {
        say!(
            "the camera at {} looking straight down along up: gave {}, expected none (no right-hand direction)",
            "la caméra en {} regardant droit vers le bas, le long de up\u{a0}: obtenu {}, attendu aucune orientation (pas de direction vers la droite)",
            vec(Vec3::new(0.0, 10.0, 0.0)),
            down.map_or(say!("none", "aucune orientation"), |(eye, _)| say!(
                "a camera at {}",
                "une caméra en {}",
                vec(eye)
            ))
        )
    })?;
    generated::aim(aim)
}
