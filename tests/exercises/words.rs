//! The checklist's language: English, or French, the course's own, as `--lang fr`
//! or the environment's locale (`LANG=fr_FR.UTF-8`) asks, the same way as `check`.

use std::sync::OnceLock;

use raycourse::messages::catalogue::{Argument, Catalogue, decimals, with_own};
use raycourse::messages::language::Language;

/// The language chosen once, at the start of the run.
static LANGUAGE: OnceLock<Language> = OnceLock::new();

/// Chooses the checklist's language: `--lang en|fr` among `args` when given,
/// otherwise the environment's. `Err` names what `--lang` was given instead.
pub fn choose(args: &[String]) -> Result<(), String> {
    let language = match args.iter().position(|a| a == "--lang") {
        None => Language::from_environment(),
        Some(at) => match args.get(at + 1).map(String::as_str) {
            Some("en") => Language::English,
            Some("fr") => Language::French,
            other => {
                return Err(format!(
                    "--lang: expected en or fr, got {}",
                    other.unwrap_or("nothing")
                ));
            }
        },
    };
    LANGUAGE.get_or_init(|| language);
    Ok(())
}

/// Whether the checklist speaks French.
pub fn french() -> bool {
    LANGUAGE.get().copied().unwrap_or_default() == Language::French
}

/// The checklist's own messages, beside the library's: `messages/<code>/checklist.ftl`.
const CHECKLIST: [(Language, &str); 2] = [
    (
        Language::English,
        include_str!("../../messages/en/checklist.ftl"),
    ),
    (
        Language::French,
        include_str!("../../messages/fr/checklist.ftl"),
    ),
];

/// The catalogue in the checklist's language, read on first use.
fn catalogue() -> &'static Catalogue {
    static CATALOGUE: OnceLock<Catalogue> = OnceLock::new();
    CATALOGUE.get_or_init(|| {
        let language = LANGUAGE.get().copied().unwrap_or_default();
        with_own(language, "checklist.ftl", &CHECKLIST)
    })
}

/// The message `id` of the catalogue in the checklist's language, with `arguments`.
pub fn message(id: &str, arguments: &[(&str, Argument)]) -> String {
    catalogue().say(id, arguments)
}

/// A value as a message's argument: its text, as the checklist wrote it.
pub fn text(value: &impl std::fmt::Display) -> Argument<'static> {
    value.to_string().into()
}

/// A message of the catalogue in the checklist's language:
/// `say!("generated-s2-l-gamma", radiance = n(radiance), gamma = n(gamma))`, each
/// argument named as the message names it.
#[macro_export]
macro_rules! say {
    ($id:literal $(, $name:ident = $value:expr)* $(,)?) => {
        $crate::words::message($id, &[$((stringify!($name), $crate::words::text(&$value))),*])
    };
}

/// A number's text, its digits as the checklist chose them, with the decimal mark
/// of the language, written by the catalogue: `0.50`, or `0,50` in French;
/// `1.5e-4`, or `1,5e-4`.
pub fn decimal(text: String) -> String {
    let (mantissa, exponent) = match text.split_once('e') {
        Some((mantissa, exponent)) => (mantissa, Some(exponent)),
        None => (text.as_str(), None),
    };
    let (Some((_, fraction)), Ok(value)) = (mantissa.split_once('.'), mantissa.parse::<f64>())
    else {
        return text;
    };
    let written = message(
        "checklist-number",
        &[("value", decimals(value, fraction.len()))],
    );
    match exponent {
        Some(exponent) => format!("{written}e{exponent}"),
        None => written,
    }
}

/// The separator between a vector's components: `, ` in English, ` ; ` in French,
/// where the comma is the decimal mark.
pub fn separator() -> String {
    message("checklist-separator", &[])
}
