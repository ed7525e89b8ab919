//! The laws of reflection and refraction: the directions a ray leaves a mirror or
//! glass by.

use crate::maths::{Real, Vec3};

// ANCHOR: reflect
/// The mirror direction of `incident` about the unit `normal`: `d - 2 (d . n) n`.
/// The angle to the normal is kept and the tangential part is unchanged.
///
/// Exercise s2.4, the mirror direction: book session 2, "Mirrors".
pub fn reflect(incident: Vec3, normal: Vec3) -> Vec3 {
    incident - 2.0 * incident.dot(normal) * normal
}
// ANCHOR_END: reflect

// ANCHOR: refract
/// The refracted direction `d_t` of the unit `incident` direction `d` through a
/// surface with unit `normal` `N` on the incident side, where `eta = n1 / n2` is the
/// ratio of the indices before and after. Snell-Descartes,
/// `n1 sin(theta_1) = n2 sin(theta_2)`, scales the part of `d` parallel to the
/// surface, `d_par = d - (d . N) N`, by `eta`; the part along the normal is
/// `-sqrt(1 - eta^2 |d_par|^2) N`. `sin^2(theta_1)` is taken as `|d_par|^2` rather
/// than `1 - cos^2(theta_1)`, which cancels near normal incidence. `None` when the
/// square root's argument is negative: total internal reflection.
///
/// Exercise s2.5, refraction and total internal reflection: book session 2, "Glass".
pub fn refract(incident: Vec3, normal: Vec3, eta: Real) -> Option<Vec3> {
    let parallel = incident - incident.dot(normal) * normal;
    let sin2_t = eta * eta * parallel.length_squared();
    if sin2_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(eta * parallel - cos_t * normal)
}
// ANCHOR_END: refract

// ANCHOR: interface
/// The boundary of an object of refractive `index` in air, as the ray meeting it
/// along `direction` sees it: the normal on the ray's side, and `eta = n1 / n2`,
/// `1 / index` entering (air to glass) or `index` leaving (glass to air).
pub fn interface(direction: Vec3, outward_normal: Vec3, index: Real) -> (Vec3, Real) {
    if direction.dot(outward_normal) < 0.0 {
        (outward_normal, 1.0 / index)
    } else {
        (-outward_normal, index)
    }
}
// ANCHOR_END: interface

#[cfg(test)]
mod tests {
    use super::*;

    fn sin_to(v: Vec3, n: Vec3) -> Real {
        v.normalize().cross(n).length()
    }

    #[test]
    fn reflection_keeps_the_angle() {
        let n = Vec3::Y;
        for angle in [0.0 as Real, 0.1, 0.7, 1.2, 1.5] {
            let d = Vec3::new(angle.sin(), -angle.cos(), 0.0);
            let r = reflect(d, n);
            assert!((r.dot(n) - angle.cos()).abs() < 1e-15);
            assert!((r.x - d.x).abs() < 1e-15, "tangential part kept");
            assert!((r.length() - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn refraction_obeys_snell() {
        let n = Vec3::Y;
        for (n1, n2) in [(1.0, 1.5), (1.5, 1.0), (1.0, 2.4), (1.33, 1.0)] {
            for angle in [0.0 as Real, 0.2, 0.5, 0.6] {
                let d = Vec3::new(angle.sin(), -angle.cos(), 0.0);
                let t = refract(d, n, n1 / n2).expect("below the critical angle");
                assert!((t.length() - 1.0).abs() < 64.0 * Real::EPSILON);
                assert!(t.dot(n) < 0.0, "the ray crosses the surface");
                let lhs = n1 * sin_to(d, n);
                let rhs = n2 * sin_to(t, n);
                assert!(
                    (lhs - rhs).abs() < 64.0 * Real::EPSILON,
                    "{n1} sin theta_1 = {lhs}, {n2} sin theta_2 = {rhs}"
                );
            }
        }
    }

    #[test]
    fn total_internal_reflection_past_the_critical_angle() {
        let n = Vec3::Y;
        let index: Real = 1.5;
        let critical = (1.0 / index).asin();
        let below = critical - 1e-6;
        let above = critical + 1e-6;
        let d = |a: Real| Vec3::new(a.sin(), -a.cos(), 0.0);
        assert!(refract(d(below), n, index).is_some());
        assert!(refract(d(above), n, index).is_none());
        let grazing = refract(d(below), n, index).unwrap();
        assert!(
            grazing.dot(n).abs() < 1e-2,
            "leaves nearly along the surface"
        );
    }
}
