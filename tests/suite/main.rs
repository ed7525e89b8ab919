//! Every test of the crate but the stages' snapshots (`tests/stages.rs`), as one
//! test binary, so that `cargo test` compiles and links it once: a module per
//! subject, in the order of the course, each gated on the session that brings what
//! it tests. `cargo test --test suite furnace` runs one module.

mod common;

mod bad_input;
mod bad_scenes;
mod cli;
mod extremes;
mod fuzz;
mod inspect;
mod pictures;

#[cfg(feature = "s2")]
mod languages;

#[cfg(feature = "s2")]
mod furnace;

#[cfg(all(feature = "s3", not(feature = "f32")))]
mod chi2;
#[cfg(feature = "plots")]
mod converge;
#[cfg(feature = "beyond")]
mod engines;
#[cfg(feature = "beyond")]
mod scale_sweep;

#[cfg(feature = "s4")]
mod light_sampling;
#[cfg(feature = "beyond")]
mod samplers;

#[cfg(feature = "s5")]
mod meshes;

#[cfg(feature = "s6")]
mod watertight;

#[cfg(feature = "s5")]
mod large_triangles;

#[cfg(feature = "s7")]
mod check;
