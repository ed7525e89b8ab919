//! `cargo xtask messages [--accept]`: the program's message catalogue (`messages/`),
//! complete and current in every language, as the book's translation check holds
//! the book's. English (`messages/en/`) is the source. Every other language must
//! have the same files, each without a syntax error, with every English message and
//! attribute and no other, each using only arguments that the English is given
//! (`$share`; it may leave one out, as French leaves out a stage's English title), and each
//! translated from the English as it is now: `messages/<code>/translated-from.toml`
//! records a fingerprint of the English each message was translated from, so an
//! English change makes its translations stale until a translator updates them and
//! records them with `--accept` (gettext's "fuzzy").

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

use fluent_syntax::ast::{Entry, Expression, InlineExpression, Pattern, PatternElement};

/// A catalogue file's messages: `id` or `id.attribute`, with the arguments it uses
/// and the fingerprint of its text.
type Messages = BTreeMap<String, (BTreeSet<String>, String)>;

/// The name of each language's record of the English its messages translate.
const RECORD: &str = "translated-from.toml";

/// Checks every language of `root/messages` against English; with `accept`, first
/// records every message as translated from the English as it is now.
pub fn check(root: &Path, accept: bool) -> Result<(), String> {
    let folder = root.join("messages");
    let english = language(&folder.join("en"))?;
    let mut problems = vec![];
    for code in codes(&folder)?.into_iter().filter(|c| c != "en") {
        let path = folder.join(&code);
        let translated = language(&path)?;
        if accept {
            write_record(&path.join(RECORD), &english, &translated)?;
        }
        let record = read_record(&path.join(RECORD))?;
        problems.extend(compare(&code, &english, &translated, &record));
    }
    if problems.is_empty() {
        println!("messages: every language has every English message, current");
        return Ok(());
    }
    for problem in problems.iter().take(30) {
        eprintln!("{problem}");
    }
    Err(format!(
        "messages: {} problems (the first 30 above); once a translation is updated, \
         record it with `cargo xtask messages --accept`",
        problems.len()
    ))
}

/// What differs between a language's messages and English's, one line each.
fn compare(
    code: &str,
    english: &BTreeMap<String, Messages>,
    translated: &BTreeMap<String, Messages>,
    record: &BTreeMap<String, String>,
) -> Vec<String> {
    let mut problems = vec![];
    for (file, messages) in english {
        let place = format!("messages/{code}/{file}");
        let Some(theirs) = translated.get(file) else {
            problems.push(format!("{place}: missing (English has messages/en/{file})"));
            continue;
        };
        for (id, (arguments, fingerprint)) in messages {
            match theirs.get(id) {
                None => problems.push(format!("{place}: {id}: untranslated")),
                Some((used, _)) if !used.is_subset(arguments) => problems.push(format!(
                    "{place}: {id}: uses the arguments {used:?}, English gives {arguments:?}"
                )),
                Some(_) if record.get(id) != Some(fingerprint) => {
                    problems.push(format!("{place}: {id}: stale, the English changed since"));
                }
                Some(_) => {}
            }
        }
        for id in theirs.keys().filter(|id| !messages.contains_key(*id)) {
            problems.push(format!("{place}: {id}: not an English message (obsolete?)"));
        }
    }
    for file in translated.keys().filter(|f| !english.contains_key(*f)) {
        problems.push(format!("messages/{code}/{file}: no such English file"));
    }
    problems
}

