//! Errors in scene files: each one names the file, the key and what was expected.

use std::path::PathBuf;

/// Why a scene could not be loaded. Its message is one line that names the file,
/// the key (and the line and column where TOML knows them) and what was expected.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("{}: cannot read the scene file: {source}", path.display())]
    Read {
        /// The scene file.
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
    /// The file is not valid TOML, or a value is of the wrong type or out of range.
    #[error("{}:{line}:{column}: {}{message}", path.display(), key_prefix(key))]
    Invalid {
        /// The scene file.
        path: PathBuf,
        /// Line of the offending text, from 1.
        line: usize,
        /// Column of the offending text, from 1.
        column: usize,
        /// Dotted path of the key, such as `spheres[2].radius`; empty for a syntax error.
        key: String,
        /// What was wrong and what was expected.
        message: String,
    },
    /// A value is acceptable on its own but not together with the others.
    #[error("{}: key `{key}`: {message}", path.display())]
    Inconsistent {
        /// The scene file.
        path: PathBuf,
        /// Dotted path of the key.
        key: String,
        /// What was wrong and what was expected.
        message: String,
    },
    /// A file the scene refers to (a mesh, a texture) cannot be used.
    #[error("{}: {message} (referred to by {})", file.display(), scene.display())]
    Asset {
        /// The scene file.
        scene: PathBuf,
        /// The mesh or texture file.
        file: PathBuf,
        /// What is wrong with it.
        message: String,
    },
    /// The scene asks for something that a later course session brings.
    #[error("{}: key `{key}`: {what} {remedy}", path.display())]
    NeedsFeature {
        /// The scene file.
        path: PathBuf,
        /// Dotted path of the key.
        key: String,
        /// What the scene asked for.
        what: String,
        /// Which session brings it, and how to get it
        /// ([`comes_with`](crate::scene_file::features::comes_with)).
        remedy: String,
    },
}

/// `text` on one line: every run of whitespace that holds a line break becomes one
/// space, so that messages from libraries keep the one-line error format.
pub fn one_line(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn key_prefix(key: &str) -> String {
    if key.is_empty() || key == "." {
        String::new()
    } else {
        format!("key `{key}`: ")
    }
}
