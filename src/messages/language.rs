//! The language `check` speaks: English, or French, the course's own language, as
//! the environment's locale (`LANG=fr_FR.UTF-8`) or `--lang fr` asks.

/// A language of the checker's report.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Language {
    /// English, the default.
    #[default]
    English,
    /// French.
    French,
}

impl Language {
    /// Every language of the catalogue, English (the source) first.
    pub const ALL: [Language; 2] = [Language::English, Language::French];

    /// The language's code, as locales and the catalogue's folders name it.
    pub fn code(self) -> &'static str {
        match self {
            Language::English => "en",
            Language::French => "fr",
        }
    }

    /// The language of a locale or a language code: French for `fr`, `fr_FR.UTF-8`,
    /// `fr-CA` and the like, English for anything else.
    pub fn from_locale(locale: &str) -> Language {
        let code = locale.split(['_', '-', '.', '@']).next().unwrap_or("");
        if code.eq_ignore_ascii_case("fr") {
            Language::French
        } else {
            Language::English
        }
    }

    /// The language of the environment, as POSIX programs find their messages' one:
    /// the first of `LC_ALL`, `LC_MESSAGES` and `LANG` that is set and not empty.
    pub fn from_environment() -> Language {
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .iter()
            .filter_map(|name| std::env::var(name).ok())
            .find(|value| !value.is_empty())
            .map_or(Language::English, |locale| Language::from_locale(&locale))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn french_locales_are_french_and_the_rest_english() {
        for locale in ["fr", "fr_FR.UTF-8", "fr-CA", "FR_be@euro"] {
            assert_eq!(Language::from_locale(locale), Language::French, "{locale}");
        }
        for locale in ["", "C", "C.UTF-8", "en_GB.UTF-8", "fy_NL", "french"] {
            assert_eq!(Language::from_locale(locale), Language::English, "{locale}");
        }
    }
}
