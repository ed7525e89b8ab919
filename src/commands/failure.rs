//! What can go wrong when a command runs, and its exit code.

use std::path::Path;

use raycourse::messages::language::Language;
use raycourse::messages::say;

/// Why a command failed: its input (exit code 2, as for clap's usage errors), the
/// machine (exit code 1), or an image that is not the stage's (exit code 1, after
/// `check`'s report has said why). The message is one line that says what and
/// where.
#[derive(Debug, thiserror::Error)]
pub enum Failure {
    /// A scene, a file or an argument that cannot be used.
    #[error("{0}")]
    Input(String),
    /// A scene file that cannot be used, said in the reader's language when shown.
    #[error("{0}")]
    Scene(raycourse::SceneError),
    /// Something the machine could not do: start threads, write a file.
    #[error("{0}")]
    Machine(String),
    /// A checked image that differs from the stage's; the report printed before
    /// says how, so the message is empty.
    #[allow(
        dead_code,
        reason = "`check`, which finds such an image, comes with session 7"
    )]
    #[error("")]
    Differs,
}

impl Failure {
    /// A bad input, described by `error`.
    pub fn input(error: impl std::fmt::Display) -> Failure {
        Failure::Input(error.to_string())
    }

    /// The file at `path` that could not be written.
    pub fn write(path: &Path, error: std::io::Error) -> Failure {
        Failure::Machine(format!(
            "{}: cannot write the file: {error}",
            path.display()
        ))
    }

    /// The exit code: 2 for bad input, 1 for a failure of the machine or an image
    /// that differs.
    pub fn exit_code(&self) -> std::process::ExitCode {
        match self {
            Failure::Input(_) | Failure::Scene(_) => std::process::ExitCode::from(2),
            Failure::Machine(_) | Failure::Differs => std::process::ExitCode::FAILURE,
        }
    }

    /// The failure's line on the standard error, in `language`: `error: ` and why.
    pub fn said(&self, language: Language) -> String {
        let why = match self {
            Failure::Scene(error) => error.say(language),
            other => other.to_string(),
        };
        say(language, "command-error", &[("why", why.into())])
    }
}

impl From<raycourse::SceneError> for Failure {
    fn from(error: raycourse::SceneError) -> Failure {
        Failure::Scene(error)
    }
}

impl From<clap::Error> for Failure {
    fn from(error: clap::Error) -> Failure {
        Failure::input(error)
    }
}
