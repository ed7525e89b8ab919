//! Beyond the course: one pixel's samples, followed one path at a time, one hit per
//! step of [`paths_at_once`](crate::fast::paths::paths_at_once): what each diffuse hit adds
//! (a `Level`), summed from the end of the path back to its start as the recursive
//! [`radiance`](crate::integrator::Tracer::radiance) does when it returns.

use crate::fast::paths::direct_at_once::Direct;
use crate::fast::paths::meshes_at_once;
use crate::fast::simd::real_lanes::LANES;
use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
use crate::maths::{Colour, PI, Real, uniform_pair};
use crate::samplers::adaptive::{Estimate, precise_enough};
use crate::samplers::pixel::{camera_sample, start_pixel};
use crate::scene::Scene;
use crate::scene::beyond::Beyond;

/// How many paths one thread follows at once: one per lane of a kind of lanes
/// ([`RealSource`](crate::fast::simd::real_lanes::RealSource)), four in double
/// precision and eight in single.
pub const PATHS: usize = LANES;

/// A path's hit, facing its ray, and the albedo of the surface hit.
pub(crate) type Shaded = Option<(Hit, Colour)>;

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
/// [`Tracer::diffuse`](crate::integrator::Tracer::diffuse) and of
/// [`Tracer::next_bounce`](crate::integrator::Tracer::next_bounce).
#[derive(Clone, Copy, Debug)]
enum Next {
    /// The scene has no indirect light: the hit reflects `direct` alone.
    NoIndirect,
    /// The path stopped: the bounce limit was reached (and Russian roulette, if
    /// any, ended it).
    Stopped,
    /// The path bounced, and what it brings back has this weight.
    Bounced(Real),
}

impl Level {
    // ANCHOR: level_radiance
    /// The radiance leaving this hit, given the radiance `rest` that its bounce
    /// brings back: the sums and products of the recursion, in its order.
    fn radiance(&self, rest: Colour) -> Colour {
        let reflected = match self.next {
            Next::NoIndirect => self.direct,
            Next::Stopped => self.direct + Colour::ZERO,
            Next::Bounced(weight) => self.direct + weight * (self.albedo * rest),
        };
        match self.emission {
            Some(emission) => emission + reflected,
            None => reflected,
        }
    }
    // ANCHOR_END: level_radiance
}

/// One pixel's samples, followed one path at a time, one hit per step.
pub(crate) struct Path<'s> {
    /// The pixel's random numbers and the counts of rays and samples.
    pub(crate) tracer: Tracer<'s>,
    /// The pixel's row and column.
    row: u32,
    pub(crate) column: u32,
    /// How many samples the pixel may take, and how many it has taken.
    count: u32,
    pub(crate) taken: u32,
    /// Adaptive sampling's target relative standard error, if any.
    noise: Option<Real>,
    /// The mean of its finished samples, and their spread.
    pub(crate) estimate: Estimate,
    /// The ray to follow next, and the bounces left after its hit.
    pub(crate) ray: Ray,
    bounces: u32,
    /// The hits of the current path so far.
    levels: Vec<Level>,
    /// The direct light of the last hit, until its shadow ray is traced.
    pub(crate) direct: Option<Direct>,
    /// Whether the path ended at its last ray.
    ended: bool,
    /// The object whose emission the bounced ray of the last hit does not count,
    /// because light sampling counted it there (session 4).
    pub(crate) skipped: Option<usize>,
}

impl<'s> Path<'s> {
    /// Pixel (`row`, `column`) of `scene` with the settings `beyond`, its first
    /// sample's camera ray ready.
    pub(crate) fn new(scene: &'s Scene, beyond: &Beyond, row: u32, column: u32) -> Self {
        let mut tracer = Tracer::new(scene);
        let count = start_pixel(&mut tracer, beyond, row, column);
        let ray = camera_sample(&mut tracer, row, column, 0);
        Path {
            tracer,
            row,
            column,
            count,
            taken: 0,
            noise: beyond.noise,
            estimate: Estimate::default(),
            ray,
            bounces: scene.settings.bounces,
            levels: Vec::new(),
            direct: None,
            ended: false,
            skipped: None,
        }
    }

