//! Scene files: the TOML format, its checks and errors, and the course's stages.

pub mod error;
pub mod features;
pub mod load;
#[cfg(feature = "s5")]
pub mod meshes;
pub mod stages;
pub mod values;

pub use error::*;
pub use features::*;
pub use load::*;
#[cfg(feature = "s5")]
pub use meshes::*;
pub use stages::*;
pub use values::*;
