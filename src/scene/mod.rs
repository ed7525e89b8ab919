//! The scene: the camera, the objects, the light and the render settings, and the
//! nearest hit of a ray among the objects.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`objects`] | 1 | the scene, and the nearest sphere a ray meets |
//! | [`settings`] | 1 | how a scene is rendered: samples, bounces, gamma, ... |
//! | [`occlusion`] | 2 | whether anything lies on a shadow ray |
//! | `sphere_hits` | 1 to 4 | the nearest hit: among the spheres |
//! | [`beyond`] | `beyond` | settings beyond the course: samplers, adaptive sampling, the fast engine |
//! | [`mesh_hits`] | 5 | the nearest hit: among the spheres, then the meshes |

pub mod objects;
pub mod settings;

#[cfg(feature = "s2")]
pub mod occlusion;

#[cfg(feature = "beyond")]
pub mod beyond;

#[cfg(not(feature = "s5"))]
pub mod sphere_hits;

#[cfg(feature = "s5")]
pub mod mesh_hits;

pub use objects::Scene;
pub use settings::Settings;
