//! Beyond the course: the pixels of a row rendered four paths at a time, to the
//! same bytes as [`pixel`](crate::render::samples::pixel).
//!
//! Following one path is a chain of steps that each wait for the one before: the
//! nearest sphere needs the ray, the bounce needs the hit, the next ray needs the
//! bounce. Four paths of four different pixels have no such chain between them, so
//! they are followed side by side, one hit each per step: the nearest-sphere test of
//! their four rays, then of their four shadow rays, runs as one test on four rays
//! at once ([`SphereLanes::nearest_of_four`]), each sphere's steps done for the four
//! rays by one instruction each.
//!
//! Every path makes the same computations as the recursive
//! [`radiance`](crate::integrator::Tracer::radiance), in the same order, with its
//! pixel's own random numbers: what each diffuse hit adds is kept (a `Level`) and
//! summed from the end of the path back to its start, as the recursion does when it
//! returns. So each pixel gets the same value to the last bit, and the image the same
//! bytes (a test renders every stage both ways). It models only what the rooms of
//! the course need: diffuse spheres and, from session 5, meshes (a mesh is always
//! diffuse; its triangles are searched one ray at a time, after the spheres, in
//! `fast/meshes_at_once.rs`), a point or sphere light, bounce limit and Russian
//! roulette; any other scene takes the course's recursion.
//!
//! [`SphereLanes::nearest_of_four`]: crate::fast::sphere_lanes::SphereLanes::nearest_of_four

use crate::fast::direct_at_once::{Direct, Towards};
use crate::fast::four_lanes::FourLanes;
#[cfg(feature = "s5")]
use crate::fast::meshes_at_once;
use crate::fast::shading::vector;
use crate::fast::sphere_lanes::SphereLanes;
use crate::geometry::{Hit, Ray};
use crate::integrator::Tracer;
#[cfg(feature = "s4")]
use crate::lights::SphereLight;
use crate::lights::{Light, PointLight};
use crate::materials::Material;
use crate::maths::{Colour, PI, Real, uniform_pair};
use crate::samplers::adaptive::{Estimate, precise_enough};
use crate::samplers::pixel::{camera_sample, start_pixel};
use crate::scene::Scene;

/// How many paths one thread follows at once: the rays of one four-ray test.
const PATHS: usize = 4;

/// Whether [`row`] can render `scene`: every sphere diffuse (a mesh always is).
pub fn applies(scene: &Scene) -> bool {
    scene
        .spheres
        .iter()
        .all(|sphere| matches!(sphere.material, Material::Diffuse { .. }))
}

/// Renders row `row` of `scene`, whose spheres are `spheres`, into `line` (each
/// pixel's radiance) and `taken` (its number of samples), `PATHS` (four) pixels at a
/// time, the next pixel starting where one
/// is done; returns the rays traced and the samples dropped as not finite, as
/// [`Tracer`] counts them.
pub fn row(
    scene: &Scene,
    spheres: &SphereLanes,
    row: u32,
    line: &mut [Colour],
    taken: &mut [u32],
) -> (u64, u64) {
    let mut columns = 0..line.len() as u32;
    let mut paths: Vec<Path> = columns
        .by_ref()
        .take(PATHS)
        .map(|column| Path::new(scene, row, column))
        .collect();
    let (mut rays, mut dropped) = (0, 0);
    while !paths.is_empty() {
        step(spheres, &mut paths);
        paths.retain_mut(|path| {
            if !path.pixel_done() {
                return true;
            }
            line[path.column as usize] = path.estimate.mean.mean();
            taken[path.column as usize] = path.taken;
            rays += path.tracer.rays;
            dropped += u64::from(path.estimate.mean.dropped);
            columns
                .next()
                .map(|column| *path = Path::new(scene, row, column))
                .is_some()
        });
    }
    (rays, dropped)
}

