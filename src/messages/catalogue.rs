//! The catalogue: the Fluent files of each language, read once, and each message
//! formatted with its arguments. The library's messages are read from [`FILES`];
//! a program with messages of its own reads them beside those into a [`Catalogue`].
//!
//! A message is named by an id (`check-matches`), or an id and an attribute
//! (`mistake-no-gamma.hint`), and given its arguments by name:
//! `say(language, "check-place", &[("place", name.into()), ("share", 12.5.into())])`.

use std::sync::OnceLock;

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::types::{FluentNumber, FluentNumberOptions};
use fluent_bundle::{FluentArgs, FluentResource, FluentValue};
use unic_langid::LanguageIdentifier;

use crate::messages::language::Language;
use crate::messages::numbers;

/// A message's argument: a text, or a number that the message writes as its
/// language does.
pub type Argument<'a> = FluentValue<'a>;

/// The catalogue's files: each language's, by file name, in `messages/<code>/`.
/// English is the source; every other language holds the same messages.
pub const FILES: &[(Language, &[(&str, &str)])] = &[
    (
        Language::English,
        &[
            ("check.ftl", include_str!("../../messages/en/check.ftl")),
            ("page.ftl", include_str!("../../messages/en/page.ftl")),
            ("plot.ftl", include_str!("../../messages/en/plot.ftl")),
            ("probe.ftl", include_str!("../../messages/en/probe.ftl")),
            ("render.ftl", include_str!("../../messages/en/render.ftl")),
            ("scene.ftl", include_str!("../../messages/en/scene.ftl")),
        ],
    ),
    (
        Language::French,
        &[
            ("check.ftl", include_str!("../../messages/fr/check.ftl")),
            ("page.ftl", include_str!("../../messages/fr/page.ftl")),
            ("plot.ftl", include_str!("../../messages/fr/plot.ftl")),
            ("probe.ftl", include_str!("../../messages/fr/probe.ftl")),
            ("render.ftl", include_str!("../../messages/fr/render.ftl")),
            ("scene.ftl", include_str!("../../messages/fr/scene.ftl")),
        ],
    ),
];

/// The messages of one language, read from its files: the library's ([`FILES`]),
/// and any a program adds (the exercises' checklist adds its own).
pub struct Catalogue {
    /// Its language.
    language: Language,
    /// Fluent's bundle of its files' messages.
    bundle: FluentBundle<FluentResource>,
}

impl Catalogue {
    /// Reads `files` (name and text) of `language` into one catalogue. Messages are
    /// written as they are, without Unicode's direction marks around the arguments
    /// (English and French both run left to right), with Fluent's functions
    /// (`NUMBER`), and numbers written by [`numbers::write`]. The files are the
    /// program's own, compiled in and held by the catalogue's tests: one that is not
    /// Fluent, or repeats a message, is a bug of the program, and panics.
    pub fn new(language: Language, files: &[(&str, &str)]) -> Catalogue {
        let code: LanguageIdentifier = language.code().parse().expect("a language code");
        let mut bundle = FluentBundle::new_concurrent(vec![code]);
        bundle.set_use_isolating(false);
        bundle.set_formatter(Some(numbers::write));
        bundle
            .add_builtins()
            .expect("Fluent's functions (NUMBER) added once");
        for (file, text) in files {
            let place = format!("messages/{}/{file}", language.code());
            let resource = FluentResource::try_new(text.to_string())
                .unwrap_or_else(|(_, errors)| panic!("{place}: {errors:?}"));
            bundle
                .add_resource(resource)
                .unwrap_or_else(|errors| panic!("{place}: {errors:?}"));
        }
        Catalogue { language, bundle }
    }

    /// Whether the catalogue has the message `id` (or `id.attribute`).
    pub fn has(&self, id: &str) -> bool {
        let (name, attribute) = split(id);
        let message = self.bundle.get_message(name);
        message.is_some_and(|m| attribute.is_none_or(|a| m.get_attribute(a).is_some()))
    }

    /// The message `id` (or `id.attribute`) with `arguments`. A message missing
    /// from the catalogue is written as its id, which the catalogue's tests make
    /// sure never happens.
    pub fn say(&self, id: &str, arguments: &[(&str, Argument)]) -> String {
        let (name, attribute) = split(id);
        let message = self.bundle.get_message(name);
        let pattern = message.and_then(|m| match attribute {
            None => m.value(),
            Some(attribute) => m.get_attribute(attribute).map(|a| a.value()),
        });
        let Some(pattern) = pattern else {
            debug_assert!(false, "{id}: no such message in {:?}", self.language);
            return id.to_owned();
        };
        let arguments: FluentArgs = arguments.iter().cloned().collect();
        let mut errors = Vec::new();
        let text = self
            .bundle
            .format_pattern(pattern, Some(&arguments), &mut errors);
        debug_assert!(errors.is_empty(), "{id} in {:?}: {errors:?}", self.language);
        text.into_owned()
    }
}

