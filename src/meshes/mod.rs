//! Triangle meshes (session 5): read from OBJ files and placed in the scene; smooth normals from session 6.

pub mod mesh;
#[cfg(feature = "s6")]
pub mod smooth;

pub use mesh::*;