// ANCHOR: step
/// Takes each of `paths` (one to four) one hit further: their rays' nearest hits in
/// one test, then their shadow rays' in another. Where fewer than four paths are
/// left, or a path has no shadow ray, a lane repeats another ray and its answer is
/// not used. The work at the hits (their records, their direct light, their
/// bounces) is done on the lanes too, each part for every path before the next.
fn step(spheres: &SphereLanes, paths: &mut [Path]) {
    let last = paths.len() - 1;
    let ray = |k: usize| &paths[k.min(last)].ray;
    let rays = [ray(0), ray(1), ray(2), ray(3)];
    let nearest = spheres.nearest_of_four(rays);
    let mut hits = [None; PATHS];
    sphere_hits(paths[0].tracer.scene, spheres, rays, nearest, &mut hits);
    for ((path, nearest), hit) in paths.iter_mut().zip(nearest).zip(&mut hits) {
        path.hit(nearest, hit);
    }
    light_all(spheres.lanes(), paths, &hits);
    bounce_all(spheres.lanes(), paths, &hits);
    let mut shadow = [None; PATHS];
    if paths.iter().any(|path| path.shadow_ray().is_some()) {
        let ray = |k: usize| {
            let path = &paths[k.min(last)];
            path.shadow_ray().unwrap_or(&path.ray)
        };
        shadow = spheres.nearest_of_four([ray(0), ray(1), ray(2), ray(3)]);
    }
    for (path, shadow) in paths.iter_mut().zip(shadow) {
        path.light(shadow);
    }
}
// ANCHOR_END: step

/// A path's hit, facing its ray, and the albedo of the surface hit.
type Shaded = Option<(Hit, Colour)>;

/// The records of the hits `nearest` (distance and sphere of `scene`) of four
/// `rays`, their normals facing the rays, worked out on the lanes, with their
/// albedos, into `hits`, which stay `None` where a ray meets no sphere (a lane
/// whose ray meets none repeats another lane's sphere).
fn sphere_hits(
    scene: &Scene,
    spheres: &SphereLanes,
    rays: [&Ray; PATHS],
    nearest: [Option<(Real, usize)>; PATHS],
    hits: &mut [Shaded; PATHS],
) {
    let Some(&Some(any)) = nearest.iter().find(|n| n.is_some()) else {
        return;
    };
    let [n0, n1, n2, n3] = nearest.map(|n| n.unwrap_or(any));
    let (t, object) = ([n0.0, n1.0, n2.0, n3.0], [n0.1, n1.1, n2.1, n3.1]);
    let rows = object.map(|object| spheres.sphere(object));
    let found = spheres.lanes().sphere_hits(rays, t, rows);
    for (k, hit) in hits.iter_mut().enumerate() {
        let sphere = &scene.spheres[object[k]];
        let Material::Diffuse { albedo } = sphere.material else {
            unreachable!("paths at once are used only where every object is diffuse")
        };
        *hit = nearest[k].is_some().then_some((
            Hit {
                t: t[k],
                point: vector(&found.point, k),
                normal: vector(&found.normal, k),
                error: vector(&found.error, k),
                offset: vector(&found.offset, k),
                material: sphere.material,
                emission: sphere.emission,
                object: object[k],
                from_outside: found.outside[k].to_bits() != 0,
            },
            albedo,
        ));
    }
}

/// The direct light at the paths' hits (`hits[k]` for `paths[k]`): for the four
/// hits at once on `lanes` where the light is a point light with shadows or
/// (session 4) a sampled sphere light, as [`Direct::at`] does it for one;
/// otherwise by `Direct::at`.
fn light_all(lanes: FourLanes, paths: &mut [Path], hits: &[Shaded; PATHS]) {
    let scene = paths[0].tracer.scene;
    match scene.light {
        Some(Light::Point(light)) if scene.settings.shadows => {
            point_light_all(lanes, paths, hits, &light);
        }
        #[cfg(feature = "s4")]
        Some(Light::Sphere(light)) if scene.settings.light_sampling => {
            sphere_light_all(lanes, paths, hits, &light);
        }
        _ => {
            for (path, hit) in paths.iter_mut().zip(hits) {
                if let Some((hit, albedo)) = hit {
                    let (direct, skipped) = Direct::at(&mut path.tracer, hit, *albedo);
                    (path.direct, path.skipped) = (Some(direct), skipped);
                }
            }
        }
    }
}

