//! The page's words: a message of the program's catalogue (`messages/*/page.ftl`),
//! in the page's language, with its arguments, for the demos and the check page,
//! which load the module on the page's own thread for this alone.

use raycourse::messages::language::Language;
use raycourse::messages::{Argument, say};
use wasm_bindgen::prelude::*;

/// The message `id` in `language` (`en` or `fr`, as the page's `lang` starts), with
/// `arguments`, a JSON object of texts and numbers (`{"stage": "glass", "size":
/// 256}`); a number is written as the language writes it, and an argument that is
/// neither is dropped.
#[wasm_bindgen]
pub fn message(language: &str, id: &str, arguments: &str) -> String {
    let language = Language::from_locale(language);
    let object: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(arguments).unwrap_or_default();
    let arguments: Vec<(&str, Argument)> = object
        .iter()
        .filter_map(|(name, value)| Some((name.as_str(), argument(value)?)))
        .collect();
    say(language, id, &arguments)
}

/// A JSON value as a message's argument: a text or a number.
fn argument(value: &serde_json::Value) -> Option<Argument<'static>> {
    match value {
        serde_json::Value::String(text) => Some(text.clone().into()),
        serde_json::Value::Number(number) => number.as_f64().map(Into::into),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raycourse::messages::catalogue::has;

    #[test]
    fn a_page_message_takes_its_arguments_as_json() {
        let arguments = r#"{"stage": "glass", "size": 256, "samples": 1, "time": "84 ms"}"#;
        assert_eq!(
            message("en", "page-pass", arguments),
            "glass, 256 × 256: 1 sample per pixel in 84 ms"
        );
        let arguments = r#"{"stage": "glass", "size": 256, "samples": 50, "time": "3,2 s"}"#;
        assert_eq!(
            message("fr", "page-pass", arguments),
            "glass, 256 × 256\u{a0}: 50 échantillons par pixel en 3,2 s"
        );
        assert_eq!(
            message("fr", "page-seconds", r#"{"seconds": 3.21}"#),
            "3,2\u{a0}s"
        );
    }

    /// Every message id the page's scripts name (`"page-..."`) is in the catalogue,
    /// in every language.
    #[test]
    fn every_message_the_pages_name_is_in_the_catalogue() {
        let scripts = [
            include_str!("../../book/src/live/workers.js"),
            include_str!("../../book/src/live/demo.js"),
            include_str!("../../book/src/live/check.js"),
        ];
        let ids: Vec<&str> = scripts
            .iter()
            .flat_map(|script| script.split('"').skip(1).step_by(2))
            .filter(|text| text.starts_with("page-"))
            .collect();
        assert!(ids.len() > 50, "{} ids", ids.len());
        for language in Language::ALL {
            for id in &ids {
                assert!(has(language, id), "{id} in {language:?}");
            }
        }
    }
}
