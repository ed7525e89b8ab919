//! The probe's account of mirrors and glass (session 2): which way the ray went on.

use crate::geometry::{Hit, Ray};
use crate::inspect::path::Next;
use crate::materials::optics::{interface, refract};
use crate::maths::{Real, Vec3};
use crate::messages::said::Said;

/// A mirror reflects.
pub fn mirror(next: &mut Next) {
    next.kind = Said::new("probe-next-mirror");
}

/// Glass of `index` met by `ray` at `hit`, the path going on in `direction`:
/// refracted with `eta = n1 / n2`, or reflected past the critical angle. Returns
/// whether it was reflected.
pub fn glass(next: &mut Next, ray: &Ray, hit: &Hit, index: Real, direction: Vec3) -> bool {
    let (normal, eta) = interface(ray.direction, hit.normal, index);
    let reflected = direction.dot(normal) > 0.0;
    next.kind = match refract(ray.direction, normal, eta) {
        None => Said::new("probe-next-total-internal-reflection"),
        Some(_) if reflected => Said::new("probe-next-reflection"),
        Some(_) => Said::new("probe-next-refraction").with("eta", crate::maths::to_double(eta)),
    };
    reflected
}