/// A message's id and attribute: `mistake-no-gamma.hint` is `mistake-no-gamma` and
/// `hint`.
fn split(id: &str) -> (&str, Option<&str>) {
    id.split_once('.').map_or((id, None), |(n, a)| (n, Some(a)))
}

/// Whether the library's catalogue of `language` has the message `id`.
pub fn has(language: Language, id: &str) -> bool {
    library(language).has(id)
}

/// The message `id` of the library's catalogue in `language`, with `arguments`.
pub fn say(language: Language, id: &str, arguments: &[(&str, Argument)]) -> String {
    library(language).say(id, arguments)
}

/// A number written with exactly `decimals` decimals and no digit grouping, as
/// the message's language writes it (`0.50`, `0,50`): for figures whose digits
/// the program chose.
pub fn decimals(value: f64, decimals: usize) -> Argument<'static> {
    fixed(value, decimals, false)
}

/// A number written with exactly `decimals` decimals and its digits grouped as the
/// message's language groups them (`1,950,868.5`, `1 950 868,5`): for tables of
/// figures the program chose.
pub fn grouped(value: f64, decimals: usize) -> Argument<'static> {
    fixed(value, decimals, true)
}

/// A number with exactly `decimals` decimals, its digits grouped if `grouping`.
fn fixed(value: f64, decimals: usize, grouping: bool) -> Argument<'static> {
    let options = FluentNumberOptions {
        minimum_fraction_digits: Some(decimals),
        maximum_fraction_digits: Some(decimals),
        use_grouping: grouping,
        ..FluentNumberOptions::default()
    };
    FluentValue::Number(FluentNumber::new(value, options))
}

/// The library's catalogue of `language`, read on first use.
fn library(language: Language) -> &'static Catalogue {
    static CATALOGUES: [OnceLock<Catalogue>; 2] = [OnceLock::new(), OnceLock::new()];
    CATALOGUES[language as usize].get_or_init(|| Catalogue::new(language, files(language)))
}

/// The library's catalogue of `language` with a program's own file `name`, whose
/// text in each language `own` gives (the checklist's `checklist.ftl`, the book's
/// tools' `book.ftl`).
pub fn with_own(language: Language, name: &str, own: &[(Language, &str)]) -> Catalogue {
    let mut all = files(language).to_vec();
    all.extend(
        own.iter()
            .filter(|(l, _)| *l == language)
            .map(|(_, text)| (name, *text)),
    );
    Catalogue::new(language, &all)
}

/// The files of `language`.
pub fn files(language: Language) -> &'static [(&'static str, &'static str)] {
    FILES
        .iter()
        .find(|(l, _)| *l == language)
        .map_or(&[], |(_, files)| files)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The brightness line with the ratios `red`, `green` and `blue`.
    fn brightness(language: Language, [red, green, blue]: [f64; 3]) -> String {
        let arguments = [
            ("red", red.into()),
            ("green", green.into()),
            ("blue", blue.into()),
        ];
        say(language, "check-brightness", &arguments)
    }

    #[test]
    fn numbers_take_the_language_s_decimal_mark_grouping_and_decimals() {
        let ratios = [1.5, 1234.5678, 0.005];
        let english = brightness(Language::English, ratios);
        assert!(
            english.ends_with("red x1.50, green x1,234.57, blue x0.01"),
            "{english}"
        );
        let french = brightness(Language::French, ratios);
        assert!(
            french.ends_with("rouge ×\u{a0}1,50, vert ×\u{a0}1\u{202f}234,57, bleu ×\u{a0}0,01"),
            "{french}"
        );
    }

    #[test]
    fn a_message_chooses_its_words_by_its_arguments() {
        let unit = |cell: u32| say(Language::French, "check-unit", &[("cell", cell.into())]);
        assert_eq!(unit(1), "des pixels");
        assert_eq!(unit(8), "des blocs de 8 × 8 pixels");
    }

    #[test]
    fn attributes_are_messages_of_their_own() {
        let hint = say(Language::French, "mistake-no-gamma.hint", &[]);
        assert!(
            hint.ends_with("écrivez min(255, L^(1/2,2)), et non min(255, L)"),
            "{hint}"
        );
    }
}
