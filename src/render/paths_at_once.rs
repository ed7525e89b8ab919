//! Beyond the course: the pixels of a row rendered eight paths at a time, to the
//! same bytes as [`pixel`](crate::render::samples::pixel).
//!
//! Following one path is a chain of steps that each wait for the one before: the
//! nearest sphere needs the ray, the bounce needs the hit, the next ray needs the
//! bounce. A processor can start a new operation every cycle but waits many cycles
//! for a square root or a division, so one path leaves it mostly idle. Eight paths of
//! eight different pixels have no such chain between them: their steps are taken
//! side by side, and the nearest-sphere test runs on four rays at once
//! ([`SphereLanes::nearest_of_four`]).
//!
//! Every path makes the same computations as the recursive
//! [`radiance`](crate::integrator::Tracer::radiance), in the same order, with its
//! pixel's own random numbers: what each diffuse hit adds is kept ([`Level`]) and
//! summed from the end of the path back to its start, as the recursion does when it
//! returns. So each pixel gets the same value to the last bit, and the image the same
//! bytes (a test renders every sphere stage both ways). It models only what the
//! sphere rooms need: diffuse spheres, a point or sphere light, bounce limit and
//! Russian roulette; any other scene takes the course's recursion.
//!
//! [`SphereLanes::nearest_of_four`]: crate::scene::sphere_lanes::SphereLanes::nearest_of_four

use crate::geometry::Ray;
use crate::integrator::Tracer;
use crate::materials::Material;
use crate::maths::{Colour, Real, uniform};
use crate::render::samples::{SampleMean, camera_sample, precise_enough, start_pixel};
use crate::scene::Scene;
use crate::scene::sphere_lanes::SphereLanes;

/// How many paths one thread follows at once: two calls of the four-ray test.
const PATHS: usize = 8;

/// Whether [`row`] can render `scene`: spheres only, all of them diffuse.
pub fn applies(scene: &Scene) -> bool {
    #[cfg(feature = "s5")]
    if !scene.meshes.is_empty() {
        return false;
    }
    scene
        .spheres
        .iter()
        .all(|sphere| matches!(sphere.material, Material::Diffuse { .. }))
}

/// Renders row `row` of `scene` into `line` (each pixel's radiance) and `taken` (its
/// number of samples), [`PATHS`] paths at a time; returns the rays traced and the
/// samples dropped as not finite, as [`Tracer`] counts them.
pub fn row(scene: &Scene, row: u32, line: &mut [Colour], taken: &mut [u32]) -> (u64, u64) {
    let spheres = scene.lanes.get_or_init(|| SphereLanes::new(&scene.spheres));
    let mut columns = 0..line.len() as u32;
    let mut paths: Vec<Path> = columns
        .by_ref()
        .take(PATHS)
        .map(|column| Path::new(scene, row, column))
        .collect();
    let (mut rays, mut dropped) = (0, 0);
    while !paths.is_empty() {
        for four in paths.chunks_mut(4) {
            let ray = |k: usize| &four[k.min(four.len() - 1)].ray;
            let nearest = spheres.nearest_of_four([ray(0), ray(1), ray(2), ray(3)]);
            for (path, nearest) in four.iter_mut().zip(nearest) {
                path.step(nearest);
            }
        }
        paths.retain_mut(|path| {
            if !path.pixel_done() {
                return true;
            }
            line[path.column as usize] = path.mean.mean();
            taken[path.column as usize] = path.taken;
            rays += path.tracer.rays;
            dropped += u64::from(path.mean.dropped);
            columns
                .next()
                .map(|column| *path = Path::new(scene, row, column))
                .is_some()
        });
    }
    (rays, dropped)
}

/// What a diffuse hit adds to its path's radiance, once the radiance arriving from
/// the rest of the path, `rest`, is known.
#[derive(Clone, Copy, Debug)]
struct Level {
    /// The light the surface gives off, `None` where light sampling has already
    /// counted it.
    emission: Option<Colour>,
    /// The light arriving straight from the light source.
    direct: Colour,
    /// The surface's albedo.
    albedo: Colour,
    /// How the path went on from here.
    next: Next,
}

/// How a path went on after a diffuse hit: the cases of
/// [`Tracer::diffuse`](crate::integrator::Tracer::diffuse) and of the bounce limit.
#[derive(Clone, Copy, Debug)]
enum Next {
    /// The scene has no indirect light: the hit reflects `direct` alone.
    NoIndirect,
    /// The bounce limit was reached (and the roulette, if any, ended the path).
    Stopped,
    /// A bounce within the limit.
    Bounced,
    /// A bounce past the limit that survived Russian roulette with this probability.
    Survived(Real),
}

