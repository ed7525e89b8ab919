//! The probe's account of glass that reflects (session 4): Fresnel's reflectance and
//! the choice it made.

use crate::geometry::{Hit, Ray};
use crate::inspect::path::Next;
use crate::inspect::specular::glass;
use crate::materials::fresnel::fresnel_reflectance;
use crate::materials::optics::{interface, refract};
use crate::maths::{Real, Vec3};
use crate::messages::said::Said;

/// Fresnel glass of `index`: as [`glass`], and, where the ray could refract,
/// Fresnel's reflectance `F` and whether the path took the reflected ray (with
/// probability `F`) or the refracted one (with probability `1 - F`).
pub fn fresnel_glass(next: &mut Next, ray: &Ray, hit: &Hit, index: Real, direction: Vec3) {
    let reflected = glass(next, ray, hit, index, direction);
    let (normal, eta) = interface(ray.direction, hit.normal, index);
    if refract(ray.direction, normal, eta).is_some() {
        next.fresnel = Some(fresnel_reflectance(-ray.direction.dot(normal), eta));
        next.kind = match reflected {
            true => Said::new("probe-next-fresnel-reflection"),
            false => {
                Said::new("probe-next-fresnel-refraction").with("eta", crate::maths::to_double(eta))
            }
        };
    }
}
