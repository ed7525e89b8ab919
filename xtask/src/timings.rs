//! `{{#timings FILE}}`: a table that `raycourse bench` printed, kept in `book/src/`
//! as it was measured. The English edition shows it as it is; the French one shows
//! the same figures in French: its words translated, decimal commas, thousands
//! grouped, a non-breaking space before a unit.

/// The table's English words, those of `bench`'s header and of the settings'
/// summary (`Scene::summary`), with their French; the longer first where one holds
/// another.
const WORDS: &[(&str, &str)] = &[
    ("course's code", "code du cours"),
    ("speed-up", "accélération"),
    ("settings", "réglages"),
    ("stage", "étape"),
    ("Mrays/s", "Mrayons/s"),
    ("rays", "rayons"),
    ("course", "cours"),
    ("about", "environ"),
    ("spp", "éch./pixel"),
    ("bounces", "rebonds"),
    ("shadows", "ombres"),
    ("light sampling", "échantillonnage de la lumière"),
    ("Russian roulette", "roulette russe"),
];

/// The non-breaking space French puts before a unit and between groups of digits.
const NBSP: char = '\u{a0}';

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
    for (english, french) in WORDS {
        text = replace_words(&text, english, french);
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
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut k = 0;
    while k < chars.len() {
        if !chars[k].is_ascii_digit() {
            out.push(chars[k]);
            k += 1;
            continue;
        }
        let start = k;
        while k < chars.len() && (chars[k].is_ascii_digit() || chars[k] == '.') {
            k += 1;
        }
        let number: String = chars[start..k].iter().collect();
        out += &french_number(&number);
        match (chars.get(k), chars.get(k + 1)) {
            (Some('x'), Some(next)) if next.is_ascii_digit() => {
                out += &format!("{NBSP}×{NBSP}");
                k += 1;
            }
            (Some('x'), _) => {
                out.push('×');
                k += 1;
            }
            (Some(' '), Some('s')) => {
                out.push(NBSP);
                k += 1;
            }
            _ => {}
        }
    }
    out
}

/// `number` (digits, perhaps a decimal point) with a decimal comma, and its whole
/// part in groups of three digits from four digits on.
fn french_number(number: &str) -> String {
    let (whole, decimals) = match number.split_once('.') {
        Some((whole, decimals)) => (whole, Some(decimals)),
        None => (number, None),
    };
    let mut grouped = String::new();
    for (k, digit) in whole.chars().enumerate() {
        if k > 0 && whole.len() >= 4 && (whole.len() - k).is_multiple_of(3) {
            grouped.push(NBSP);
        }
        grouped.push(digit);
    }
    match decimals {
        Some(decimals) => format!("{grouped},{decimals}"),
        None => grouped,
    }
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
                        | `bvh` (15) | 512\u{a0}×\u{a0}512, 50 éch./pixel, 5 rebonds, gamma 2,2, indirect, échantillonnage de la lumière | 16,93\u{a0}s | 156\u{a0}073\u{a0}262 | 9,22 | environ 60\u{a0}s | 9,53\u{a0}s | 1,78× |\n";
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
        assert_eq!(french_number("123"), "123");
        assert_eq!(french_number("5856"), "5\u{a0}856");
    }
}
