//! What can go wrong when a command runs, and its exit code.

use std::path::Path;

use raycourse::messages::language::Language;
use raycourse::messages::said::Said;
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
    /// A bad input, said in the reader's language when shown: a message of the
    /// catalogue with its arguments.
    #[error("{0}")]
    Refused(Said),
    /// Something the machine could not do, said in the reader's language when
    /// shown.
    #[error("{0}")]
    Broke(Said),
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
        let said = Said::new("command-cannot-write")
            .with("file", path.display().to_string())
            .with("why", error.to_string());
        Failure::Broke(said)
    }

    /// The exit code: 2 for bad input, 1 for a failure of the machine or an image
    /// that differs.
    pub fn exit_code(&self) -> std::process::ExitCode {
        match self {
            Failure::Input(_) | Failure::Scene(_) | Failure::Refused(_) => {
                std::process::ExitCode::from(2)
            }
            Failure::Broke(_) | Failure::Differs => std::process::ExitCode::FAILURE,
        }
    }

    /// The failure's line on the standard error, in `language`: `error: ` and why.
    pub fn said(&self, language: Language) -> String {
        let why = match self {
            Failure::Scene(error) => error.say(language),
            Failure::Refused(said) | Failure::Broke(said) => said.say(language),
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
