//! A half-line `p(t) = origin + t * direction`, `t > 0`.

use crate::maths::numbers::{Real, Vec3};

/// A ray: an origin and a unit direction. Because the direction has length 1,
/// the parameter `t` of a hit is the distance travelled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts.
    pub origin: Vec3,
    /// Where it goes, of length 1.
    pub direction: Vec3,
}

impl Ray {
    /// A ray from `origin` along `direction`, which is normalised here.
    pub fn new(origin: Vec3, direction: Vec3) -> Self {
        Self {
            origin,
            direction: direction.normalize(),
        }
    }

    /// The point at distance `t` along the ray: `origin + t * direction`.
    pub fn at(&self, t: Real) -> Vec3 {
        self.origin + t * self.direction
    }
}
