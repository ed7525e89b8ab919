//! The probe's account of how a path goes on from a hit, or why it ends: the next
//! direction, its density and weight, Fresnel's choice and Russian roulette.

use crate::geometry::{Hit, Ray};
use crate::inspect::path::Next;
use crate::materials::Material;
use crate::maths::{Colour, Vec3};
use crate::messages::said::Said;
use crate::scene::Scene;

/// How the path went on from `hit`, met by `ray`, in `direction`, with `bounces`
/// allowed.
#[cfg_attr(
    not(feature = "s2"),
    expect(unused_variables, reason = "mirrors and glass use the ray")
)]
pub fn next(scene: &Scene, ray: &Ray, hit: &Hit, direction: Vec3, bounces: u32) -> Next {
    let survival = if bounces == 0 {
        scene.settings.russian_roulette
    } else {
        None
    };
    let roulette = survival.map_or(1.0, |s| 1.0 / s);
    let mut next = Next {
        kind: Said::new("probe-next-diffuse"),
        direction: direction.to_array(),
        cos: None,
        pdf: None,
        fresnel: None,
        survival,
        weight: [roulette; 3],
    };
    match hit.material {
        Material::Diffuse { albedo } => {
            let cos = direction.dot(hit.facing_the_ray().normal);
            next.cos = Some(cos);
            // A diffuse surface sends a path on from session 3, which draws it so.
            #[cfg(feature = "s3")]
            {
                next.pdf = Some(crate::maths::sampling::cosine_hemisphere_pdf(cos));
            }
            next.weight = (albedo * roulette).to_array();
        }
        #[cfg(feature = "s2")]
        Material::Mirror => crate::inspect::specular::mirror(&mut next),
        #[cfg(feature = "s2")]
        Material::Glass { index } => {
            crate::inspect::specular::glass(&mut next, ray, hit, index, direction);
        }
        #[cfg(feature = "s4")]
        Material::FresnelGlass { index } => {
            crate::inspect::fresnel::fresnel_glass(&mut next, ray, hit, index, direction);
        }
    }
    next
}

/// The albedo of a diffuse material; `None` for mirrors and glass.
pub fn diffuse_albedo(material: &Material) -> Option<Colour> {
    match material {
        Material::Diffuse { albedo } => Some(*albedo),
        #[allow(unreachable_patterns, reason = "session 1 has only diffuse surfaces")]
        _ => None,
    }
}

/// Why the path ends at `hit` with `bounces` allowed.
pub fn end(scene: &Scene, hit: &Hit, bounces: u32) -> Said {
    let settings = &scene.settings;
    if diffuse_albedo(&hit.material).is_some() && !settings.indirect {
        return Said::new("probe-end-no-indirect");
    }
    match (bounces, settings.russian_roulette) {
        (0, Some(survival)) => {
            Said::new("probe-end-roulette").with("survival", crate::maths::to_double(survival))
        }
        (0, None) => {
            Said::new("probe-end-bounce-limit").with("bounces", u64::from(settings.bounces))
        }
        _ => Said::new("probe-end-here"),
    }
}
