//! The point light of the course and Lambert's law.

use crate::maths::{Colour, PI, Real, Vec3};

// ANCHOR: light
/// The light source of a scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    /// A point: hard shadows, direct lighting by Lambert's law.
    Point(PointLight),
    /// A glowing sphere: soft shadows.
    #[cfg(feature = "s4")]
    Sphere(crate::lights::SphereLight),
}

/// A point light radiating its power `intensity` equally in every direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Where the light is.
    pub position: Vec3,
    /// Total emitted power `Phi` (the course calls it the intensity `I`), in the
    /// course's units, in which a radiance of 255 shows as full white.
    pub intensity: Real,
}
// ANCHOR_END: light

impl PointLight {
    // ANCHOR: lambert
    /// Radiance that a Lambertian surface of `albedo` at `point`, with unit `normal`,
    /// sends towards the eye under this light, shadows aside:
    /// `L = Phi / (4 pi r^2) * max(0, N . l) * albedo / pi`,
    /// where `Phi` is the light's power (`intensity`), `r` the distance to the light
    /// and `l` the unit direction towards it. `Phi / (4 pi r^2)` is the power per unit
    /// area arriving at distance `r`, `N . l` spreads it over the tilted surface,
    /// `albedo / pi` is the BRDF.
    ///
    /// Exercise s1.4, Lambert shading with the light's falloff: book session 1, "Lambert shading".
    pub fn lambert(&self, point: Vec3, normal: Vec3, albedo: Colour) -> Colour {
        let to_light = self.position - point;
        let d2 = to_light.length_squared();
        let cos = normal.dot(to_light / d2.sqrt()).max(0.0);
        self.intensity / (4.0 * PI * d2) * cos * albedo / PI
    }
    // ANCHOR_END: lambert
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lambert_matches_the_formula_at_a_known_point() {
        let light = PointLight {
            position: Vec3::new(-10.0, 20.0, 40.0),
            intensity: 2e10,
        };
        let point = Vec3::new(0.0, 0.0, 10.0);
        let normal = Vec3::Z;
        let albedo = Colour::new(1.0, 0.5, 0.25);
        let l = light.lambert(point, normal, albedo);
        let d2: Real = 10.0 * 10.0 + 20.0 * 20.0 + 30.0 * 30.0;
        let cos = 30.0 / d2.sqrt();
        let expected = 2e10 / (4.0 * PI * d2) * cos / PI;
        assert!(
            (l.x - expected).abs() <= 1e-12 * expected,
            "{} vs {expected}",
            l.x
        );
        assert!((l.y - expected * 0.5).abs() <= 1e-12 * expected);
        assert!((l.z - expected * 0.25).abs() <= 1e-12 * expected);
    }

    #[test]
    fn a_surface_facing_away_gets_no_light() {
        let light = PointLight {
            position: Vec3::new(0.0, 10.0, 0.0),
            intensity: 1.0,
        };
        let l = light.lambert(Vec3::ZERO, -Vec3::Y, Colour::ONE);
        assert_eq!(l, Colour::ZERO);
    }

    #[test]
    fn unit_sphere_known_answer() {
        // A light of intensity 4 pi^2 at distance 1 straight above a surface of
        // albedo 1 gives radiance exactly 1.
        let light = PointLight {
            position: Vec3::Y,
            intensity: 4.0 * PI * PI,
        };
        let l = light.lambert(Vec3::ZERO, Vec3::Y, Colour::ONE);
        assert!((l - Colour::ONE).abs().max_element() < 1e-15);
    }
}
