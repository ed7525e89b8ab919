//! Beyond the course: the direct light of [paths followed at
//! once](crate::render::paths_at_once), in two halves, so that the shadow rays of
//! four paths are traced together.
//!
//! [`Tracer::direct_light`] traces its shadow ray as soon as it has made it. Here the
//! first half makes the ray and the light it lets through ([`Direct`]); the second
//! ([`Direct::resolve`]) takes the nearest hit that the four-ray test found for it.
//! The two halves make the same computations as `direct_light`, in the same order:
//! the same light to the last bit. Only the point light's shadow rays are split so;
//! a sphere light (session 4) is sampled whole by the course's own `sphere_light`.
//!
//! [`Tracer::direct_light`]: crate::integrator::Tracer::direct_light

use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::lights::{Light, PointLight};
use crate::maths::{Colour, Real};

/// The direct light at a hit, or what it waits for: a shadow ray's nearest hit.
#[derive(Clone, Copy, Debug)]
pub enum Direct {
    /// Known without a shadow ray.
    Known(Colour),
    /// `lit` unless the shadow `ray` meets something closer than `distance` (a point
    /// light: [`Tracer::in_shadow`](crate::integrator::Tracer::in_shadow)).
    Unblocked {
        /// The shadow ray, from the hit towards the light.
        ray: Ray,
        /// The distance from the ray's origin to the light.
        distance: Real,
        /// The light that arrives if nothing is in the way.
        lit: Colour,
    },
}

impl Direct {
    /// The first half of [`Tracer::direct_light`](crate::integrator::Tracer::direct_light)
    /// at `hit` (facing the ray) of a surface of `albedo`: the shadow ray it needs,
    /// counted in `tracer.rays`, and the light it would let through.
    pub fn at(tracer: &mut Tracer, hit: &Hit, albedo: Colour) -> Direct {
        match tracer.scene.light {
            None => Direct::Known(Colour::ZERO),
            Some(Light::Point(light)) => point(tracer, &light, hit, albedo),
            #[cfg(feature = "s4")]
            Some(Light::Sphere(light)) => Direct::Known(tracer.sphere_light(&light, hit, albedo)),
        }
    }

    /// The shadow ray to trace, if any.
    pub fn ray(&self) -> Option<&Ray> {
        match self {
            Direct::Known(_) => None,
            Direct::Unblocked { ray, .. } => Some(ray),
        }
    }

    /// The direct light, given the nearest hit of the shadow ray (distance and
    /// object), which is ignored where there is no shadow ray.
    pub fn resolve(&self, nearest: Option<(Real, usize)>) -> Colour {
        match *self {
            Direct::Known(light) => light,
            Direct::Unblocked { distance, lit, .. } => match nearest {
                Some((t, _)) if t < distance => Colour::ZERO,
                _ => lit,
            },
        }
    }
}

/// [`Tracer::point_light`](crate::integrator::Tracer::point_light), first half.
fn point(tracer: &mut Tracer, light: &PointLight, hit: &Hit, albedo: Colour) -> Direct {
    let lit = light.lambert(hit.point, hit.normal, albedo);
    if !tracer.scene.settings.shadows {
        return Direct::Known(lit);
    }
    let (ray, distance) = hit.spawn_towards(light.position);
    tracer.rays += 1;
    Direct::Unblocked { ray, distance, lit }
}
