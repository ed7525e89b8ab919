//! Errors in scene files: each one names the file, the key and what was expected,
//! in the reader's language (the catalogue's `scene.ftl`).

use std::fmt::{self, Display, Formatter};
use std::path::PathBuf;

use crate::messages::language::Language;
use crate::messages::said::Said;

/// Why a scene could not be loaded. Its message is one line that names the file,
/// the key (and the line and column where TOML knows them) and what was expected;
/// [`SceneError::say`] writes it in a language, `Display` in English.
#[derive(Debug)]
pub enum SceneError {
    /// The file could not be read.
    Read {
        /// The scene file.
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
    /// The file is not valid TOML, or a value is of the wrong type or out of range.
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
    Inconsistent {
        /// The scene file.
        path: PathBuf,
        /// Dotted path of the key.
        key: String,
        /// What was wrong and what was expected.
        message: Said,
    },
    /// A file the scene refers to (a mesh, a texture) cannot be used.
    Asset {
        /// The scene file.
        scene: PathBuf,
        /// The mesh or texture file.
        file: PathBuf,
        /// What is wrong with it.
        message: Said,
    },
    /// The scene asks for something that a later course session brings.
    NeedsFeature {
        /// The scene file.
        path: PathBuf,
        /// Dotted path of the key.
        key: String,
        /// What the scene asked for: a message of the catalogue's `scene.ftl`
        /// (`scene-part-mirror`).
        what: &'static str,
        /// Which session brings it, and how to get it
        /// ([`comes_with`](crate::scene_file::features::comes_with)).
        remedy: Said,
    },
}

/// `text` on one line: every run of whitespace that holds a line break becomes one
/// space, so that messages from libraries keep the one-line error format.
pub fn one_line(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

impl SceneError {
    /// The error's one line in `language`. The file, the line, the column and the
    /// key are named as they are; what the TOML reader says of a value is its own
    /// English, but for the words of serde's messages that the catalogue knows
    /// and those of the scene file's own rules.
    pub fn say(&self, language: Language) -> String {
        match self {
            SceneError::Read { path, source } => said("scene-cannot-read", path)
                .with("why", source.to_string())
                .say(language),
            SceneError::Invalid {
                path,
                line,
                column,
                key,
                message,
            } => {
                let id = if key.is_empty() || key == "." {
                    "scene-invalid"
                } else {
                    "scene-invalid-key"
                };
                said(id, path)
                    .with("line", line.to_string())
                    .with("column", column.to_string())
                    .with("key", key.as_str())
                    .with("message", serde_words(message, language))
                    .say(language)
            }
            SceneError::Inconsistent { path, key, message } => said("scene-inconsistent", path)
                .with("key", key.as_str())
                .with("message", message.say(language))
                .say(language),
            SceneError::Asset {
                scene,
                file,
                message,
            } => said("scene-asset", file)
                .with("scene", scene.display().to_string())
                .with("message", message.say(language))
                .say(language),
            SceneError::NeedsFeature {
                path,
                key,
                what,
                remedy,
            } => said("scene-needs-feature", path)
                .with("key", key.as_str())
                .with("what", Said::new(what).say(language))
                .with("remedy", remedy.say(language))
                .say(language),
        }
    }
}

/// The message `id` about the file at `path`, its first argument `file`.
fn said(id: &'static str, path: &std::path::Path) -> Said {
    Said::new(id).with("file", path.display().to_string())
}

/// What serde said of a key, with the words of its messages about fields in
/// `language` (`unknown field `colour`, expected one of `albedo`, ...`, `missing
/// field `radius``); any other message as serde wrote it.
fn serde_words(message: &str, language: Language) -> String {
    let after = |prefix: &str| message.strip_prefix(prefix)?.split_once('`');
    let said = if let Some((name, rest)) = after("unknown field `") {
        match rest.strip_prefix(", expected one of ") {
            Some(fields) => Said::new("scene-unknown-field").with("expected", fields),
            None => return message.to_owned(),
        }
        .with("field", name)
    } else if let Some((name, "")) = after("missing field `") {
        Said::new("scene-missing-field").with("field", name)
    } else if let Some(said) = value_rule(message) {
        said
    } else {
        return message.to_owned();
    };
    said.say(language)
}

/// The messages of the scene file's rules for a value ([`crate::maths::values`]),
/// each ending in the value found.
const VALUE_RULES: [&str; 6] = [
    "scene-not-finite",
    "scene-not-positive",
    "scene-negative",
    "scene-not-probability",
    "scene-not-angle",
    "scene-not-albedo",
];

/// The catalogue's message of a value's rule that `message` (written by
/// [`crate::maths::values`], in English) breaks, with the value found; `None` for
/// any other message.
pub fn value_rule(message: &str) -> Option<Said> {
    VALUE_RULES.iter().find_map(|&id| {
        let start = Said::new(id).with("value", "").say(Language::English);
        let value = message.strip_prefix(&start)?;
        Some(Said::new(id).with("value", value))
    })
}

impl Display for SceneError {
    fn fmt(&self, f: &mut Formatter) -> fmt::Result {
        f.write_str(&self.say(Language::English))
    }
}

impl std::error::Error for SceneError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SceneError::Read { source, .. } => Some(source),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maths::Real;
    use crate::maths::values::{Albedo, Degrees, NonNegative, Positive, Probability};
    use crate::scene_file::features::{Made, remedy};

    #[test]
    fn every_rule_of_a_value_is_in_the_catalogue() {
        let messages = [
            Positive::try_from(Real::NAN).unwrap_err(),
            Positive::try_from(-1.0).unwrap_err(),
            NonNegative::try_from(-1.0).unwrap_err(),
            Probability::try_from(2.0).unwrap_err(),
            Degrees::try_from(180.0).unwrap_err(),
            Albedo::try_from([0.5, 2.0, 0.5]).unwrap_err(),
        ];
        for (message, id) in messages.iter().zip(VALUE_RULES) {
            let said = value_rule(message).unwrap_or_else(|| panic!("{message}"));
            assert_eq!(said.id, id);
            assert_eq!(&said.say(Language::English), message);
        }
        let french = value_rule(&messages[1]).unwrap().say(Language::French);
        assert_eq!(french, "nombre supérieur à 0 attendu, trouvé -1");
    }

    #[test]
    fn a_part_of_a_later_session_is_named_in_each_language() {
        let error = SceneError::NeedsFeature {
            path: PathBuf::from("room.toml"),
            key: "spheres[0].material".into(),
            what: "scene-part-mirror",
            remedy: remedy(Made::Features, 2, 1),
        };
        assert_eq!(
            error.to_string(),
            "room.toml: key `spheres[0].material`: a mirror material needs feature s2: \
             cargo run --features s2 -- ..."
        );
        assert_eq!(
            error.say(Language::French),
            "room.toml: clé `spheres[0].material`\u{a0}: un matériau miroir demande la \
             fonctionnalité s2\u{a0}: cargo run --features s2 -- ..."
        );
    }
}
