//! A spherical light: soft shadows, and the cone of directions under which a point
//! sees it, for direct lighting by sampling the light.

use crate::geometry::Sphere;
use crate::materials::Material;
use crate::maths::frame::Frame;
use crate::maths::{Colour, PI, Real, Vec3};

// ANCHOR: light_struct
/// A sphere that emits the same radiance from every point of its surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereLight {
    /// Its centre.
    pub centre: Vec3,
    /// Its radius.
    pub radius: Real,
    /// Radiance of its surface. For a light of total power `I`, `I / (4 pi^2 R^2)`:
    /// a sphere of area `4 pi R^2` emitting radiance `L` over each hemisphere sends
    /// out `pi L` per unit area.
    pub emission: Colour,
    /// Index of the sphere in the scene that is the light's body.
    pub object: usize,
}
// ANCHOR_END: light_struct

// ANCHOR: cone
/// The cone of directions around `+z` that meet a sphere seen under the half-angle
/// `theta_max`. It keeps `1 - cos(theta_max)` as well as the cosine: for a small or
/// distant light the cosine rounds to 1 and `1 - cos` computed from it would be 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    /// `cos(theta_max)`: directions with a larger cosine are inside the cone.
    pub cos_max: Real,
    /// `1 - cos(theta_max)`, computed as `sin^2 / (1 + cos)` without cancellation.
    pub one_minus_cos_max: Real,
}

impl Cone {
    /// The cone whose half-angle has `sin^2(theta_max) = sin2` (at most 1).
    pub fn from_sin2(sin2: Real) -> Self {
        let cos_max = (1.0 - sin2).sqrt();
        Self {
            cos_max,
            one_minus_cos_max: sin2 / (1.0 + cos_max),
        }
    }

    /// A direction in the cone, uniform per unit solid angle:
    /// `1 - cos(theta) = xi1 (1 - cos_max)`, `phi = 2 pi xi2` (`xi1 = u1`, `xi2 = u2`;
    /// `theta` measured from the cone's axis, towards the light), and
    /// `sin^2(theta) = (1 - cos)(1 + cos)`, again without cancellation.
    ///
    /// Exercise s4.1, a direction in the light's cone: book session 4, "Light sampling".
    pub fn sample(&self, u1: Real, u2: Real) -> Vec3 {
        let one_minus_cos = u1 * self.one_minus_cos_max;
        let sin_theta = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
        let phi = 2.0 * PI * u2;
        Vec3::new(
            phi.cos() * sin_theta,
            phi.sin() * sin_theta,
            1.0 - one_minus_cos,
        )
    }

    /// Density of [`Cone::sample`] per unit solid angle: one over the cone's solid
    /// angle, `1 / (2 pi (1 - cos_max))`, inside the cone.
    ///
    /// Exercise s4.2, the cone's density: book session 4, "Light sampling".
    pub fn pdf(&self, cos_theta: Real) -> Real {
        if cos_theta >= self.cos_max {
            1.0 / (2.0 * PI * self.one_minus_cos_max)
        } else {
            0.0
        }
    }
}
// ANCHOR_END: cone

impl SphereLight {
    // ANCHOR: sphere_light
    /// A light of total power `intensity` at `centre`, whose body will be the scene's
    /// sphere number `object`.
    pub fn new(centre: Vec3, radius: Real, intensity: Real, object: usize) -> Self {
        Self {
            centre,
            radius,
            emission: Colour::splat(intensity / (4.0 * PI * PI * radius * radius)),
            object,
        }
    }

    /// The sphere that is the light's visible body: it glows, and reflects nothing.
    pub fn body(&self) -> Sphere {
        Sphere {
            centre: self.centre,
            radius: self.radius,
            material: Material::Diffuse {
                albedo: Colour::ZERO,
            },
            emission: self.emission,
        }
    }
    // ANCHOR_END: sphere_light

    // ANCHOR: light_cone
    /// The cone under which the light is seen from `point`, whose half-angle has
    /// `sin^2(theta_max) = R^2 / r^2`, with `r` the distance from `point` to the
    /// light's centre, or `None` from inside the light.
    pub fn cone(&self, point: Vec3) -> Option<Cone> {
        let r2 = (self.centre - point).length_squared();
        let sin2 = self.radius * self.radius / r2;
        (sin2 < 1.0).then(|| Cone::from_sin2(sin2))
    }

    /// A direction from `point` towards the light, uniform over the cone of
    /// directions that meet it, with its density per unit solid angle.
    pub fn sample(&self, point: Vec3, u1: Real, u2: Real) -> Option<(Vec3, Real)> {
        let cone = self.cone(point)?;
        let frame = Frame::new((self.centre - point).normalize());
        let local = cone.sample(u1, u2);
        Some((frame.to_world(local), cone.pdf(local.z)))
    }
    // ANCHOR_END: light_cone
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sampled_directions_meet_the_light() {
        let light = SphereLight {
            centre: Vec3::new(-10.0, 20.0, 40.0),
            radius: 5.0,
            emission: Colour::ONE,
            object: 0,
        };
        let point = Vec3::new(3.0, -10.0, 1.0);
        for k in 0..1000 {
            let u = (k as Real + 0.5) / 1000.0;
            let (d, pdf) = light.sample(point, u, (u * 7.3).fract()).unwrap();
            let f = point - light.centre;
            let h = f.dot(d);
            let miss2 = f.length_squared() - h * h;
            assert!(miss2 <= 25.0 * (1.0 + 1e-12), "the ray meets the sphere");
            assert!(pdf > 0.0);
        }
        assert!(light.cone(light.centre + Vec3::X).is_none());
    }

    #[test]
    fn small_far_light_matches_a_point_light() {
        // Le (albedo/pi) cos / pdf integrates to I / (4 pi d^2) cos albedo / pi as
        // R -> 0: the solid angle 1/pdf tends to pi R^2 / d^2.
        for (r, d) in [(1e-2, 50.0), (1.0, 1e9), (1e-6, 1e3)] {
            let light = SphereLight {
                centre: Vec3::new(0.0, d, 0.0),
                radius: r,
                emission: Colour::ONE,
                object: 0,
            };
            let cone = light.cone(Vec3::ZERO).unwrap();
            let solid_angle = 1.0 / cone.pdf(1.0);
            let expected = PI * r * r / (d * d);
            let relative = (solid_angle - expected).abs() / expected;
            assert!(relative < 1e-4, "R = {r}, d = {d}: {relative}");
        }
    }
}
