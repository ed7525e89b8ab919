//! Fresnel reflection: glass reflects part of the light and transmits the rest.

use crate::maths::Real;

// ANCHOR: fresnel
/// The fraction of unpolarised light reflected at a smooth dielectric boundary, for
/// the cosine `cos_i` of the angle of incidence and `eta = n1 / n2` (exact Fresnel
/// equations, averaging the two polarisations):
/// `r_s = (eta cos_i - cos_t) / (eta cos_i + cos_t)`,
/// `r_p = (cos_i - eta cos_t) / (cos_i + eta cos_t)`, `F = (r_s^2 + r_p^2) / 2`;
/// 1 past the critical angle.
pub fn fresnel_reflectance(cos_i: Real, eta: Real) -> Real {
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    (r_s * r_s + r_p * r_p) / 2.0
}
// ANCHOR_END: fresnel

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_reflectances() {
        // Normal incidence: ((n1 - n2) / (n1 + n2))^2 = 0.04 for glass.
        assert!((fresnel_reflectance(1.0, 1.0 / 1.5) - 0.04).abs() < 8.0 * Real::EPSILON);
        assert!((fresnel_reflectance(1.0, 1.5) - 0.04).abs() < 8.0 * Real::EPSILON);
        // Grazing incidence reflects everything.
        assert!((fresnel_reflectance(1e-9, 1.0 / 1.5) - 1.0).abs() < 1e-8);
        // Past the critical angle: total internal reflection.
        assert_eq!(fresnel_reflectance(0.5, 1.5), 1.0);
        // Index 1: no boundary, no reflection.
        assert!(fresnel_reflectance(0.3, 1.0) < 4.0 * Real::EPSILON * Real::EPSILON);
        // Brewster's angle, tan(theta) = n2 / n1: r_p vanishes, F = r_s^2 / 2.
        let theta = (1.5 as Real).atan();
        let f = fresnel_reflectance(theta.cos(), 1.0 / 1.5);
        let cos_t = (1.0 - (theta.sin() / 1.5).powi(2)).sqrt();
        let r_s = (theta.cos() - 1.5 * cos_t) / (theta.cos() + 1.5 * cos_t);
        assert!((f - r_s * r_s / 2.0).abs() < 8.0 * Real::EPSILON);
    }
}