impl Level {
    /// The radiance leaving this hit, given the radiance `rest` that its bounce
    /// brings back: the sums and products of the recursion, in its order.
    fn radiance(&self, rest: Colour) -> Colour {
        let reflected = match self.next {
            Next::NoIndirect => self.direct,
            Next::Stopped => self.direct + Colour::ZERO,
            Next::Bounced => self.direct + self.albedo * rest,
            Next::Survived(survival) => self.direct + (1.0 / survival) * (self.albedo * rest),
        };
        match self.emission {
            Some(emission) => emission + reflected,
            None => reflected,
        }
    }
}

/// One pixel's samples, followed one path at a time, one hit per [`Path::step`].
struct Path<'s> {
    /// The pixel's random numbers and the counts of rays and samples.
    tracer: Tracer<'s>,
    /// The pixel's row and column.
    row: u32,
    column: u32,
    /// How many samples the pixel may take, and how many it has taken.
    count: u32,
    taken: u32,
    /// The mean of its finished samples.
    mean: SampleMean,
    /// The ray to follow next, and the bounces left after its hit.
    ray: Ray,
    bounces: u32,
    /// The hits of the current path so far.
    levels: Vec<Level>,
}

impl<'s> Path<'s> {
    /// Pixel (`row`, `column`) of `scene`, its first sample's camera ray ready.
    fn new(scene: &'s Scene, row: u32, column: u32) -> Self {
        let mut tracer = Tracer::new(scene);
        let count = start_pixel(&mut tracer, row, column);
        let ray = camera_sample(&mut tracer, row, column, 0);
        Path {
            tracer,
            row,
            column,
            count,
            taken: 0,
            mean: SampleMean::default(),
            ray,
            bounces: scene.settings.bounces,
            levels: Vec::new(),
        }
    }

    /// Starts sample `taken` of the pixel: its camera ray and the full bounces.
    fn start_sample(&mut self) {
        self.ray = camera_sample(&mut self.tracer, self.row, self.column, self.taken);
        self.bounces = self.tracer.scene.settings.bounces;
    }

    /// Whether the pixel has all its samples.
    fn pixel_done(&self) -> bool {
        self.taken == self.count
            || precise_enough(&self.tracer.scene.settings, &self.mean, self.taken)
    }

    /// Follows the path to the hit `nearest` (the distance and sphere that the ray
    /// meets first): shades it, and either bounces or ends the sample.
    fn step(&mut self, nearest: Option<(Real, usize)>) {
        self.tracer.rays += 1;
        let scene = self.tracer.scene;
        let Some((t, object)) = nearest else {
            return self.end_sample(Colour::ZERO);
        };
        let hit = scene.spheres[object].hit_at(&self.ray, t, object);
        let Material::Diffuse { albedo } = hit.material else {
            unreachable!("paths at once are used only where every sphere is diffuse")
        };
        let counted = self.levels.is_empty() || skipped(scene) != Some(object);
        let hit = hit.facing_the_ray();
        let direct = self.tracer.direct_light(&hit, albedo);
        let next = self.next();
        self.levels.push(Level {
            emission: counted.then_some(hit.emission),
            direct,
            albedo,
            next,
        });
        match next {
            Next::Bounced | Next::Survived(_) => {
                let direction = self.tracer.cosine_direction(&hit);
                self.ray = hit.spawn(direction);
            }
            Next::NoIndirect | Next::Stopped => self.end_sample(Colour::ZERO),
        }
    }

    /// How the path goes on after a hit: the random number of the roulette is
    /// drawn where the recursion draws it.
    fn next(&mut self) -> Next {
        let settings = self.tracer.scene.settings;
        if !settings.indirect {
            return Next::NoIndirect;
        }
        if let Some(left) = self.bounces.checked_sub(1) {
            self.bounces = left;
            return Next::Bounced;
        }
        match roulette(&settings) {
            Some(survival) if uniform(&mut self.tracer.rng) < survival => Next::Survived(survival),
            _ => Next::Stopped,
        }
    }

    /// Ends the current sample, `rest` being the radiance its last ray brought
    /// back, and starts the next one unless the pixel is done.
    fn end_sample(&mut self, rest: Colour) {
        let radiance = self
            .levels
            .drain(..)
            .rev()
            .fold(rest, |rest, level| level.radiance(rest));
        self.mean.add(radiance);
        self.taken += 1;
        if !self.pixel_done() {
            self.start_sample();
        }
    }
}

/// The object whose emission indirect rays do not count because light sampling
/// counts it (session 4), if any.
fn skipped(scene: &Scene) -> Option<usize> {
    #[cfg(feature = "s4")]
    if let Some(crate::lights::Light::Sphere(light)) = scene.light
        && scene.settings.light_sampling
    {
        return Some(light.object);
    }
    let _ = scene;
    None
}

/// The survival probability of Russian roulette past the bounce limit (session 4).
fn roulette(settings: &crate::scene::Settings) -> Option<Real> {
    #[cfg(feature = "s4")]
    return settings.russian_roulette;
    #[cfg(not(feature = "s4"))]
    {
        let _ = settings;
        None
    }
}
