//! `{{#timings FILE}}`: a table that `raycourse bench` printed, kept in `book/src/`
//! as it was measured. The English edition shows it as it is; the French one shows
//! the same figures in French: its words translated, decimal commas, thousands
//! grouped, a non-breaking space before a unit, all from the book's catalogue
//! (`messages/<code>/book.ftl`, numbers written by its library).

use raycourse::messages::catalogue::{Argument, grouped};
use raycourse::messages::language::Language;

use crate::words::catalogue;

/// The table's words, those of `bench`'s header and of the settings' summary
/// (`Scene::summary`): messages of the book's catalogue (`bench-*`), the longer
/// first where one holds another.
const WORDS: &[&str] = &[
    "bench-course-s-code",
    "bench-speed-up",
    "bench-settings",
    "bench-stage",
    "bench-mrays",
    "bench-rays",
    "bench-course",
    "bench-about",
    "bench-spp",
    "bench-bounces",
    "bench-shadows",
    "bench-light-sampling",
    "bench-russian-roulette",
];

/// `table` as the edition in `language` shows it: as it is in English, in French
/// otherwise ([`french`]).
pub fn in_language(table: &str, language: Language) -> String {
    match language {
        Language::English => table.to_owned(),
        Language::French => french(table),
    }
}

/// The lines of `table` in French, cell by cell; code spans (stage names, options)
/// are left as they are.
pub fn french(table: &str) -> String {
    table
        .lines()
        .map(|line| {
            if line.starts_with("|---") {
                return line.to_owned();
            }
            line.split('|')
                .map(|cell| {
                    if cell.contains('`') {
                        cell.to_owned()
                    } else {
                        cell_in_french(cell)
                    }
                })
                .collect::<Vec<_>>()
                .join("|")
        })
        .map(|line| line + "\n")
        .collect()
}

/// One cell in French: its words, then its numbers.
fn cell_in_french(cell: &str) -> String {
    let mut text = cell.to_owned();
    for id in WORDS {
        let english = catalogue(Language::English).say(id, &[]);
        let french = catalogue(Language::French).say(id, &[]);
        text = replace_words(&text, &english, &french);
    }
    numbers_in_french(&text)
}

/// `text` with `english` replaced by `french` where it stands as whole words.
fn replace_words(text: &str, english: &str, french: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find(english) {
        let before = rest[..at].chars().next_back();
        let after = rest[at + english.len()..].chars().next();
        let whole =
            !before.is_some_and(char::is_alphanumeric) && !after.is_some_and(char::is_alphanumeric);
        out += &rest[..at];
        out += if whole { french } else { english };
        rest = &rest[at + english.len()..];
    }
    out + rest
}

/// `text` with each number written the French way: `71.41 s` as `71,41 s`,
/// `1950868` as `1 950 868`, `128x128` as `128 × 128` and the speed-up `1.78x` as
/// `1,78×`.
fn numbers_in_french(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(start) = rest.find(|c: char| c.is_ascii_digit()) {
        out += &rest[..start];
        let (number, after) = number_at(&rest[start..]);
        let say = |id: &str, arguments: &[(&str, Argument)]| {
            catalogue(Language::French).say(id, arguments)
        };
        rest = if let Some((height, after)) = after
            .strip_prefix('x')
            .filter(|a| a.starts_with(|c: char| c.is_ascii_digit()))
            .map(number_at)
        {
            out += &say("bench-size", &[("width", number), ("height", height)]);
            after
        } else if let Some(after) = after.strip_prefix('x') {
            out += &say("bench-speed-up-times", &[("value", number)]);
            after
        } else if let Some(after) = after.strip_prefix(" s") {
            out += &say("bench-seconds", &[("value", number)]);
            after
        } else {
            out += &say("bench-number", &[("value", number)]);
            after
        };
    }
    out + rest
}

/// The number at the start of `text` (digits, perhaps a decimal point), with as
/// many decimals as it was written with, and the text after it.
fn number_at(text: &str) -> (Argument<'static>, &str) {
    let end = text
        .find(|c: char| !c.is_ascii_digit() && c != '.')
        .unwrap_or(text.len());
    let digits = &text[..end];
    let decimals = digits.split_once('.').map_or(0, |(_, d)| d.len());
    let value = digits.parse().unwrap_or(f64::NAN);
    (grouped(value, decimals), &text[end..])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A header, a rule and a row of `bench 5 6 7`'s table, in French: every word
    /// translated, every number written the French way, the stage left as code.
    #[test]
    fn a_bench_table_reads_in_french() {
        let table = "| stage | settings | course's code | rays | Mrays/s | course | `--fast` | speed-up |\n\
                     |---|---|---|---|---|---|---|---|\n\
                     | `bvh` (15) | 512x512, 50 spp, 5 bounces, gamma 2.2, indirect, light sampling | 16.93 s | 156073262 | 9.22 | about 60 s | 9.53 s | 1.78x |\n";
        let expected = "| étape | réglages | code du cours | rayons | Mrayons/s | cours | `--fast` | accélération |\n\
                        |---|---|---|---|---|---|---|---|\n\
                        | `bvh` (15) | 512\u{a0}×\u{a0}512, 50 éch./pixel, 5 rebonds, gamma 2,2, indirect, échantillonnage de la lumière | 16,93\u{a0}s | 156\u{202f}073\u{202f}262 | 9,22 | environ 60\u{a0}s | 9,53\u{a0}s | 1,78× |\n";
        assert_eq!(french(table), expected);
    }

    /// A word inside another is not replaced: `course` in `course's code` is the
    /// phrase's, and `rays` in `Mrays/s` the unit's.
    #[test]
    fn only_whole_words_are_replaced() {
        assert_eq!(
            replace_words("courses, course", "course", "cours"),
            "courses, cours"
        );
        assert_eq!(numbers_in_french("123"), "123");
        assert_eq!(numbers_in_french("5856 and 2.50"), "5\u{202f}856 and 2,50");
    }
}
