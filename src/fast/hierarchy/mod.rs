//! The fast engine's hierarchy: eight boxes a node, eight triangles a group, built by
//! the surface area heuristic and walked nearest child first.
//!
//! | file | what it holds | in place of |
//! |---|---|---|
//! | [`fast_bvh`] | the hierarchy of eight-box nodes and eight-triangle groups | `Bvh` |
//! | [`sah`] | splits chosen by the surface area heuristic | `Bvh::build` |
//! | [`wide_node`] | eight boxes tested at once, on any lanes | `Aabb::entry` |
//! | [`traversal_stack`] | the children yet to visit, nearest on top | the course's stack |
//! | [`triangle_group`] | the single-precision pre-test of eight triangles | the ray-triangle test |

pub mod fast_bvh;
pub mod sah;
pub mod traversal_stack;
pub mod triangle_group;
pub mod wide_node;
