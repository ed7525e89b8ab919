//! The probe's account of mirrors and glass (session 2): which way the ray went on.

use crate::geometry::{Hit, Ray};
use crate::inspect::path::Next;
use crate::materials::optics::{interface, refract};
use crate::maths::{Real, Vec3};

/// A mirror reflects.
pub fn mirror(next: &mut Next) {
    next.kind = "mirror reflection".into();
}

/// Glass of `index` met by `ray` at `hit`, the path going on in `direction`:
/// refracted with `eta = n1 / n2`, or reflected past the critical angle. Returns
/// whether it was reflected.
pub fn glass(next: &mut Next, ray: &Ray, hit: &Hit, index: Real, direction: Vec3) -> bool {
    let (normal, eta) = interface(ray.direction, hit.normal, index);
    let reflected = direction.dot(normal) > 0.0;
    next.kind = match refract(ray.direction, normal, eta) {
        None => "total internal reflection: past the critical angle".into(),
        Some(_) if reflected => "reflection".into(),
        Some(_) => format!("refraction, eta = n1 / n2 = {eta:.4}"),
    };
    reflected
}
