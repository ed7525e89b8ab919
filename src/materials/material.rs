//! What a surface does with light.

use serde::Deserialize;

use crate::maths::Colour;

// ANCHOR: material
/// The material of a surface. Each session adds the kinds it teaches. A scene file
/// writes one as `{ diffuse = [r, g, b] }`, `"mirror"`, `{ glass = 1.5 }` or
/// `{ fresnel-glass = 1.5 }`.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Material {
    /// A Lambertian (matte) surface that reflects the fraction `albedo` of the light
    /// it receives, equally in every direction: its BRDF is `albedo / pi`.
    #[serde(deserialize_with = "crate::maths::values::albedo")]
    Diffuse {
        /// Reflectance in red, green and blue, each in [0, 1].
        albedo: Colour,
    },
    /// A perfect mirror: every ray leaves in the reflected direction.
    #[cfg(feature = "s2")]
    Mirror,
    /// A transparent dielectric such as glass, refracting by Snell-Descartes.
    #[cfg(feature = "s2")]
    #[serde(deserialize_with = "crate::maths::values::positive")]
    Glass {
        /// Refractive index inside the object (the outside is air, index 1).
        index: crate::maths::Real,
    },
    /// Glass that also reflects part of the light, as the Fresnel equations say.
    #[cfg(feature = "s4")]
    #[serde(deserialize_with = "crate::maths::values::positive")]
    FresnelGlass {
        /// Refractive index inside the object.
        index: crate::maths::Real,
    },
}
// ANCHOR_END: material
