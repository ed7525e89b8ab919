//! Beyond the course: the direct light of [paths followed at
//! once](crate::fast::paths_at_once), in two halves, so that the shadow rays of
//! four paths are traced together.
//!
//! [`Tracer::direct_light`] traces its shadow ray as soon as it has made it. Here the
//! first half makes the ray and the light it lets through ([`Direct`]); the second
//! ([`Direct::resolve`]) takes the nearest hit that the four-ray test found for it.
//! The two halves make the same computations as `direct_light`, in the same order:
//! the same light to the last bit. A point light's shadow ray asks whether anything
//! is closer than the light; a sphere light's sample (session 4: `sample_light`)
//! asks whether the first object it meets is the light.
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
    /// `lit` if the first object that `ray` meets is `object`, a sphere light (the
    /// light sample of `sample_light`, session 4).
    Seen {
        /// The ray, from the hit towards a point of the light.
        ray: Ray,
        /// The light's sphere.
        object: usize,
        /// The light that arrives if the ray meets the light first.
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
            Some(Light::Sphere(light)) => sphere(tracer, &light, hit, albedo),
        }
    }

    /// The shadow ray to trace, if any.
    pub fn ray(&self) -> Option<&Ray> {
        match self {
            Direct::Known(_) => None,
            Direct::Unblocked { ray, .. } | Direct::Seen { ray, .. } => Some(ray),
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
            Direct::Seen { object, lit, .. } => match nearest {
                Some((_, seen)) if seen == object => lit,
                _ => Colour::ZERO,
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

/// [`Tracer::sphere_light`](crate::integrator::Tracer::sphere_light) and
/// `sample_light`, first half.
#[cfg(feature = "s4")]
fn sphere(
    tracer: &mut Tracer,
    light: &crate::lights::SphereLight,
    hit: &Hit,
    albedo: Colour,
) -> Direct {
    use crate::maths::{PI, uniform_pair};
    if !tracer.scene.settings.light_sampling {
        return Direct::Known(Colour::ZERO);
    }
    let (u1, u2) = uniform_pair(&mut tracer.rng);
    let Some((direction, pdf)) = light.sample(hit.point, u1, u2) else {
        return Direct::Known(Colour::ZERO);
    };
    let cos = direction.dot(hit.normal);
    if cos <= 0.0 {
        return Direct::Known(Colour::ZERO);
    }
    tracer.rays += 1;
    Direct::Seen {
        ray: hit.spawn(direction),
        object: light.object,
        lit: light.emission * albedo / PI * cos / pdf,
    }
}
