//! Beyond the course: samplers that place a pixel's samples better than independent
//! random numbers do, and adaptive sampling, which gives each pixel as many samples
//! as it needs. A scene asks for them with `[render] sampler` and `noise`; without,
//! every stage renders through the course's pixel loop. pbrt-v4 (chapter 8) is the
//! model: one dimension per decision of a path, scrambled per pixel, deterministic.
//!
//! | file | session | what it holds | beside |
//! |---|---|---|---|
//! | [`sobol`] | 3 | Owen-scrambled Sobol points | |
//! | [`spread`] | 3 | stratified and Sobol numbers for each decision of a path | `pixel_rng` |
//! | [`adaptive`] | 3 | a pixel's estimated error, and when it stops | |
//! | [`pixel`] | 3 | one pixel's samples with a sampler, as many as it needs | `pixel` |

pub mod adaptive;
pub mod pixel;
pub mod sobol;
pub mod spread;
