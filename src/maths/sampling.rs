//! Random directions and offsets for Monte Carlo integration, each sampler beside
//! its probability density (pdf), which the estimator divides by.

use crate::maths::{PI, Real, Vec3};

// ANCHOR: cosine
/// A direction in the hemisphere around `+z` with density proportional to
/// `cos(theta)`, from two uniform numbers in `[0, 1)`, as in the course:
/// `x = cos(2 pi xi1) sqrt(1 - xi2)`, `y = sin(2 pi xi1) sqrt(1 - xi2)`,
/// `z = sqrt(xi2)`, with `xi1`, `xi2` the two uniform numbers `u1`, `u2`.
///
/// Exercise s3.1, the cosine-weighted direction: book session 3, "Indirect lighting".
pub fn sample_cosine_hemisphere(u1: Real, u2: Real) -> Vec3 {
    let r = (1.0 - u2).sqrt();
    let phi = 2.0 * PI * u1;
    Vec3::new(phi.cos() * r, phi.sin() * r, u2.sqrt())
}

/// Density of [`sample_cosine_hemisphere`] per unit solid angle:
/// `cos(theta) / pi` above the surface, 0 below.
pub fn cosine_hemisphere_pdf(cos_theta: Real) -> Real {
    cos_theta.max(0.0) / PI
}
// ANCHOR_END: cosine

// ANCHOR: gaussian
/// Two independent normal numbers of standard deviation `sigma` from two uniform
/// numbers `xi1 = u1`, `xi2 = u2` in `[0, 1)` (Box-Muller): radius
/// `sigma sqrt(-2 ln(1 - xi1))`, angle `2 pi xi2`. `1 - xi1` lies in `(0, 1]`, so
/// the logarithm is never taken of 0.
///
/// Exercise s3.4, the Gaussian pixel filter: book session 3, "Antialiasing".
pub fn sample_gaussian(u1: Real, u2: Real, sigma: Real) -> (Real, Real) {
    let r = sigma * (-2.0 * (1.0 - u1).ln()).sqrt();
    let phi = 2.0 * PI * u2;
    (r * phi.cos(), r * phi.sin())
}

/// Density of [`sample_gaussian`] at `(x, y)`:
/// `exp(-(x^2 + y^2) / (2 sigma^2)) / (2 pi sigma^2)`.
pub fn gaussian_pdf(x: Real, y: Real, sigma: Real) -> Real {
    let s2 = sigma * sigma;
    (-(x * x + y * y) / (2.0 * s2)).exp() / (2.0 * PI * s2)
}
// ANCHOR_END: gaussian

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cosine_directions_are_unit_and_above_the_surface() {
        for (u1, u2) in [(0.0, 0.0), (0.3, 0.999_999), (0.7, 0.5), (0.999, 1e-12)] {
            let d = sample_cosine_hemisphere(u1, u2);
            assert!((d.length() - 1.0).abs() < 4.0 * Real::EPSILON);
            assert!(d.z >= 0.0);
        }
    }

    #[test]
    fn box_muller_never_takes_the_log_of_zero() {
        let (x, y) = sample_gaussian(0.0, 0.25, 1.0);
        assert_eq!((x, y), (0.0, 0.0));
        // The largest u1 below 1 gives the longest radius, sqrt(-2 ln(eps / 2)).
        let (x, y) = sample_gaussian(1.0 - Real::EPSILON / 2.0, 0.0, 1.0);
        let longest = (-2.0 * (Real::EPSILON / 2.0).ln()).sqrt();
        assert!(y == 0.0 && (x - longest).abs() < 1e-3 * longest, "{x}");
    }
}
