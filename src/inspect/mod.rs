//! Looking inside a render, to find what went wrong: one pixel's path ray by ray
//! (`raycourse probe`), and images of what the renderer sees (`--aov`). Both run
//! the course's own functions.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`probe`] | 1 | one sample of one pixel, followed ray by ray |
//! | [`light`] | 1 | the probe's account of the light at a diffuse hit |
//! | [`bounce`] | 1 | the probe's account of how the path goes on |
//! | [`probe_text`] | 1 | the probe as text, in the book's notation |
//! | [`aov`] | 1 | normals, distances, albedos, objects and costs as images |
//! | [`colour_scale`] | 1 | the false-colour scale and its legend |

pub mod aov;
pub mod bounce;
pub mod colour_scale;
pub mod light;
pub mod probe;
pub mod probe_text;
