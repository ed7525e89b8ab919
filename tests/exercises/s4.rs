//! Session 4: the light's cone and its density, the lens's disk, the thin lens.

use raycourse::camera::ThinLens;
use raycourse::camera::lens::sample_disk;
use raycourse::lights::Cone;
use raycourse::maths::{PI, Real, Vec3, pixel_rng};

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, close, close_vec, ensure, grid_mean, num, vec};
use crate::s3::mean_of;
use crate::say;
use crate::words::separator;

/// Session 4's exercises, in the book's order.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "s4.1",
        name: "s4_1_cone_sample",
        shown_by: "light-sampling",
        needs: &[],
        check: cone_sample,
        french: [
            "une direction dans le cône de la source",
            "séance 4, «\u{a0}Échantillonnage de la lumière\u{a0}»",
        ],
    },
    Exercise {
        id: "s4.2",
        name: "s4_2_cone_pdf",
        shown_by: "light-sampling",
        needs: &[],
        check: cone_pdf,
        french: [
            "la densité du cône",
            "séance 4, «\u{a0}Échantillonnage de la lumière\u{a0}»",
        ],
    },
    Exercise {
        id: "s4.3",
        name: "s4_3_sample_disk",
        shown_by: "depth-of-field",
        needs: &[],
        check: disk,
        french: [
            "un point de la lentille",
            "séance 4, «\u{a0}Profondeur de champ\u{a0}»",
        ],
    },
    Exercise {
        id: "s4.4",
        name: "s4_4_thin_lens_refocus",
        shown_by: "depth-of-field",
        needs: &["s4.3"],
        check: thin_lens,
        french: [
            "la lentille mince",
            "séance 4, «\u{a0}Profondeur de champ\u{a0}»",
        ],
    },
];

/// The grid used for the samplers' averages: 64 x 64 points.
const GRID: u32 = 64;

/// A light seen under 30 degrees: `sin^2(theta_max) = 1/4`, `cos(theta_max) =
/// 0.8660`. Uniform per solid angle, `cos(theta)` is uniform on
/// `[cos(theta_max), 1]`, so its mean is `(1 + 0.8660) / 2 = 0.9330`; the azimuth
/// is uniform, so `E[x] = E[y] = 0`. Every direction is a unit vector inside the
/// cone.
fn cone_sample() -> Outcome {
    let cone = Cone::from_sin2(0.25);
    let mut wrong: Option<(Real, Real, Vec3)> = None;
    let [z, x, y] = grid_mean(GRID, |u1, u2| {
        let w = cone.sample(u1, u2);
        if w.z < cone.cos_max - 1e-5 || (w.length() - 1.0).abs() > 1e-4 {
            wrong.get_or_insert((u1, u2, w));
        }
        [w.z, w.x, w.y]
    });
    if let Some((u1, u2, w)) = wrong {
        let (u1, u2, s) = (num(u1), num(u2), separator());
        return Err(say!(
            "the cone of half-angle 30 degrees around +z, (u1, u2) = ({u1}, {u2}): gave {}, expected a unit vector with z >= cos(30) = 0.866",
            "le cône de demi-angle 30 degrés autour de +z, (u1{s}u2) = ({u1}{s}{u2})\u{a0}: obtenu {}, attendu un vecteur unitaire avec z >= cos(30) = 0,866",
            vec(w)
        ));
    }
    close(
        &say!(
            "the cone of half-angle 30 degrees: the mean of cos(theta)",
            "le cône de demi-angle 30 degrés\u{a0}: la moyenne de cos(theta)"
        ),
        z,
        0.9330,
        0.002,
    )
    .map_err(|e| {
        say!(
            "{e}: uniform over the cone's solid angle, cos(theta) is uniform between cos(theta_max) and 1 (not theta between 0 and theta_max)",
            "{e}\u{a0}: uniformes sur l'angle solide du cône, les directions ont un cos(theta) uniforme entre cos(theta_max) et 1 (et non un theta uniforme entre 0 et theta_max)"
        )
    })?;
    close(&mean_of("x"), x, 0.0, 0.005)?;
    close(&mean_of("y"), y, 0.0, 0.005)?;
    generated::cone_sample(Cone::sample)
}

/// One over the cone's solid angle `2 pi (1 - cos(theta_max))` inside it:
/// `1 / (2 pi * 0.1340) = 1.1879` for the 30-degree cone; 0 outside.
fn cone_pdf() -> Outcome {
    let cone = Cone::from_sin2(0.25);
    let inside = 1.0 / (2.0 * PI * (1.0 - (0.75 as Real).sqrt()));
    let at = |cos: Real| {
        let cos = num(cos);
        say!(
            "the density of the 30-degree cone at cos(theta) = {cos}",
            "la densité du cône de 30 degrés en cos(theta) = {cos}"
        )
    };
    close(&at(0.95), cone.pdf(0.95), inside, 1e-3)?;
    close(&at(1.0), cone.pdf(1.0), inside, 1e-3)?;
    close(
        &(at(0.5) + &say!(", outside it", ", hors du cône")),
        cone.pdf(0.5),
        0.0,
        1e-9,
    )?;
    generated::cone_pdf(Cone::pdf)
}

