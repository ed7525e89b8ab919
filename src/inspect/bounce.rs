//! The probe's account of how a path goes on from a hit, or why it ends: the next
//! direction, its density and weight, Fresnel's choice and Russian roulette.

use crate::geometry::{Hit, Ray};
use crate::inspect::probe::{Next, cosine_pdf};
use crate::materials::Material;
use crate::maths::{Colour, Vec3};
use crate::scene::Scene;

/// How the path went on from `hit`, met by `ray`, in `direction`, with `bounces`
/// allowed.
pub fn next(scene: &Scene, ray: &Ray, hit: &Hit, direction: Vec3, bounces: u32) -> Next {
    let survival = if bounces == 0 {
        scene.settings.russian_roulette
    } else {
        None
    };
    let roulette = survival.map_or(1.0, |s| 1.0 / s);
    let mut next = Next {
        kind: String::new(),
        direction: direction.to_array(),
        cos: None,
        pdf: None,
        fresnel: None,
        survival,
        weight: [roulette; 3],
    };
    match diffuse_albedo(&hit.material) {
        Some(albedo) => {
            let cos = direction.dot(hit.facing_the_ray().normal);
            next.kind = "diffuse bounce, drawn with density cos(theta) / pi".into();
            next.cos = Some(cos);
            next.pdf = Some(cosine_pdf(cos));
            next.weight = (albedo * roulette).to_array();
        }
        None => specular(&mut next, ray, hit, direction),
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

/// Names what a mirror or glass did with the ray, with Fresnel's reflectance for
/// glass that reflects.
#[cfg_attr(
    not(feature = "s2"),
    expect(unused_variables, reason = "mirrors and glass come with session 2")
)]
fn specular(next: &mut Next, ray: &Ray, hit: &Hit, direction: Vec3) {
    #[cfg(feature = "s2")]
    {
        use crate::materials::optics::{interface, refract};
        let index = match hit.material {
            Material::Glass { index } => index,
            #[cfg(feature = "s4")]
            Material::FresnelGlass { index } => index,
            _ => {
                next.kind = "mirror reflection".into();
                return;
            }
        };
        let (normal, eta) = interface(ray.direction, hit.normal, index);
        let reflected = direction.dot(normal) > 0.0;
        next.kind = match refract(ray.direction, normal, eta) {
            None => "total internal reflection: past the critical angle".into(),
            Some(_) if reflected => "reflection".into(),
            Some(_) => format!("refraction, eta = n1 / n2 = {eta:.4}"),
        };
        #[cfg(feature = "s4")]
        if let Material::FresnelGlass { .. } = hit.material
            && refract(ray.direction, normal, eta).is_some()
        {
            let cos_i = -ray.direction.dot(normal);
            let f = crate::materials::fresnel::fresnel_reflectance(cos_i, eta);
            next.fresnel = Some(f);
            next.kind += if reflected {
                ", Fresnel's choice, with probability F"
            } else {
                ", Fresnel's choice, with probability 1 - F"
            };
        }
    }
}

/// Why the path ends at `hit` with `bounces` allowed.
pub fn end(scene: &Scene, hit: &Hit, bounces: u32) -> String {
    let settings = &scene.settings;
    if diffuse_albedo(&hit.material).is_some() && !settings.indirect {
        return "no indirect light in this scene: the path ends at its diffuse hit".into();
    }
    match (bounces, settings.russian_roulette) {
        (0, Some(survival)) => format!(
            "past the bounce limit, Russian roulette ended the path (it goes on with probability {survival})"
        ),
        (0, None) => format!("the bounce limit ({}) is reached", settings.bounces),
        _ => "the path ends here".into(),
    }
}
