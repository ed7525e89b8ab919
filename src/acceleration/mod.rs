//! Finding the nearest triangle quickly (session 6): the bounding volume hierarchy.

pub mod bvh;
pub mod fast_bvh;
pub mod sah;
pub mod triangle_group;

pub use bvh::*;
pub use fast_bvh::*;
pub use triangle_group::*;
