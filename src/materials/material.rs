//! What a surface does with light.

use crate::maths::numbers::Colour;

/// The material of a surface. Each session adds the kinds it teaches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// A Lambertian (matte) surface that reflects the fraction `albedo` of the light
    /// it receives, equally in every direction: its BRDF is `albedo / pi`.
    Diffuse {
        /// Reflectance in red, green and blue, each in [0, 1].
        albedo: Colour,
    },
    /// A perfect mirror: every ray leaves in the reflected direction.
    #[cfg(feature = "s2")]
    Mirror,
    /// A transparent dielectric such as glass, refracting by Snell-Descartes.
    #[cfg(feature = "s2")]
    Glass {
        /// Refractive index inside the object (the outside is air, index 1).
        index: crate::maths::numbers::Real,
    },
    /// Glass that also reflects part of the light, as the Fresnel equations say.
    #[cfg(feature = "s4")]
    FresnelGlass {
        /// Refractive index inside the object.
        index: crate::maths::numbers::Real,
    },
}
