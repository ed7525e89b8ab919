//! One pixel's path, ray by ray (`raycourse probe`): the pixel is rendered by the
//! course's own [`pixel`] with the tracer writing down each ray it traces; each
//! level of the chosen sample is then explained with the course's functions, run
//! again from a copy of the tracer as it was at that ray, so every number is the
//! renderer's own.

use serde::Serialize;

use crate::geometry::Hit;
use crate::inspect::bounce::diffuse_albedo;
use crate::integrator::Tracer;
use crate::integrator::tracer::Traced;
use crate::materials::Material;
use crate::maths::{Colour, PI, Real, Vec3};
use crate::render::film::display;
use crate::render::rows::pixel;
use crate::scene::Scene;

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
    pub end: Option<String>,
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
    pub kind: String,
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

/// Why a probe cannot follow the pixel.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ProbeError {
    /// The pixel is outside the image.
    #[error("pixel ({x}, {y}) is outside the image, which is {width}x{height}")]
    Outside {
        /// The column asked for.
        x: u32,
        /// The row asked for.
        y: u32,
        /// The image's width.
        width: u32,
        /// The image's height.
        height: u32,
    },
    /// The sample is past the pixel's samples.
    #[error("sample {sample} does not exist: the pixel takes {samples} (from 0)")]
    NoSuchSample {
        /// The sample asked for.
        sample: u32,
        /// The samples a pixel takes.
        samples: u32,
    },
    /// The scene renders with code beyond the course, which the probe does not follow.
    #[error("the probe follows the course's code; this scene asks for {0}")]
    Beyond(String),
}

/// Follows sample `sample` of pixel (`x`, `y`) of `scene`.
pub fn probe(scene: &Scene, x: u32, y: u32, sample: u32) -> Result<Probe, ProbeError> {
    check(scene, x, y, sample)?;
    let mut tracer = Tracer::new(scene);
    tracer.log = Some(vec![]);
    let mean = pixel(&mut tracer, y, x);
    let log = tracer.log.take().unwrap_or_default();
    let path: Vec<&Traced> = log
        .iter()
        .filter(|t| t.before.samples == u64::from(sample) + 1)
        .collect();
    let levels = explain(scene, &path);
    let gamma = scene.settings.gamma;
    Ok(Probe {
        x,
        y,
        sample,
        samples: scene.settings.samples,
        radiance: levels.first().map_or([0.0; 3], |l| l.arriving),
        levels,
        pixel: mean.to_array(),
        gamma,
        shown: mean.to_array().map(|c| display(c, gamma)),
    })
}

/// Refuses a pixel outside the image, a sample past the last, and a scene that
/// renders with code beyond the course.
fn check(scene: &Scene, x: u32, y: u32, sample: u32) -> Result<(), ProbeError> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    if x >= width || y >= height {
        return Err(ProbeError::Outside {
            x,
            y,
            width,
            height,
        });
    }
    let samples = scene.settings.samples;
    if sample >= samples {
        return Err(ProbeError::NoSuchSample { sample, samples });
    }
    #[cfg(feature = "s3")]
    if let Some(what) = beyond_the_course(&scene.settings.beyond) {
        return Err(ProbeError::Beyond(what));
    }
    Ok(())
}

/// What a scene's render uses beyond the course, if anything: another sampler,
/// adaptive sampling, the fast engine.
#[cfg(feature = "s3")]
fn beyond_the_course(beyond: &crate::scene::beyond::Beyond) -> Option<String> {
    use crate::scene::beyond::Sampler;
    let mut what = vec![];
    if beyond.sampler != Sampler::Independent {
        what.push(format!("the sampler {:?}", beyond.sampler));
    }
    if let Some(noise) = beyond.noise {
        what.push(format!("adaptive sampling (noise {noise})"));
    }
    if beyond.fast {
        what.push("the fast engine (--fast)".into());
    }
    (!what.is_empty()).then(|| what.join(" and "))
}

/// The levels of a path whose rays are `path`, in order.
fn explain(scene: &Scene, path: &[&Traced]) -> Vec<Level> {
    let mut levels: Vec<Level> = vec![];
    let mut bounces = scene.settings.bounces;
    let mut throughput = Colour::ONE;
    let mut after_diffuse = false;
    for (k, traced) in path.iter().enumerate() {
        let level = level(
            scene,
            traced,
            path.get(k + 1),
            bounces,
            after_diffuse,
            throughput,
        );
        throughput *= level
            .next
            .as_ref()
            .map_or(Colour::ZERO, |n| Vec3::from(n.weight));
        after_diffuse = matches!(
            traced.hit.map(|h| h.material),
            Some(Material::Diffuse { .. })
        );
        bounces = bounces.saturating_sub(1);
        levels.push(level);
    }
    levels
}