/// The language folders of the catalogue.
fn codes(folder: &Path) -> Result<Vec<String>, String> {
    let entries = fs::read_dir(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    let mut codes: Vec<String> = entries
        .filter_map(Result::ok)
        .filter(|e| e.path().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    codes.sort();
    Ok(codes)
}

/// The messages of each `.ftl` file of a language's folder, by file name.
fn language(folder: &Path) -> Result<BTreeMap<String, Messages>, String> {
    let mut files = BTreeMap::new();
    let entries = fs::read_dir(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    for path in entries.filter_map(Result::ok).map(|e| e.path()) {
        if path.extension().is_some_and(|e| e == "ftl") {
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            files.insert(name, messages(&path)?);
        }
    }
    Ok(files)
}

/// The messages of one file; `Err` for a file that does not parse whole.
fn messages(path: &Path) -> Result<Messages, String> {
    let text = fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    parsed(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// The messages of a file's text; `Err` names the first syntax error.
fn parsed(text: &str) -> Result<Messages, String> {
    let resource = fluent_syntax::parser::parse(text)
        .map_err(|(_, errors)| format!("not Fluent: {:?}", errors.first()))?;
    let mut messages = Messages::new();
    for entry in resource.body {
        let Entry::Message(message) = entry else {
            continue;
        };
        let id = message.id.name;
        if let Some(value) = &message.value {
            messages.insert(id.to_owned(), described(value));
        }
        for attribute in &message.attributes {
            let key = format!("{id}.{}", attribute.id.name);
            messages.insert(key, described(&attribute.value));
        }
    }
    Ok(messages)
}

/// A pattern's arguments and fingerprint (CRC-32 of its parsed form, comments aside).
fn described(pattern: &Pattern<&str>) -> (BTreeSet<String>, String) {
    let mut arguments = BTreeSet::new();
    for element in &pattern.elements {
        if let PatternElement::Placeable { expression } = element {
            expression_arguments(expression, &mut arguments);
        }
    }
    let fingerprint = crc32fast::hash(format!("{pattern:?}").as_bytes());
    (arguments, format!("{fingerprint:08x}"))
}

/// Adds the arguments an expression uses to `arguments`.
fn expression_arguments(expression: &Expression<&str>, arguments: &mut BTreeSet<String>) {
    match expression {
        Expression::Inline(inline) => inline_arguments(inline, arguments),
        Expression::Select { selector, variants } => {
            inline_arguments(selector, arguments);
            for variant in variants {
                for element in &variant.value.elements {
                    if let PatternElement::Placeable { expression } = element {
                        expression_arguments(expression, arguments);
                    }
                }
            }
        }
    }
}

/// Adds the arguments an inline expression uses to `arguments`.
fn inline_arguments(inline: &InlineExpression<&str>, arguments: &mut BTreeSet<String>) {
    match inline {
        InlineExpression::VariableReference { id } => {
            arguments.insert(id.name.to_owned());
        }
        InlineExpression::FunctionReference {
            arguments: call, ..
        } => {
            for argument in &call.positional {
                inline_arguments(argument, arguments);
            }
        }
        InlineExpression::Placeable { expression } => expression_arguments(expression, arguments),
        _ => {}
    }
}

/// A language's record: each message's fingerprint of the English it translates.
fn read_record(path: &Path) -> Result<BTreeMap<String, String>, String> {
    let Ok(text) = fs::read_to_string(path) else {
        return Ok(BTreeMap::new());
    };
    let table: toml_edit::DocumentMut = text
        .parse()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(table
        .iter()
        .filter_map(|(id, value)| Some((id.to_owned(), value.as_str()?.to_owned())))
        .collect())
}

/// Records every message that `translated` has as translated from `english` as it is.
fn write_record(
    path: &Path,
    english: &BTreeMap<String, Messages>,
    translated: &BTreeMap<String, Messages>,
) -> Result<(), String> {
    let mut text = String::from(
        "# The fingerprint of the English each message here translates, written by\n\
         # `cargo xtask messages --accept` once the translation is up to date.\n",
    );
    for (file, messages) in english {
        let theirs = translated.get(file);
        for (id, (_, fingerprint)) in messages {
            if theirs.is_some_and(|t| t.contains_key(id)) {
                text.push_str(&format!("\"{id}\" = \"{fingerprint}\"\n"));
            }
        }
    }
    fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One file, `check.ftl`, holding `text`.
    fn catalogue(text: &str) -> BTreeMap<String, Messages> {
        BTreeMap::from([("check.ftl".to_owned(), parsed(text).unwrap())])
    }

    #[test]
    fn a_translation_is_missing_obsolete_stale_or_with_other_arguments() {
        let english = catalogue("a = one { $x }\nb = two\n    .hint = three\nc = four\n");
        let french = catalogue("a = un { $y }\nb = deux\nd = cinq\n");
        let mut record: BTreeMap<String, String> = BTreeMap::new();
        for (id, (_, fingerprint)) in &english["check.ftl"] {
            record.insert(id.clone(), fingerprint.clone());
        }
        record.insert("b".into(), "00000000".into());
        let problems = compare("fr", &english, &french, &record);
        let expected = [
            "a: uses the arguments {\"y\"}, English gives {\"x\"}",
            "b: stale, the English changed since",
            "b.hint: untranslated",
            "c: untranslated",
            "d: not an English message (obsolete?)",
        ];
        assert_eq!(problems.len(), expected.len(), "{problems:#?}");
        for (problem, end) in problems.iter().zip(expected) {
            assert_eq!(problem, &format!("messages/fr/check.ftl: {end}"));
        }
    }

    #[test]
    fn a_file_that_is_not_fluent_is_refused() {
        assert!(parsed("a = { $x\n").unwrap_err().starts_with("not Fluent"));
    }
}
