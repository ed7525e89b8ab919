//! The tracer: what the integrator's functions share while they follow the rays of
//! one pixel.

use crate::geometry::{Hit, Ray};
use crate::scene::Scene;

#[cfg(feature = "s3")]
use crate::maths::{PixelRng, pixel_rng};

// ANCHOR: tracer
/// Traces the rays of one pixel through a scene, counting them.
#[derive(Clone)]
pub struct Tracer<'a> {
    /// The scene being rendered.
    pub scene: &'a Scene,
    /// Rays traced so far: camera, shadow and secondary rays.
    pub rays: u64,
    /// Samples taken so far: one per pixel, many from session 3.
    pub samples: u64,
    /// Samples whose radiance was NaN or infinite, left out of their pixel's mean
    /// (session 3).
    pub dropped: u64,
    /// The random numbers of the pixel being rendered (session 3).
    #[cfg(feature = "s3")]
    pub rng: PixelRng,
    /// The rays traced, written down only when a pixel is probed (`raycourse
    /// probe`); `None` while rendering.
    pub log: Option<Vec<Traced<'a>>>,
}
// ANCHOR_END: tracer

/// One ray that a probed pixel traced, what it met, and the tracer as it was just
/// before: a copy of it traces the same path again from this ray on.
#[derive(Clone)]
pub struct Traced<'a> {
    /// The ray.
    pub ray: Ray,
    /// What it met, if anything.
    pub hit: Option<Hit>,
    /// The tracer before the ray was traced, without its log.
    pub before: Tracer<'a>,
}

impl<'a> Tracer<'a> {
    /// A tracer over `scene` that has traced no ray yet.
    pub fn new(scene: &'a Scene) -> Self {
        Self {
            scene,
            rays: 0,
            samples: 0,
            dropped: 0,
            #[cfg(feature = "s3")]
            rng: pixel_rng(scene.settings.seed, 0),
            log: None,
        }
    }

    // ANCHOR: trace
    /// The nearest hit of `ray`, counted as one ray traced (and written down when the
    /// pixel is probed).
    pub fn trace(&mut self, ray: &Ray) -> Option<Hit> {
        self.rays += 1;
        let hit = self.scene.intersect(ray);
        self.write_down(ray, hit);
        hit
    }
    // ANCHOR_END: trace

    /// Adds `ray` and `hit` to the log, if there is one, with the tracer as it was
    /// before the ray.
    fn write_down(&mut self, ray: &Ray, hit: Option<Hit>) {
        if let Some(mut log) = self.log.take() {
            let mut before = self.clone();
            before.rays -= 1;
            log.push(Traced {
                ray: *ray,
                hit,
                before,
            });
            self.log = Some(log);
        }
    }
}
