//! How a pixel's samples are placed and how many it takes, beyond the course's
//! fixed number of independent samples.

use crate::maths::{Real, Sampler};

/// How a pixel's samples are placed (`[render] sampler`), how many it takes
/// (`[render] noise`) and how they are followed (`[render] recursive`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sampling {
    /// How the random numbers of the samples are chosen.
    pub sampler: Sampler,
    /// Adaptive sampling: a pixel takes samples until the estimated relative
    /// standard error of its mean falls below `noise`, up to [`MOST_SAMPLES`] times
    /// the scene's count; `None`: every pixel takes the scene's count.
    pub noise: Option<Real>,
    /// Whether every sample is followed by the course's recursive
    /// [`radiance`](crate::integrator::Tracer::radiance), one path at a time;
    /// `false`: sphere scenes are followed four paths at a time
    /// ([`paths_at_once`](crate::fast::paths_at_once)), to the same bytes.
    pub recursive: bool,
}

/// With adaptive sampling, a pixel takes at most this many times the scene's sample
/// count.
pub const MOST_SAMPLES: u32 = 4;
