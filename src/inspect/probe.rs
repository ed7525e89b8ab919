//! One pixel's path, ray by ray (`raycourse probe`): the pixel is rendered by the
//! course's own [`pixel`] with the tracer writing down each ray it traces; each
//! level of the chosen sample is then explained with the course's functions, run
//! again from a copy of the tracer as it was at that ray, so every number is the
//! renderer's own.

use crate::geometry::Hit;
use crate::inspect::bounce::{diffuse_albedo, end, next as next_ray};
use crate::inspect::light::direct;
use crate::inspect::path::{Level, Met, Probe};
use crate::integrator::Tracer;
use crate::integrator::tracer::Traced;
use crate::maths::{Colour, Vec3};
use crate::messages::language::Language;
use crate::messages::said::Said;
use crate::render::film::display;
use crate::render::rows::pixel;
use crate::scene::Scene;

/// Why a probe cannot follow the pixel: [`ProbeError::say`] says it in a
/// language, `Display` in English.
#[derive(Clone, Debug, PartialEq)]
pub enum ProbeError {
    /// The pixel is outside the image.
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
    NoSuchSample {
        /// The sample asked for.
        sample: u32,
        /// The samples a pixel takes.
        samples: u32,
    },
}

impl ProbeError {
    /// Why the probe cannot follow the pixel, in `language`.
    pub fn say(&self, language: Language) -> String {
        let said = match *self {
            ProbeError::Outside {
                x,
                y,
                width,
                height,
            } => Said::new("probe-outside")
                .with("x", u64::from(x))
                .with("y", u64::from(y))
                .with("width", u64::from(width))
                .with("height", u64::from(height)),
            ProbeError::NoSuchSample { sample, samples } => Said::new("probe-no-such-sample")
                .with("sample", u64::from(sample))
                .with("samples", u64::from(samples)),
        };
        said.say(language)
    }
}

impl std::fmt::Display for ProbeError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(&self.say(Language::English))
    }
}

impl std::error::Error for ProbeError {}

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

/// Refuses a pixel outside the image and a sample past the last.
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
    Ok(())
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
        after_diffuse = traced
            .hit
            .is_some_and(|h| diffuse_albedo(&h.material).is_some());
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
    let mut level = Level {
        origin: ray.origin.to_array(),
        direction: ray.direction.to_array(),
        bounces_left: bounces,
        hit: None,
        emitted: [0.0; 3],
        glow_not_counted: false,
        direct: None,
        next: None,
        end: Some(crate::messages::said::Said::new("probe-end-leaves")),
        arriving: [0.0; 3],
        throughput: throughput.to_array(),
        adds: [0.0; 3],
    };
    let Some(hit) = traced.hit else {
        return level;
    };
    level.hit = Some(met(scene, &hit));
    let own = own_light(&mut level, traced, &hit, after_diffuse);
    level.adds = (throughput * own).to_array();
    level.end = None;
    match next {
        Some(following) => {
            let direction = following.ray.direction;
            level.next = Some(next_ray(scene, &ray, &hit, direction, bounces));
        }
        None => level.end = Some(end(scene, &hit, bounces)),
    }
    level
}

/// Fills in the light that `level`'s surface `hit` gives of its own, and returns it:
/// what it emits (unless light sampling already counted that glow) and, if it is
/// diffuse, the light source's light; and the radiance arriving along the ray.
fn own_light(level: &mut Level, traced: &Traced, hit: &Hit, after_diffuse: bool) -> Colour {
    level.glow_not_counted = after_diffuse && glow_sampled(traced, hit);
    let emitted = match level.glow_not_counted {
        true => Colour::ZERO,
        false => hit.emission,
    };
    level.emitted = emitted.to_array();
    level.arriving = (emitted + reflected(traced, hit, level.bounces_left)).to_array();
    let Some(albedo) = diffuse_albedo(&hit.material) else {
        return emitted;
    };
    let direct = direct(traced, &hit.facing_the_ray(), albedo);
    let own = emitted + Vec3::from(direct.brings);
    level.direct = Some(direct);
    own
}

/// The light the surface of `hit` reflects along the traced ray: the course's
/// `reflected`, run again from a copy of the tracer as it was before the ray (tracing
/// draws no random number), which draws the same random numbers as the render did.
/// Emitted light plus this is the radiance arriving along the ray, to the last bit.
fn reflected(traced: &Traced, hit: &Hit, bounces: u32) -> Colour {
    traced.before.clone().reflected(&traced.ray, hit, bounces)
}

/// Whether the glow of the object hit is the light that light sampling already
/// counted at the previous diffuse hit.
#[cfg_attr(
    not(feature = "s4"),
    expect(unused_variables, reason = "light sampling comes with session 4")
)]
fn glow_sampled(traced: &Traced, hit: &Hit) -> bool {
    #[cfg(feature = "s4")]
    if traced.before.sampled_light() == Some(hit.object) {
        return true;
    }
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
        material: format!("{:?}", hit.material),
        front_face: hit.from_outside,
    }
}
