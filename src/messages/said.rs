//! A message to say later: its id and its arguments, kept until the reader's
//! language is known. The library makes a scene file's errors; the command that
//! shows one knows the language (`--lang`, or the environment's).

use crate::messages::catalogue::{Argument, Catalogue, say};
use crate::messages::language::Language;

/// One argument of a message kept for later: a text, or a number that the
/// message writes as its language does.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A text, written as it is.
    Text(String),
    /// A number.
    Number(f64),
}

impl From<String> for Value {
    fn from(text: String) -> Value {
        Value::Text(text)
    }
}

impl From<&str> for Value {
    fn from(text: &str) -> Value {
        Value::Text(text.to_owned())
    }
}

impl From<u64> for Value {
    fn from(number: u64) -> Value {
        Value::Number(number as f64)
    }
}

impl From<f64> for Value {
    fn from(number: f64) -> Value {
        Value::Number(number)
    }
}

/// A message of the library's catalogue with its arguments, not yet said.
#[derive(Clone, Debug, PartialEq)]
pub struct Said {
    /// The message's id, such as `scene-too-many-pixels`.
    pub id: &'static str,
    /// Its arguments, by name.
    pub arguments: Vec<(&'static str, Value)>,
}

impl Said {
    /// The message `id`, with no arguments yet.
    pub fn new(id: &'static str) -> Said {
        Said {
            id,
            arguments: Vec::new(),
        }
    }

    /// The message with the argument `name` set to `value` too.
    pub fn with(mut self, name: &'static str, value: impl Into<Value>) -> Said {
        self.arguments.push((name, value.into()));
        self
    }

    /// The message in `language`, from the library's catalogue.
    pub fn say(&self, language: Language) -> String {
        say(language, self.id, &self.arguments())
    }

    /// The message from `catalogue`, a program's own (the library's files and its).
    pub fn say_from(&self, catalogue: &Catalogue) -> String {
        catalogue.say(self.id, &self.arguments())
    }

    /// Its arguments as the catalogue takes them, by name.
    fn arguments(&self) -> Vec<(&str, Argument<'_>)> {
        self.arguments
            .iter()
            .map(|(name, value)| {
                let argument = match value {
                    Value::Text(text) => Argument::from(text.as_str()),
                    Value::Number(number) => Argument::from(*number),
                };
                (*name, argument)
            })
            .collect()
    }
}

/// Written in a format (`probe --json`) as its English text: a format's words stay
/// one language, as its keys do.
impl serde::Serialize for Said {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(&self.to_string())
    }
}

/// The message in English, the catalogue's source.
impl std::fmt::Display for Said {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(&self.say(Language::English))
    }
}
