//! Geometry: rays and the shapes they meet.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`ray`] | 1 | the half-line `O + t d` |
//! | [`hit`] | 1 | what a ray finds: the hit record |
//! | [`sphere`] | 1 | the ray-sphere test, the only shape of sessions 1 to 4 |
//! | [`cost`] | 1 | the tests a ray took, counted for the image `--aov cost` |
//! | [`spawn`] | 2 | a new ray leaving a hit point without meeting its own surface |
//! | [`aabb`] | 5 | axis-aligned boxes and the slab test |
//! | [`triangle`] | 5 | the ray-triangle test of the course (Moller-Trumbore) |
//! | [`watertight`] | 5 | the watertight ray-triangle test (Woop, Benthin and Wald) |

pub mod cost;
pub mod hit;
pub mod ray;
pub mod sphere;

#[cfg(feature = "s2")]
pub mod spawn;

#[cfg(feature = "s5")]
pub mod aabb;
#[cfg(feature = "s5")]
pub mod triangle;
#[cfg(feature = "s5")]
pub mod watertight;

pub use hit::Hit;
pub use ray::Ray;
pub use sphere::Sphere;

#[cfg(feature = "s5")]
pub use aabb::Aabb;
#[cfg(feature = "s5")]
pub use triangle::{TriangleHit, TriangleTest, intersect_triangle};
#[cfg(feature = "s5")]
pub use watertight::ShearedRay;
