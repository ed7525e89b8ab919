//! Beyond the course: session 5's searches of a mesh, every triangle for every ray,
//! with one ray tested against several triangles at once.
//!
//! | file | what it holds |
//! |---|---|
//! | [`triangle_lanes`] | Moller and Trumbore's test of one ray against four or eight triangles at once, to the course's bits |
//! | [`fast_brute_force`] | the brute-force search and the bounding box's, on those lanes |

pub mod fast_brute_force;
pub mod triangle_lanes;
