//! Studies of speed and accuracy, beyond the course: a render's error against a reference at a ladder of
//! sample counts, variants of a scene to compare methods, scenes scaled to test
//! rounding, and ray sets to compare the hierarchy's speed with other ray tracers.
//!
//! | file | what it holds |
//! |---|---|
//! | [`convergence`] | error against samples and time; efficiency |
//! | [`variant`] | the same scene file with some keys changed |
//! | [`scale`] | a scene made larger or smaller: rounding at every scale |
//! | [`rayset`] | ray sets in the Embree benchmark's format, traced against a mesh |

pub mod convergence;
pub mod scale;
pub mod variant;

pub mod rayset;