/// The light from the point light `light` at the paths' hits, and their shadow
/// rays, on `lanes`: `Direct::at` with a point light and shadows.
fn point_light_all(
    lanes: FourLanes,
    paths: &mut [Path],
    hits: &[Shaded; PATHS],
    light: &PointLight,
) {
    let Some([h0, h1, h2, h3]) = repeated(hits) else {
        return;
    };
    let four = [&h0.0, &h1.0, &h2.0, &h3.0];
    let lit = lanes.point_light(four, [h0.1, h1.1, h2.1, h3.1], light);
    for (k, (path, hit)) in paths.iter_mut().zip(hits).enumerate() {
        if hit.is_some() {
            path.tracer.rays += 1;
            let ray = Ray {
                origin: vector(&lit.origin, k),
                direction: vector(&lit.direction, k),
            };
            let (lit, towards) = (vector(&lit.lit, k), Towards::Point(lit.distance[k]));
            (path.direct, path.skipped) = (Some(Direct::Shadowed { ray, lit, towards }), None);
        }
    }
}

/// One direction sampled towards the sphere light `light` from each of the paths'
/// hits, its ray and the light it brings, on `lanes`: `Direct::at` with a sampled
/// sphere light (session 4), each path drawing its own random numbers first.
#[cfg(feature = "s4")]
fn sphere_light_all(
    lanes: FourLanes,
    paths: &mut [Path],
    hits: &[Shaded; PATHS],
    light: &SphereLight,
) {
    let mut samples = [[0.0; 3]; PATHS];
    for ((path, hit), sample) in paths.iter_mut().zip(hits).zip(&mut samples) {
        if hit.is_some() {
            let (u1, u2) = uniform_pair(&mut path.tracer.rng);
            let phi = 2.0 * PI * u2;
            *sample = [u1, phi.cos(), phi.sin()];
        }
    }
    let Some([h0, h1, h2, h3]) = repeated(hits) else {
        return;
    };
    let (four, albedo) = ([&h0.0, &h1.0, &h2.0, &h3.0], [h0.1, h1.1, h2.1, h3.1]);
    let shape = (light.centre, light.radius, light.emission);
    let found = lanes.sphere_light(four, albedo, samples, shape);
    for (k, (path, hit)) in paths.iter_mut().zip(hits).enumerate() {
        if hit.is_none() {
            continue;
        }
        let mut direct = Direct::Known(Colour::ZERO);
        if found.kept[k].to_bits() != 0 {
            path.tracer.rays += 1;
            let ray = Ray {
                origin: vector(&found.origin, k),
                direction: vector(&found.direction, k),
            };
            let (lit, towards) = (vector(&found.lit, k), Towards::Body(light.object));
            direct = Direct::Shadowed { ray, lit, towards };
        }
        (path.direct, path.skipped) = (Some(direct), path.tracer.sampled_light());
    }
}

/// Takes the paths on from their hits (`hits[k]` for `paths[k]`): keeps what each
/// hit adds, and makes the next rays of those that bounce, the four at once on
/// `lanes`, each from its own path's random numbers.
fn bounce_all(lanes: FourLanes, paths: &mut [Path], hits: &[Shaded; PATHS]) {
    let mut samples = [None; PATHS];
    let mut bouncing = [None; PATHS];
    for (k, (path, hit)) in paths.iter_mut().zip(hits).enumerate() {
        if let Some((hit, albedo)) = hit
            && path.go_on(hit, *albedo)
        {
            (samples[k], bouncing[k]) = (Some(path.bounce_sample()), Some(hit));
        }
    }
    let Some([h0, h1, h2, h3]) = repeated(&bouncing) else {
        return;
    };
    let any = samples.iter().flatten().next().copied().unwrap_or_default();
    let (origin, direction) =
        lanes.bounces([*h0, *h1, *h2, *h3], samples.map(|s| s.unwrap_or(any)));
    for (k, path) in paths.iter_mut().enumerate() {
        if samples[k].is_some() {
            path.ray = Ray {
                origin: vector(&origin, k),
                direction: vector(&direction, k),
            };
        }
    }
}

