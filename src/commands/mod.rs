//! The commands of `raycourse`, one file each, and what they share: the options of
//! a render, its progress bar and closing line, and the failures they report.

pub mod failure;
pub mod options;
pub mod output;

pub mod animate;
pub mod bench;
pub mod figures;
pub mod list;
pub mod render;
pub mod stage;

#[cfg(feature = "s3")]
pub mod converge;
#[cfg(feature = "s3")]
pub mod plot;

#[cfg(feature = "s6")]
pub mod rays;

#[cfg(feature = "s7")]
pub mod check;

use clap::ArgMatches;

use failure::Failure;

/// A command: the session that brings it, its arguments as clap describes them, and
/// what it does with them.
#[derive(Clone, Copy)]
pub struct Verb {
    /// The first session whose build has the command.
    pub session: u32,
    /// Its name, help and arguments.
    pub command: fn() -> clap::Command,
    /// Runs it on the arguments given.
    pub run: fn(&ArgMatches) -> Result<(), Failure>,
}

/// Every command of this build but the sessions' own (`s1` to `s7`).
pub fn verbs() -> Vec<Verb> {
    let verbs = vec![
        list::VERB,
        render::VERB,
        figures::VERB,
        bench::VERB,
        animate::VERB,
    ];
    #[cfg(feature = "s3")]
    let verbs = [verbs, vec![converge::VERB, plot::VERB]].concat();
    #[cfg(feature = "s6")]
    let verbs = [verbs, vec![rays::VERB]].concat();
    #[cfg(feature = "s7")]
    let verbs = [verbs, vec![check::VERB]].concat();
    verbs
        .into_iter()
        .filter(|v| v.session <= raycourse::scene_file::SESSION)
        .collect()
}
