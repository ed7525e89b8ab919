//! Checking a student's image of a stage: is it the stage's image, and if not, what
//! differs, where, and which classic mistake explains it. The comparison serves
//! every session (the exercises' checklist compares each stage with its reference
//! image); the `check` command, which grades images made elsewhere, comes with the
//! whole crate (session 7).
//!
//! | file | what it holds |
//! |---|---|
//! | [`expected`] | the stage's reference images at the student's size, cached |
//! | [`compare`] | the comparison: per pixel for deterministic stages, per block of pixels, against the noise, for Monte Carlo ones |
//! | [`regions`] | which object each pixel shows, to say where the differences are |
//! | [`mistakes`] | the classic mistakes, each as the image it would make |
//! | [`report`] | the verdict, the figures behind it and the hint |
//! | [`wording`] | the report in words, as `check` prints it |
//! | [`grading`] | a student's folder or a class graded, and the grading sheet |

pub mod compare;
#[cfg(feature = "s7")]
pub mod expected;
#[cfg(feature = "s7")]
pub mod grading;
#[cfg(feature = "s7")]
pub mod mistakes;
#[cfg(feature = "s7")]
pub mod regions;
#[cfg(feature = "s7")]
pub mod report;
#[cfg(feature = "s7")]
pub mod wording;
