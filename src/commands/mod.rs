//! The commands of `raycourse`, one file each, and what they share: the options of
//! a render, its progress bar and closing line, and the failures they report.

pub mod failure;
pub mod job;
pub mod options;
pub mod output;
pub mod pipe;

pub mod bench;
pub mod figures;
pub mod list;
pub mod probe;
pub mod render;
pub mod stage;

#[cfg(feature = "beyond")]
pub mod beyond;
#[cfg(feature = "beyond")]
pub mod beyond_options;
#[cfg(feature = "plots")]
pub mod converge;
#[cfg(feature = "plots")]
pub mod plot;
#[cfg(feature = "beyond")]
pub mod rays;

#[cfg(feature = "s7")]
pub mod animate;
#[cfg(feature = "s7")]
pub mod check;

use clap::ArgMatches;

use failure::Failure;

/// A command: its place in the help, its arguments as clap describes them, and
/// what it does with them.
#[derive(Clone, Copy)]
pub struct Verb {
    /// Where it stands in `raycourse --help`: the commonest first.
    pub rank: u32,
    /// Its name, help and arguments.
    pub command: fn() -> clap::Command,
    /// Runs it on the arguments given.
    pub run: fn(&ArgMatches) -> Result<(), Failure>,
}

inventory::collect!(Verb);

/// Every command of this build but the sessions' own (`s1` to `s7`), in the order
/// of their rank. Each command's file registers it; the files of later sessions'
/// commands are only compiled in those sessions' builds.
pub fn verbs() -> Vec<Verb> {
    let mut verbs: Vec<Verb> = inventory::iter::<Verb>.into_iter().copied().collect();
    verbs.sort_by_key(|v| v.rank);
    verbs
}
