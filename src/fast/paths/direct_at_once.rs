//! The direct light of [paths followed at once](crate::fast::paths::paths_at_once), in two
//! halves, so that the shadow rays of four paths are traced together.
//!
//! [`Tracer::direct_light`] traces its shadow ray as soon as it has made it. Here the
//! first half makes the ray and the light it lets through ([`Direct::at`]), with the
//! course's own first halves: [`Tracer::shadow_ray`] for a point light,
//! `Tracer::light_sample` for a sphere light (session 4). The second,
//! [`Direct::resolve`], takes the nearest hit that the four-ray test found for the
//! ray and asks the course's question of it: is anything closer than the point light
//! ([`closer_than`]), is the sphere light the first object met.
//!
//! [`Tracer::direct_light`]: crate::integrator::Tracer::direct_light

use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::lights::Light;
use crate::maths::{Colour, Real};
use crate::scene::occlusion::closer_than;

/// The direct light at a hit, or what it waits for: a shadow ray's nearest hit.
#[derive(Clone, Copy, Debug)]
pub enum Direct {
    /// Known without a shadow ray.
    Known(Colour),
    /// `lit` if the shadow ray `ray` lets it through.
    Shadowed {
        /// The shadow ray, from the hit towards the light.
        ray: Ray,
        /// The light that arrives if nothing is in the way.
        lit: Colour,
        /// What the ray must not meet first: anything closer than the point light
        /// (the distance to it; [`Tracer::in_shadow`]), or with a sphere light
        /// (session 4) any object but the light's body (its number).
        towards: Towards,
    },
}

/// What a shadow ray is sent towards.
#[derive(Clone, Copy, Debug)]
pub enum Towards {
    /// A point light this far away.
    Point(Real),
    /// The body of a sphere light: the scene's object of this number.
    Body(usize),
}

impl Direct {
    /// The first half of [`Tracer::direct_light`] at `hit` (facing the ray) of a
    /// surface of `albedo`: the shadow ray it needs, counted in `tracer.rays`, and the
    /// light it would let through; and the object whose glow the path's next ray
    /// must not count, having been sampled here (session 4:
    /// `Tracer::sampled_light`). Inlined into its caller: compiled to WebAssembly as a
    /// call, returning its answer through memory, it took a tenth of the fast
    /// engine's time on `soft-shadows`.
    #[inline(always)]
    pub fn at(tracer: &mut Tracer, hit: &Hit, albedo: Colour) -> (Direct, Option<usize>) {
        let settings = tracer.scene.settings;
        match tracer.scene.light {
            None => (Direct::Known(Colour::ZERO), None),
            Some(Light::Point(light)) => {
                let lit = light.lambert(hit.point, hit.normal, albedo);
                if !settings.shadows {
                    return (Direct::Known(lit), None);
                }
                let (ray, distance) = tracer.shadow_ray(hit, &light);
                let towards = Towards::Point(distance);
                (Direct::Shadowed { ray, lit, towards }, None)
            }
            Some(Light::Sphere(light)) => {
                let sample = match settings.light_sampling {
                    true => tracer.light_sample(&light, hit, albedo),
                    false => None,
                };
                let direct = sample.map_or(Direct::Known(Colour::ZERO), |(ray, lit)| {
                    let towards = Towards::Body(light.object);
                    Direct::Shadowed { ray, lit, towards }
                });
                (direct, tracer.sampled_light())
            }
        }
    }

    /// The shadow ray to trace, if any.
    pub fn ray(&self) -> Option<&Ray> {
        match self {
            Direct::Known(_) => None,
            Direct::Shadowed { ray, .. } => Some(ray),
        }
    }

    /// The direct light, given the nearest hit of the shadow ray (distance and
    /// object), which is ignored where there is no shadow ray.
    pub fn resolve(&self, nearest: Option<(Real, usize)>) -> Colour {
        match *self {
            Direct::Known(light) => light,
            Direct::Shadowed { lit, towards, .. } if towards.reached(nearest) => lit,
            Direct::Shadowed { .. } => Colour::ZERO,
        }
    }
}

impl Towards {
    /// Whether a shadow ray whose nearest hit is `nearest` reaches the light: nothing
    /// closer than a point light, the body of a sphere light first.
    fn reached(self, nearest: Option<(Real, usize)>) -> bool {
        match self {
            Towards::Point(distance) => !closer_than(nearest, distance),
            Towards::Body(light) => nearest.is_some_and(|(_, seen)| seen == light),
        }
    }
}
