//! How a scene is rendered: the settings of a scene file's `[render]` table.

use smart_default::SmartDefault;

use crate::maths::Real;

// ANCHOR: settings
/// How a scene is rendered. Every setting is read from the scene file; the later
/// ones keep the course's first choices unless a scene asks for more. By default:
/// one sample, five bounces, seed 0, linear output, and nothing more.
#[derive(Clone, Copy, Debug, PartialEq, SmartDefault)]
pub struct Settings {
    /// Camera rays averaged in each pixel (many from session 3).
    #[default = 1]
    pub samples: u32,
    /// How many times a path may bounce off mirrors, glass (session 2) and diffuse
    /// surfaces (session 3) before it stops.
    #[default = 5]
    pub bounces: u32,
    /// Seed of the per-pixel random generators (session 3).
    pub seed: u64,
    /// Display gamma (session 2): an 8-bit pixel is `min(255, L^(1/gamma))`; 1 leaves
    /// radiance as is.
    #[default = 1.0]
    pub gamma: Real,
    /// Whether a shadow ray checks that the point light is visible (session 2).
    pub shadows: bool,
    /// The course's fixed offset `epsilon`: a shadow ray starts at `P + epsilon N`
    /// (session 2). `None`: at the offset that follows the point's rounding error
    /// (`Hit::spawn`, session 2); `Some(0.0)` shows shadow acne.
    pub shadow_offset: Option<Real>,
    /// Whether diffuse surfaces also reflect light arriving from other surfaces
    /// (session 3), or only the light source's.
    pub indirect: bool,
    /// Whether a sphere light is sampled directly at each diffuse hit (session 4),
    /// or found only by indirect rays that happen to hit it.
    pub light_sampling: bool,
    /// Past the bounce limit, the probability that a path goes on (Russian roulette,
    /// session 4); `None`: paths stop at the limit.
    pub russian_roulette: Option<Real>,
}
// ANCHOR_END: settings