/// One level: `traced`, the ray after it (if any), the bounces allowed, whether the
/// ray left a diffuse surface, and the throughput so far.
fn level(
    scene: &Scene,
    traced: &Traced,
    next: Option<&&Traced>,
    bounces: u32,
    after_diffuse: bool,
    throughput: Colour,
) -> Level {
    let ray = traced.ray;
    let arriving = arriving(traced, bounces, after_diffuse);
    let mut level = Level {
        origin: ray.origin.to_array(),
        direction: ray.direction.to_array(),
        bounces_left: bounces,
        hit: None,
        emitted: [0.0; 3],
        glow_not_counted: false,
        direct: None,
        next: None,
        end: Some("the ray leaves the scene: it brings black".into()),
        arriving: arriving.to_array(),
        throughput: throughput.to_array(),
        adds: [0.0; 3],
    };
    let Some(hit) = traced.hit else {
        return level;
    };
    level.hit = Some(met(scene, &hit));
    level.glow_not_counted = after_diffuse && glow_sampled(traced, &hit);
    let emitted = if level.glow_not_counted {
        Colour::ZERO
    } else {
        hit.emission
    };
    level.emitted = emitted.to_array();
    let mut own = emitted;
    if let Some(albedo) = diffuse_albedo(&hit.material) {
        let direct = super::light::direct(traced, &hit.facing_the_ray(), albedo);
        own += Vec3::from(direct.brings);
        level.direct = Some(direct);
    }
    level.adds = (throughput * own).to_array();
    match next {
        Some(following) => {
            level.next = Some(super::bounce::next(
                scene,
                &ray,
                &hit,
                following.ray.direction,
                bounces,
            ));
            level.end = None;
        }
        None => level.end = Some(super::bounce::end(scene, &hit, bounces)),
    }
    level
}

/// The radiance arriving along the traced ray: the course's `radiance` run again
/// from a copy of the tracer as it was, which draws the same random numbers.
#[cfg_attr(
    not(feature = "s4"),
    expect(
        unused_variables,
        reason = "from session 4 a bounce may skip the light's glow"
    )
)]
fn arriving(traced: &Traced, bounces: u32, after_diffuse: bool) -> Colour {
    let mut again = traced.before.clone();
    #[cfg(feature = "s4")]
    if after_diffuse {
        let skip = again.sampled_light();
        return again.radiance_skipping(&traced.ray, bounces, skip);
    }
    again.radiance(&traced.ray, bounces)
}

/// Whether the glow of the object hit is the light that light sampling already
/// counted at the previous diffuse hit.
#[cfg_attr(
    not(feature = "s4"),
    expect(unused_variables, reason = "light sampling comes with session 4")
)]
fn glow_sampled(traced: &Traced, hit: &Hit) -> bool {
    #[cfg(feature = "s4")]
    return traced.before.sampled_light() == Some(hit.object);
    #[cfg(not(feature = "s4"))]
    false
}

/// What a ray met, in the book's terms.
fn met(scene: &Scene, hit: &Hit) -> Met {
    Met {
        t: hit.t,
        point: hit.point.to_array(),
        normal: hit.normal.to_array(),
        object: hit.object,
        shape: if hit.object < scene.spheres.len() {
            "sphere"
        } else {
            "mesh"
        },
        material: material_name(&hit.material),
        front_face: hit.from_outside,
    }
}

/// A material as the scene file writes it: `{ diffuse = [0.8, 0.2, 0.2] }`.
pub fn material_name(material: &Material) -> String {
    match material {
        Material::Diffuse { albedo } => format!("diffuse {}", triple(albedo.to_array())),
        #[cfg(feature = "s2")]
        Material::Mirror => "mirror".into(),
        #[cfg(feature = "s2")]
        Material::Glass { index } => format!("glass of index {index}"),
        #[cfg(feature = "s4")]
        Material::FresnelGlass { index } => format!("Fresnel glass of index {index}"),
    }
}

/// Three numbers as the probe writes them: `(0.800, 0.200, 0.200)`.
pub fn triple(v: [Real; 3]) -> String {
    format!("({:.4}, {:.4}, {:.4})", v[0], v[1], v[2])
}

/// The density of a cosine-weighted direction at `cos`: `cos(theta) / pi`.
pub fn cosine_pdf(cos: Real) -> Real {
    cos / PI
}
