//! Acceleration: finding the triangle a ray meets without testing them all.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`bounding_box`] | 5 | the mesh's box tested before its triangles |
//! | [`bvh`] | 6 | the course's bounding volume hierarchy: boxes within boxes |

pub mod bounding_box;

#[cfg(feature = "s6")]
pub mod bvh;

pub use bounding_box::BoundingBox;

#[cfg(feature = "s6")]
pub use bvh::Bvh;