    /// Starts sample `taken` of the pixel: its camera ray and the full bounces.
    fn start_sample(&mut self) {
        self.ray = camera_sample(&mut self.tracer, self.row, self.column, self.taken);
        self.bounces = self.tracer.scene.settings.bounces;
    }

    /// Whether the pixel has all its samples.
    pub(crate) fn pixel_done(&self) -> bool {
        self.taken == self.count
            || precise_enough(
                self.noise,
                self.tracer.scene.settings.samples,
                &self.estimate,
                self.taken,
            )
    }

    /// Counts the ray, whose nearest sphere is `nearest` and whose hit on it is
    /// `hit`: a mesh's hit replaces it if closer. `None` where the ray meets
    /// nothing, which ends the path.
    pub(crate) fn hit(&mut self, nearest: Option<(Real, usize)>, hit: &mut Shaded) {
        self.tracer.rays += 1;
        if let Some(on_mesh) = meshes_at_once::nearer_mesh(self.tracer.scene, &self.ray, nearest) {
            *hit = Some(on_mesh);
        }
        self.ended = hit.is_none();
    }

    /// Goes on from `hit`, of a surface of `albedo`, once its direct light is
    /// drawn: keeps what the hit adds; returns whether the path bounces.
    pub(crate) fn go_on(&mut self, hit: &Hit, albedo: Colour) -> bool {
        let counted = self.levels.is_empty() || self.skipped != Some(hit.object);
        let next = self.next();
        self.levels.push(Level {
            emission: counted.then_some(hit.emission),
            direct: Colour::ZERO,
            albedo,
            next,
        });
        self.ended = matches!(next, Next::NoIndirect | Next::Stopped);
        !self.ended
    }

    /// The random numbers of a bounce, drawn as `Tracer::cosine_direction` draws
    /// them, as its angle and its second number: `[phi, u2]`, `phi = 2 pi u1`, whose
    /// cosine and sine are taken on the lanes for all the paths at once.
    pub(crate) fn bounce_sample(&mut self) -> [Real; 2] {
        let (u1, u2) = uniform_pair(&mut self.tracer.rng);
        [2.0 * PI * u1, u2]
    }

    /// The shadow ray of the last hit, if it has one.
    pub(crate) fn shadow_ray(&self) -> Option<&Ray> {
        self.direct.as_ref().and_then(Direct::ray)
    }

    /// Completes the last hit with its direct light, `shadow` being the nearest
    /// sphere of its shadow ray (from session 5 the meshes are searched too), and
    /// ends the sample if the path ended there.
    pub(crate) fn light(&mut self, shadow: Option<(Real, usize)>) {
        if let (Some(direct), Some(level)) = (self.direct.take(), self.levels.last_mut()) {
            level.direct = direct.resolve(shadow);
            if meshes_at_once::in_the_way(self.tracer.scene, &direct, shadow) {
                level.direct = Colour::ZERO;
            }
        }
        if self.ended {
            self.ended = false;
            self.end_sample(Colour::ZERO);
        }
    }

    /// How the path goes on after a hit: by the course's
    /// [`next_bounce`](crate::integrator::Tracer::next_bounce), which draws the
    /// roulette's random number where the recursion draws it.
    fn next(&mut self) -> Next {
        if !self.tracer.scene.settings.indirect {
            return Next::NoIndirect;
        }
        match self.tracer.next_bounce(self.bounces) {
            Some((left, weight)) => {
                self.bounces = left;
                Next::Bounced(weight)
            }
            None => Next::Stopped,
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
        self.estimate.add(radiance);
        self.taken += 1;
        if !self.pixel_done() {
            self.start_sample();
        }
    }
}

/// The entries of `hits`, a lane without one repeating the first that has one;
/// `None` if none has.
pub(crate) fn repeated<T>(hits: &[Option<T>; PATHS]) -> Option<[&T; PATHS]> {
    let first = hits.iter().flatten().next()?;
    Some(std::array::from_fn(|k| hits[k].as_ref().unwrap_or(first)))
}
