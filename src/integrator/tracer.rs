//! The tracer: what the integrator's functions share while they follow the rays of
//! one pixel.

use crate::geometry::{Hit, Ray};
use crate::scene::Scene;

#[cfg(feature = "s3")]
use crate::maths::{PixelRng, pixel_rng};

// ANCHOR: tracer
/// Traces the rays of one pixel through a scene, counting them.
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
}
// ANCHOR_END: tracer

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
        }
    }

    // ANCHOR: trace
    /// The nearest hit of `ray`, counted as one ray traced.
    pub fn trace(&mut self, ray: &Ray) -> Option<Hit> {
        self.rays += 1;
        self.scene.intersect(ray)
    }
    // ANCHOR_END: trace
}
