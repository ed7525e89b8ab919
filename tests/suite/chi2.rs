//! Chi-square goodness-of-fit tests of the samplers against their densities, as
//! Mitsuba 3's `chi2` test does it: about a million seeded samples are mapped to the
//! unit square and histogrammed on a grid; the expected count of each cell is the
//! sampler's pdf integrated over the cell; cells expecting fewer than 5 samples are
//! pooled; the statistic's p-value comes from the chi-square distribution, and the
//! sampler is rejected below 1%. Each test has a twin with a deliberately wrong pdf,
//! which must be rejected: a test that cannot fail proves nothing.

use raycourse::maths::{PI, PixelRng, Real, pixel_rng, uniform};
use statrs::distribution::{ChiSquared, ContinuousCDF};

const SAMPLES: usize = 1_000_000;
const ROWS: usize = 32;
const COLUMNS: usize = 64;
const SIGNIFICANCE: Real = 0.01;

/// Gauss-Legendre nodes and weights on [0, 1], 4 points (exact for degree 7).
const GAUSS: [(Real, Real); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_9, 0.326_072_577_431_273_1),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_1),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// The p-value of the hypothesis that `sample` (mapped to the unit square) has the
/// density `density` (per unit area of the square).
fn p_value(
    mut sample: impl FnMut(&mut PixelRng) -> (Real, Real),
    density: impl Fn(Real, Real) -> Real,
) -> Real {
    let mut observed = vec![0.0; ROWS * COLUMNS];
    let mut rng = pixel_rng(2024, 7);
    for _ in 0..SAMPLES {
        let (u, v) = sample(&mut rng);
        assert!(
            (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v),
            "({u}, {v})"
        );
        let row = ((u * ROWS as Real) as usize).min(ROWS - 1);
        let column = ((v * COLUMNS as Real) as usize).min(COLUMNS - 1);
        observed[row * COLUMNS + column] += 1.0;
    }
    let (du, dv) = (1.0 / ROWS as Real, 1.0 / COLUMNS as Real);
    let mut cells = Vec::new();
    let (mut pooled_observed, mut pooled_expected) = (0.0, 0.0);
    for row in 0..ROWS {
        for column in 0..COLUMNS {
            let mut integral = 0.0;
            for (x, wx) in GAUSS {
                for (y, wy) in GAUSS {
                    let u = (row as Real + x) * du;
                    let v = (column as Real + y) * dv;
                    integral += wx * wy * density(u, v);
                }
            }
            let expected = integral * du * dv * SAMPLES as Real;
            let seen = observed[row * COLUMNS + column];
            if expected < 5.0 {
                pooled_observed += seen;
                pooled_expected += expected;
            } else {
                cells.push((seen, expected));
            }
        }
    }
    if pooled_expected > 0.0 {
        cells.push((pooled_observed, pooled_expected));
    } else if pooled_observed > 0.0 {
        return 0.0; // samples where the density says none can be
    }
    let statistic: Real = cells.iter().map(|(o, e)| (o - e) * (o - e) / e).sum();
    let dof = (cells.len() - 1) as Real;
    ChiSquared::new(dof).unwrap().sf(statistic)
}

fn accepted(p: Real) -> bool {
    eprintln!("p-value {p:.3e}");
    p >= SIGNIFICANCE
}

/// `(u, v)` of a direction around `+z`: `u = cos(theta)` over `[0, 1]`,
/// `v = phi / 2 pi`. A solid angle `d omega = d(cos theta) d phi = 2 pi du dv`.
fn hemisphere_coordinates(x: Real, y: Real, z: Real) -> (Real, Real) {
    (z, y.atan2(x).rem_euclid(2.0 * PI) / (2.0 * PI))
}

mod cosine_hemisphere {
    use super::*;
    use raycourse::maths::sampling::{cosine_hemisphere_pdf, sample_cosine_hemisphere};

    fn sample(rng: &mut PixelRng) -> (Real, Real) {
        let d = sample_cosine_hemisphere(uniform(rng), uniform(rng));
        hemisphere_coordinates(d.x, d.y, d.z)
    }

    #[test]
    fn matches_its_pdf() {
        let p = p_value(sample, |u, _| cosine_hemisphere_pdf(u) * 2.0 * PI);
        assert!(accepted(p), "p = {p}");
    }

    #[test]
    fn rejects_the_uniform_pdf() {
        let p = p_value(sample, |_, _| 1.0 / (2.0 * PI) * 2.0 * PI);
        assert!(!accepted(p), "p = {p}");
    }
}

mod box_muller {
    use super::*;
    use raycourse::maths::sampling::{gaussian_pdf, sample_gaussian};

    const SIGMA: Real = 0.5;

