//! What the probe records of a path: a block per ray, in the book's terms, and the
//! sample's and the pixel's radiance. Every field is a plain number, vector or name,
//! so that the record prints as text and as JSON alike.

use serde::Serialize;

use crate::maths::Real;
use crate::messages::said::Said;

/// One sample of one pixel, followed ray by ray.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Probe {
    /// The pixel's column, from the left.
    pub x: u32,
    /// The pixel's row, from the top.
    pub y: u32,
    /// The sample followed, from 0.
    pub sample: u32,
    /// The samples the pixel takes.
    pub samples: u32,
    /// Each ray of the sample's path, the camera ray first.
    pub levels: Vec<Level>,
    /// The sample's radiance `L`: what the camera ray brings.
    pub radiance: [Real; 3],
    /// The pixel's radiance: the mean of its samples.
    pub pixel: [Real; 3],
    /// The display gamma.
    pub gamma: Real,
    /// The pixel's 8-bit value after gamma.
    pub shown: [u8; 3],
}

/// One ray of the path and what it brings.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Level {
    /// The ray's origin `O`.
    pub origin: [Real; 3],
    /// The ray's direction `u`.
    pub direction: [Real; 3],
    /// Bounces still allowed after this ray's hit, before Russian roulette decides.
    pub bounces_left: u32,
    /// What the ray meets; `None`: it leaves the scene and brings black.
    pub hit: Option<Met>,
    /// The light the surface emits that the path counts, `Le`.
    pub emitted: [Real; 3],
    /// Whether the surface's glow was left out, because light sampling at the
    /// previous diffuse hit already counted it.
    pub glow_not_counted: bool,
    /// The light from the light source at a diffuse hit.
    pub direct: Option<Direct>,
    /// How the path goes on; `None` where it ends.
    pub next: Option<Next>,
    /// Why the path ends here, where it does.
    pub end: Option<Said>,
    /// The radiance `L` arriving along this ray: emitted, direct and what the rest of
    /// the path brings, weighted.
    pub arriving: [Real; 3],
    /// The product of the weights of the bounces before this ray.
    pub throughput: [Real; 3],
    /// What this level adds to the sample's radiance: throughput times (emitted plus
    /// direct).
    pub adds: [Real; 3],
}

/// What a ray met.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Met {
    /// Distance `t` along the ray.
    pub t: Real,
    /// The point `P`.
    pub point: [Real; 3],
    /// The unit normal `N`, out of the object.
    pub normal: [Real; 3],
    /// The object's index in the scene (spheres first, then meshes).
    pub object: usize,
    /// `sphere` or `mesh`.
    pub shape: &'static str,
    /// The material, as the scene file would write it.
    pub material: String,
    /// Whether the ray came from outside the object.
    pub front_face: bool,
}

/// The light source's part at a diffuse hit.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Direct {
    /// `point light` or `sphere light`.
    pub light: &'static str,
    /// The shadow ray, where one was traced.
    pub shadow_ray: Option<ShadowRay>,
    /// The light it brings, after Lambert's law (and the pdf, for a sphere light).
    pub brings: [Real; 3],
}

/// A ray towards the light.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ShadowRay {
    /// Its origin, pushed off the surface.
    pub origin: [Real; 3],
    /// Its direction.
    pub direction: [Real; 3],
    /// The distance to the point light, or to the sphere light where the ray meets it.
    pub distance: Option<Real>,
    /// The object in the way, if any.
    pub blocked_by: Option<usize>,
    /// Where along the shadow ray the object in the way is met.
    pub blocked_at: Option<Real>,
}

/// How the path goes on from a hit.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Next {
    /// What the surface does: a diffuse bounce, a mirror reflection, a refraction,
    /// a total internal reflection, or Fresnel's choice of one.
    pub kind: Said,
    /// The next ray's direction.
    pub direction: [Real; 3],
    /// For a diffuse bounce: `cos(theta) = N . u'`.
    pub cos: Option<Real>,
    /// For a diffuse bounce: the density it was drawn with, `cos(theta) / pi`.
    pub pdf: Option<Real>,
    /// For glass that reflects: Fresnel's reflectance `F`, the probability of the
    /// reflected ray.
    pub fresnel: Option<Real>,
    /// Past the bounce limit: the probability that Russian roulette let it go on.
    pub survival: Option<Real>,
    /// The weight of the light it brings back.
    pub weight: [Real; 3],
}

impl ShadowRay {
    /// The record of `ray`, with the distance to the light where known, and the
    /// object in its way with its distance, if any.
    pub fn new(
        ray: &crate::geometry::Ray,
        distance: Option<Real>,
        in_the_way: Option<(Real, usize)>,
    ) -> ShadowRay {
        ShadowRay {
            origin: ray.origin.to_array(),
            direction: ray.direction.to_array(),
            distance,
            blocked_by: in_the_way.map(|(_, object)| object),
            blocked_at: in_the_way.map(|(t, _)| t),
        }
    }
}
