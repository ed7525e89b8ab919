//! Rays and the shapes they meet: spheres from session 1, boxes and triangles from session 5.

#[cfg(feature = "s5")]
pub mod aabb;
pub mod hit;
pub mod ray;
pub mod sphere;
#[cfg(feature = "s5")]
pub mod triangle;
#[cfg(feature = "s5")]
pub mod watertight;

#[cfg(feature = "s5")]
pub use aabb::*;
pub use hit::*;
pub use ray::*;
pub use sphere::*;
#[cfg(feature = "s5")]
pub use triangle::*;
#[cfg(feature = "s5")]
pub use watertight::*;
