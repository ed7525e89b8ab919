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
    },
    Exercise {
        id: "s4.2",
        name: "s4_2_cone_pdf",
        shown_by: "light-sampling",
        needs: &[],
        check: cone_pdf,
    },
    Exercise {
        id: "s4.3",
        name: "s4_3_sample_disk",
        shown_by: "depth-of-field",
        needs: &[],
        check: disk,
    },
    Exercise {
        id: "s4.4",
        name: "s4_4_thin_lens_refocus",
        shown_by: "depth-of-field",
        needs: &["s4.3"],
        check: thin_lens,
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
            "s4-the-cone-of-half-angle-30",
            vec_w = vec(w),
            u1 = u1,
            u2 = u2,
            s = s
        ));
    }
    close(&say!("s4-the-cone-of-half-angle-30-2"), z, 0.9330, 0.002)
        .map_err(|e| say!("s4-uniform-over-the-cone-s-solid", e = e))?;
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
        say!("s4-the-density-of-the-30-degree", cos = cos)
    };
    close(&at(0.95), cone.pdf(0.95), inside, 1e-3)?;
    close(&at(1.0), cone.pdf(1.0), inside, 1e-3)?;
    close(
        &(at(0.5) + &say!("s4-outside-it")),
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
            "s4-gave-the-point-outside-the-unit",
            x = x,
            y = y,
            s = s
        ));
    }
    close(&mean_of("x"), x, 0.0, 0.01)?;
    close(&mean_of("y"), y, 0.0, 0.01)?;
    close(&mean_of("r^2"), r2, 0.5, 0.01).map_err(|e| {
        if (r2 - 1.0 / 3.0).abs() > 0.02 {
            return e;
        }
        say!("s4-with-r-xi-the-points-crowd", e = e)
    })?;
    close(&say!("s4-the-share-of-points-within-r"), near, 0.25, 0.01)?;
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
            || say!("s4-a-ray-through-the-lens-of", vec_origin = vec(origin)),
        )?;
        ensure(direction.z < 0.0, || {
            say!(
                "s4-the-ray-from-along-never-reaches",
                vec_origin = vec(origin),
                vec_direction = vec(direction)
            )
        })?;
        let s = (focus.z - origin.z) / direction.z;
        close_vec(
            &say!(
                "s4-the-ray-from-along-where-it",
                vec_origin = vec(origin),
                vec_direction = vec(direction)
            ),
            origin + s * direction,
            focus,
            1e-3,
        )?;
        spread += origin.truncate().length_squared();
    }
    close(
        &say!("s4-the-mean-of-x-2-y"),
        spread / draws as Real,
        0.125,
        0.01,
    )?;
    generated::thin_lens(ThinLens::refocus)
}
