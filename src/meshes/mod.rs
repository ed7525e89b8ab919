//! Triangle meshes (session 5): read from OBJ files, placed in the scene, searched
//! for the triangle a ray meets first.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`obj`] | 5 | reading an OBJ file, and placing its mesh in the scene |
//! | [`clearance`] | 5 | how far from its triangle a new ray starts |
//! | [`mesh`] | 5 | the placed mesh, the ray-triangle tests, how its triangles are searched, the hit record |
//! | [`brute_force`] | 5 | the simplest search: every triangle |
//! | [`smooth`] | 6 | normals interpolated across triangles |
//! | [`uv`] | 7 | texture coordinates interpolated across triangles |

pub mod brute_force;
pub mod clearance;
pub mod mesh;
pub mod obj;

#[cfg(feature = "s6")]
pub mod smooth;

#[cfg(feature = "s7")]
pub mod uv;

pub use brute_force::BruteForce;
pub use mesh::{Mesh, MeshAlbedo, MeshHit, Search};
pub use obj::{ObjData, Placement, read_obj, read_obj_from};
