//! Direct light: the light source's light, reflected by a diffuse surface.

use crate::geometry::Hit;
use crate::integrator::Tracer;
use crate::lights::{Light, PointLight};
use crate::maths::Colour;

impl Tracer<'_> {
    // ANCHOR: direct_light
    /// Light from the light source reflected by a diffuse surface of `albedo`: a
    /// point light by Lambert's law, and from session 4 a sphere light.
    pub fn direct_light(&mut self, hit: &Hit, albedo: Colour) -> Colour {
        match self.scene.light {
            None => Colour::ZERO,
            Some(Light::Point(light)) => self.point_light(&light, hit, albedo),
            #[cfg(feature = "s4")]
            Some(Light::Sphere(light)) => self.sphere_light(&light, hit, albedo),
        }
    }
    // ANCHOR_END: direct_light

    // ANCHOR: point_light
    /// Light from a point light reflected by a diffuse surface: Lambert's law, and
    /// from session 2 zero where a shadow ray finds an object between the point and
    /// the light.
    pub fn point_light(&mut self, light: &PointLight, hit: &Hit, albedo: Colour) -> Colour {
        #[cfg(feature = "s2")]
        if self.scene.settings.shadows && self.in_shadow(hit, light) {
            return Colour::ZERO;
        }
        light.lambert(hit.point, hit.normal, albedo)
    }
    // ANCHOR_END: point_light
}
