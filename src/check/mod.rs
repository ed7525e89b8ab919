//! Checking a student's image of a stage (beyond the course's sessions, with the
//! whole crate): is it the stage's image, and if not, what differs, where, and which
//! classic mistake explains it.
//!
//! | file | what it holds |
//! |---|---|
//! | [`expected`] | the stage's reference images at the student's size, cached |
//! | [`compare`] | the comparison: per pixel for deterministic stages, per block of pixels, against the noise, for Monte Carlo ones |
//! | [`regions`] | which object each pixel shows, to say where the differences are |
//! | [`mistakes`] | the classic mistakes, each as the image it would make |
//! | [`report`] | the verdict, the figures behind it and the hint |

pub mod compare;
pub mod expected;
pub mod mistakes;
pub mod regions;
pub mod report;

pub use report::{Report, Verdict, check};