/// Uniform on the unit disk: inside it, `E[x] = E[y] = 0`, `E[r^2] = 1/2`, and a
/// quarter of the points within `r = 1/2`.
fn disk() -> Outcome {
    let mut outside: Option<(Real, Real)> = None;
    let [x, y, r2, near] = grid_mean(GRID, |u1, u2| {
        let (x, y) = sample_disk(u1, u2);
        if x * x + y * y > 1.0 + 1e-6 {
            outside.get_or_insert((x, y));
        }
        let r2 = x * x + y * y;
        [x, y, r2, if r2 <= 0.25 { 1.0 } else { 0.0 }]
    });
    if let Some((x, y)) = outside {
        let (x, y, s) = (num(x), num(y), separator());
        return Err(say!(
            "gave the point ({x}, {y}), outside the unit disk",
            "donne le point ({x}{s}{y}), hors du disque unité"
        ));
    }
    close(&mean_of("x"), x, 0.0, 0.01)?;
    close(&mean_of("y"), y, 0.0, 0.01)?;
    close(&mean_of("r^2"), r2, 0.5, 0.01).map_err(|e| {
        if (r2 - 1.0 / 3.0).abs() > 0.02 {
            return e;
        }
        say!(
            "{e}; with r = xi the points crowd the centre (1/3): uniform over the area needs r = sqrt(xi)",
            "{e}\u{a0}; avec r = xi, les points se massent au centre (1/3)\u{a0}: une répartition uniforme sur l'aire demande r = sqrt(xi)"
        )
    })?;
    close(
        &say!(
            "the share of points within r = 1/2",
            "la part des points à une distance r <= 1/2 du centre"
        ),
        near,
        0.25,
        0.01,
    )?;
    generated::disk(sample_disk)
}

/// A lens of radius 0.5 focused 10 in front of the eye: the pinhole ray along
/// `(1, 2, -4)` meets the focus plane at `(2.5, 5, -10)`, and every ray through the
/// lens starts on the lens (`z = 0`, within 0.5 of the eye) and passes through
/// that point; the starts cover the lens, `E[x^2 + y^2] = 0.5^2 / 2`.
fn thin_lens() -> Outcome {
    let lens = ThinLens {
        aperture: 0.5,
        focus: 10.0,
    };
    let focus = Vec3::new(2.5, 5.0, -10.0);
    let draws = 4000;
    let mut spread = 0.0;
    for k in 0..draws {
        let mut rng = pixel_rng(7, k);
        let (origin, direction) = lens.refocus(Vec3::ZERO, Vec3::new(1.0, 2.0, -4.0), &mut rng);
        ensure(
            origin.z.abs() < 1e-6 && origin.truncate().length() <= 0.5 + 1e-6,
            || {
                say!(
                    "a ray through the lens of radius 0.5 starts at {}: expected a point of the lens (z = 0, within 0.5 of the eye)",
                    "un rayon à travers la lentille de rayon 0,5 part de {}\u{a0}: attendu un point de la lentille (z = 0, à moins de 0,5 de l'œil)",
                    vec(origin)
                )
            },
        )?;
        ensure(direction.z < 0.0, || {
            say!(
                "the ray from {} along {} never reaches the focus plane z = -10: it must head from its point of the lens towards (2.5, 5, -10), where the pinhole ray meets that plane",
                "le rayon issu de {} selon {} n'atteint jamais le plan de mise au point z = -10\u{a0}: il doit aller de son point de la lentille vers (2,5\u{a0}; 5\u{a0}; -10), où le rayon du sténopé rencontre ce plan",
                vec(origin),
                vec(direction)
            )
        })?;
        let s = (focus.z - origin.z) / direction.z;
        close_vec(
            &say!(
                "the ray from {} along {}, where it crosses the focus plane z = -10 (a plane at the focus distance along the view, not a sphere around the eye: the pinhole direction is scaled so that its z is -focus)",
                "le rayon issu de {} selon {}, là où il traverse le plan de mise au point z = -10 (un plan à la distance de mise au point le long de la visée, non une sphère autour de l'œil\u{a0}: la direction du sténopé est mise à l'échelle pour que son z vaille -focus)",
                vec(origin),
                vec(direction)
            ),
            origin + s * direction,
            focus,
            1e-3,
        )?;
        spread += origin.truncate().length_squared();
    }
    close(
        &say!(
            "the mean of x^2 + y^2 over the starts on the lens",
            "la moyenne de x^2 + y^2 sur les points de départ de la lentille"
        ),
        spread / draws as Real,
        0.125,
        0.01,
    )?;
    generated::thin_lens(ThinLens::refocus)
}
