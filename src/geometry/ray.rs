//! A half-line `p(t) = O + t d`, `t > 0`.

use crate::maths::{Real, Vec3};

// ANCHOR: ray
/// A ray: an origin `O` and a unit direction `d`. Because the direction has length 1,
/// the parameter `t` of a hit is the distance travelled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts: `O`.
    pub origin: Vec3,
    /// Where it goes, of length 1: `d`.
    pub direction: Vec3,
}
// ANCHOR_END: ray

impl Ray {
    /// A ray from `origin` along `direction`, which is normalised here.
    pub fn new(origin: Vec3, direction: Vec3) -> Self {
        Self {
            origin,
            direction: direction.normalize(),
        }
    }

    /// The point at distance `t` along the ray: `O + t d`.
    pub fn at(&self, t: Real) -> Vec3 {
        self.origin + t * self.direction
    }
}
