//! Looking inside a render, to find what went wrong: one pixel's path ray by ray
//! (`raycourse probe`), and images of what the renderer sees (`--aov`). Both run
//! the course's own functions.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`probe`] | 1 | one sample of one pixel, followed ray by ray |
//! | [`path`] | 1 | what the probe records of each ray |
//! | [`light`] | 1 | the probe's account of the light at a diffuse hit |
//! | `sphere_light` | 4 | the same for a sphere light |
//! | [`bounce`] | 1 | the probe's account of how the path goes on |
//! | `specular` | 2 | the same at a mirror or glass |
//! | `fresnel` | 4 | the same at glass that reflects: Fresnel's choice |
//! | [`probe_text`] | 1 | the probe as text, in the book's notation |
//! | [`aov`] | 1 | normals, distances, albedos, objects and costs as images |
//! | [`false_colour`] | 1 | the false-colour scale and its legend |

pub mod aov;
pub mod bounce;
pub mod false_colour;
pub mod light;
pub mod path;
pub mod probe;
pub mod probe_text;

#[cfg(feature = "s2")]
pub mod specular;

#[cfg(feature = "s4")]
pub mod fresnel;
#[cfg(feature = "s4")]
pub mod sphere_light;
