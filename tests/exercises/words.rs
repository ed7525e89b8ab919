//! The checklist's language: English, or French, the course's own, as `--lang fr`
//! or the environment's locale (`LANG=fr_FR.UTF-8`) asks, the same way as `check`.

use std::sync::OnceLock;

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

/// A message in the checklist's language: `say!("english {x}", "français {x}")`,
/// each a format string with the same arguments.
#[macro_export]
macro_rules! say {
    ($english:literal, $french:literal $(, $arg:expr)* $(,)?) => {
        if $crate::words::french() {
            format!($french $(, $arg)*)
        } else {
            format!($english $(, $arg)*)
        }
    };
}

/// A number's text with the language's decimal mark: `0.5`, or `0,5` in French.
pub fn decimal(text: String) -> String {
    if french() {
        text.replace('.', ",")
    } else {
        text
    }
}

/// The separator between a vector's components: `, ` in English, ` ; ` in French,
/// where the comma is the decimal mark.
pub fn separator() -> &'static str {
    if french() { "\u{a0}; " } else { ", " }
}
