//! Studies of speed and accuracy (from session 3, when rendering becomes a trade
//! between time and noise): a render's error against a reference at a ladder of
//! sample counts, variants of a scene to compare methods, scenes scaled to test
//! rounding, and ray sets to compare the hierarchy's speed with other ray tracers.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`convergence`] | 3 | error against samples and time; efficiency |
//! | [`reference`](mod@reference) | 3 | converged reference images, cached on disk |
//! | [`variant`] | 3 | the same scene file with some keys changed |
//! | [`scale`] | 3 | a scene made larger or smaller: rounding at every scale |
//! | [`rayset`] | 6 | ray sets in the Embree benchmark's format, traced against a mesh |

pub mod convergence;
pub mod reference;
pub mod scale;
pub mod variant;

#[cfg(feature = "s6")]
pub mod rayset;