/// The four entries of `hits`, a lane without one repeating the first that has
/// one; `None` if none has.
fn repeated<T>(hits: &[Option<T>; PATHS]) -> Option<[&T; PATHS]> {
    let first = hits.iter().flatten().next()?;
    let lane = |k: usize| hits[k].as_ref().unwrap_or(first);
    Some([lane(0), lane(1), lane(2), lane(3)])
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

/// One pixel's samples, followed one path at a time, one hit per [`step`].
struct Path<'s> {
    /// The pixel's random numbers and the counts of rays and samples.
    tracer: Tracer<'s>,
    /// The pixel's row and column.
    row: u32,
    column: u32,
    /// How many samples the pixel may take, and how many it has taken.
    count: u32,
    taken: u32,
    /// The mean of its finished samples, and their spread.
    estimate: Estimate,
    /// The ray to follow next, and the bounces left after its hit.
    ray: Ray,
    bounces: u32,
    /// The hits of the current path so far.
    levels: Vec<Level>,
    /// The direct light of the last hit, until its shadow ray is traced.
    direct: Option<Direct>,
    /// Whether the path ended at its last ray.
    ended: bool,
    /// The object whose emission the bounced ray of the last hit does not count,
    /// because light sampling counted it there (session 4).
    skipped: Option<usize>,
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
    fn pixel_done(&self) -> bool {
        self.taken == self.count
            || precise_enough(&self.tracer.scene.settings, &self.estimate, self.taken)
    }

    /// Counts the ray, whose nearest sphere is `nearest` and whose hit on it is
    /// `hit`: from session 5 a mesh's hit replaces it if closer. `None` where the
    /// ray meets nothing, which ends the path.
    #[cfg_attr(not(feature = "s5"), allow(unused_variables))]
    fn hit(&mut self, nearest: Option<(Real, usize)>, hit: &mut Shaded) {
        self.tracer.rays += 1;
        #[cfg(feature = "s5")]
        if let Some(on_mesh) = meshes_at_once::nearer_mesh(self.tracer.scene, &self.ray, nearest) {
            let Material::Diffuse { albedo } = on_mesh.material else {
                unreachable!("paths at once are used only where every object is diffuse")
            };
            *hit = Some((on_mesh.facing_the_ray(), albedo));
        }
        self.ended = hit.is_none();
    }

    /// Goes on from `hit`, of a surface of `albedo`, once its direct light is
    /// drawn: keeps what the hit adds; returns whether the path bounces.
    fn go_on(&mut self, hit: &Hit, albedo: Colour) -> bool {
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
    /// them, and the cosine and sine of its angle: `[cos phi, sin phi, u2]`.
    fn bounce_sample(&mut self) -> [Real; 3] {
        let (u1, u2) = uniform_pair(&mut self.tracer.rng);
        let phi = 2.0 * PI * u1;
        [phi.cos(), phi.sin(), u2]
    }

    /// The shadow ray of the last hit, if it has one.
    fn shadow_ray(&self) -> Option<&Ray> {
        self.direct.as_ref().and_then(Direct::ray)
    }

    /// Completes the last hit with its direct light, `shadow` being the nearest
    /// sphere of its shadow ray (from session 5 the meshes are searched too), and
    /// ends the sample if the path ended there.
    fn light(&mut self, shadow: Option<(Real, usize)>) {
        if let (Some(direct), Some(level)) = (self.direct.take(), self.levels.last_mut()) {
            level.direct = direct.resolve(shadow);
            #[cfg(feature = "s5")]
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
