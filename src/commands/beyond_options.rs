//! The command line's options beyond the course: adaptive sampling and its map, and
//! the fast engine. A file of their own, which needs no other command's, so that a
//! render's options (`options.rs`) can hold them.

use std::path::PathBuf;

use clap::Args;
use raycourse::maths::Real;
use raycourse::scene_file::beyond::BeyondOverrides;

/// A render's settings beyond the course.
#[derive(Args, Clone, Debug, Default)]
pub struct BeyondArgs {
    /// Adaptive sampling: each pixel takes samples until the estimated relative
    /// standard error of its mean is below this (such as 0.02), up to 4 times `--spp`.
    #[arg(long)]
    pub noise: Option<Real>,
    /// Also write a grey PNG of the samples each pixel took, black for the fewest
    /// and white for the most.
    #[arg(long)]
    pub noise_map: Option<PathBuf>,
    /// Render with the fast engine, beyond the course: the same image as the
    /// course's functions give, in less time; an edit of a course function does not
    /// show in it.
    #[arg(long)]
    pub fast: bool,
}

impl BeyondArgs {
    /// The scene-file settings beyond the course that these options replace.
    pub fn overrides(&self) -> BeyondOverrides {
        BeyondOverrides {
            noise: self.noise,
            fast: self.fast,
        }
    }
}
