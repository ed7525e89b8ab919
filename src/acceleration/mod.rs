//! Acceleration: finding the triangle a ray meets without testing them all.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`bounding_box`] | 5 | the mesh's box tested before its triangles |
//! | [`bvh`] | 6 | the course's bounding volume hierarchy: boxes within boxes |
//! | [`sah`] | 6 | beyond the course: splits chosen by the surface area heuristic |
//! | [`fast_bvh`] | 6 | beyond the course: four boxes and four triangles tested at once |
//! | [`triangle_group`] | 6 | beyond the course: the single-precision pre-test of four triangles |

pub mod bounding_box;

#[cfg(feature = "s6")]
pub mod bvh;
#[cfg(feature = "s6")]
pub mod fast_bvh;
#[cfg(feature = "s6")]
pub mod sah;
#[cfg(feature = "s6")]
pub mod triangle_group;

pub use bounding_box::BoundingBox;

#[cfg(feature = "s6")]
pub use bvh::Bvh;
#[cfg(feature = "s6")]
pub use fast_bvh::FastBvh;
