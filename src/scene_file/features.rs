//! Which course session this build was compiled for.
//!
//! The Cargo features `s1`..`s7` decide what code exists; a scene file decides what a
//! render uses. When a scene asks for something this build lacks, the loader names
//! the feature that brings it, using the session number below.

/// The last course session enabled in this build: 7 with feature `s7` (the default),
/// 1 with `s1` alone. The build script (`build.rs`) finds it.
pub const SESSION: u32 = (env!("RAYCOURSE_SESSION").as_bytes()[0] - b'0') as u32;

/// The Cargo feature of a session: `s` followed by its number.
pub fn feature_name(session: u32) -> String {
    format!("s{session}")
}