    /// `u = 1 - exp(-r^2 / (2 sigma^2))`, `v = phi / 2 pi`: an area
    /// `dA = 2 pi sigma^2 / (1 - u) du dv`.
    fn sample(rng: &mut PixelRng) -> (Real, Real) {
        let (x, y) = sample_gaussian(uniform(rng), uniform(rng), SIGMA);
        let r2 = x * x + y * y;
        (
            -(-r2 / (2.0 * SIGMA * SIGMA)).exp_m1(),
            y.atan2(x).rem_euclid(2.0 * PI) / (2.0 * PI),
        )
    }

    fn density(pdf: impl Fn(Real, Real) -> Real) -> impl Fn(Real, Real) -> Real {
        move |u, v| {
            let r = (-2.0 * SIGMA * SIGMA * (-u).ln_1p()).sqrt();
            let phi = 2.0 * PI * v;
            pdf(r * phi.cos(), r * phi.sin()) * 2.0 * PI * SIGMA * SIGMA / (1.0 - u)
        }
    }

    #[test]
    fn matches_its_pdf() {
        let p = p_value(sample, density(|x, y| gaussian_pdf(x, y, SIGMA)));
        assert!(accepted(p), "p = {p}");
    }

    #[test]
    fn rejects_a_gaussian_of_the_wrong_width() {
        let p = p_value(sample, density(|x, y| gaussian_pdf(x, y, SIGMA * 1.05)));
        assert!(!accepted(p), "p = {p}");
    }
}

#[cfg(feature = "s4")]
mod disk {
    use super::*;
    use raycourse::camera::lens::{disk_pdf, sample_disk};

    /// `u = r^2`, `v = phi / 2 pi`: an area `dA = r dr dphi = pi du dv`.
    fn sample(rng: &mut PixelRng) -> (Real, Real) {
        let (x, y) = sample_disk(uniform(rng), uniform(rng));
        (x * x + y * y, y.atan2(x).rem_euclid(2.0 * PI) / (2.0 * PI))
    }

    fn density(pdf: impl Fn(Real, Real) -> Real) -> impl Fn(Real, Real) -> Real {
        move |u, v| {
            let (r, phi) = (u.sqrt(), 2.0 * PI * v);
            pdf(r * phi.cos(), r * phi.sin()) * PI
        }
    }

    #[test]
    fn matches_its_pdf() {
        let p = p_value(sample, density(disk_pdf));
        assert!(accepted(p), "p = {p}");
    }

    #[test]
    fn rejects_a_centre_weighted_pdf() {
        // Normalised, but denser at the centre: 2 (1 - r^2) / pi.
        let p = p_value(sample, density(|x, y| 2.0 * (1.0 - x * x - y * y) / PI));
        assert!(!accepted(p), "p = {p}");
    }
}

#[cfg(feature = "s4")]
mod light_cone {
    use super::*;
    use raycourse::lights::{Cone, SphereLight};
    use raycourse::maths::Vec3;
    use raycourse::maths::frame::Frame;

    /// A light close to the shaded point, so the cone is wide (half-angle 42 degrees).
    fn light() -> SphereLight {
        SphereLight::new(Vec3::new(1.0, 2.0, 3.0), 2.0, 1.0, 0)
    }

    const POINT: Vec3 = Vec3::new(1.0, 2.0, 0.0);

    /// The light's sampled direction in the frame around the light's axis:
    /// `u = (1 - cos(theta)) / (1 - cos_max)`, `v = phi / 2 pi`, so that
    /// `d omega = 2 pi (1 - cos_max) du dv`.
    fn sample(rng: &mut PixelRng) -> (Real, Real) {
        let light = light();
        let cone = light.cone(POINT).unwrap();
        let (direction, _) = light.sample(POINT, uniform(rng), uniform(rng)).unwrap();
        let local = Frame::new((light.centre - POINT).normalize()).to_local(direction);
        let (_, v) = hemisphere_coordinates(local.x, local.y, local.z);
        (
            ((1.0 - local.z) / cone.one_minus_cos_max).clamp(0.0, 1.0),
            v,
        )
    }

    fn density(pdf: impl Fn(&Cone, Real) -> Real) -> impl Fn(Real, Real) -> Real {
        let cone = light().cone(POINT).unwrap();
        move |u, _| {
            let cos_theta = 1.0 - u * cone.one_minus_cos_max;
            pdf(&cone, cos_theta) * 2.0 * PI * cone.one_minus_cos_max
        }
    }

    #[test]
    fn matches_its_pdf() {
        let p = p_value(sample, density(Cone::pdf));
        assert!(accepted(p), "p = {p}");
        let (_, pdf) = light().sample(POINT, 0.3, 0.6).unwrap();
        let cone = light().cone(POINT).unwrap();
        assert_eq!(pdf, cone.pdf(1.0), "sample() returns the cone pdf");
    }

    #[test]
    fn rejects_a_cosine_weighted_pdf() {
        // Normalised over the cone, but proportional to cos(theta).
        let wrong =
            |cone: &Cone, cos_theta: Real| cos_theta / (PI * (1.0 - cone.cos_max * cone.cos_max));
        let p = p_value(sample, density(wrong));
        assert!(!accepted(p), "p = {p}");
    }
}
