//! The book's formulas, kept whole through the translation, as two mdBook
//! preprocessors (`cargo xtask mdbook-formulas hide|show`).
//!
//! mdbook-gettext rebuilds every chapter it translates from its Markdown events, and
//! Markdown takes TeX apart: `t\,d` loses its backslash, `[X]` gains two, a line that
//! starts with `-` is escaped. `hide` (before gettext, and before the xgettext
//! renderer extracts the messages) turns each formula into a code span, which
//! Markdown keeps as it is: `$O + t\,d$` becomes `` `$O + t\,d$` `` (a formula written
//! on several lines is joined into one); `show` (after gettext, before katex) turns
//! those spans back into formulas. A formula is found where mdbook-katex finds it:
//! `$$...$$` or `$...$` outside code spans, a backslash escaping the next character.
//! Both leave an English book alone (no `po/LANG.po` for its `book.language`), so it
//! is exactly what mdBook and mdbook-katex make without them.

use std::path::Path;

use serde_json::Value;

/// Reads mdBook's `[context, book]` from stdin and writes the book to stdout, its
/// formulas hidden (`hide`) or shown again (`show`) when the build is translated.
pub fn preprocess(mode: &str) -> Result<(), String> {
    let change: fn(&str, &str) -> Result<String, String> = match mode {
        "hide" => hide,
        "show" => |text, _| Ok(show(text)),
        _ => return Err(format!("`{mode}`: expected hide or show")),
    };
    let (context, mut book) = crate::preprocessor::read()?;
    if translated(&context) {
        chapters(&mut book, change)?;
    }
    println!("{book}");
    Ok(())
}

/// Whether mdbook-gettext translates this build: the xgettext renderer's messages,
/// or a `book.language` with its `po/LANG.po`.
fn translated(context: &Value) -> bool {
    if context["renderer"] == "xgettext" {
        return true;
    }
    let root = context["root"].as_str().unwrap_or(".");
    context["config"]["book"]["language"]
        .as_str()
        .is_some_and(|language| Path::new(root).join(format!("po/{language}.po")).exists())
}

/// Applies `change` to the content of every chapter under `item`, with the chapter's
/// path for messages.
fn chapters(
    item: &mut Value,
    change: fn(&str, &str) -> Result<String, String>,
) -> Result<(), String> {
    match item {
        Value::Object(map) => {
            if let Some(Value::Object(chapter)) = map.get_mut("Chapter") {
                let place = chapter
                    .get("path")
                    .or(chapter.get("name"))
                    .and_then(Value::as_str)
                    .unwrap_or("a chapter")
                    .to_owned();
                if let Some(Value::String(content)) = chapter.get_mut("content") {
                    *content = change(content, &place)?;
                }
            }
            map.values_mut().try_for_each(|v| chapters(v, change))
        }
        Value::Array(items) => items.iter_mut().try_for_each(|v| chapters(v, change)),
        _ => Ok(()),
    }
}

/// `text` (the chapter at `place`) with each formula made a code span.
fn hide(text: &str, place: &str) -> Result<String, String> {
    if !hidden(text).is_empty() {
        return Err(format!(
            "{place}: a code span `$...$` would be taken for a hidden formula: write it another way"
        ));
    }
    let mut out = String::new();
    let mut last = 0;
    for (start, end) in formulas(text) {
        let formula = &text[start..end];
        if formula.contains('`') {
            return Err(format!("{place}: a formula holds a backtick: {formula}"));
        }
        out += &text[last..start];
        out += "`";
        out += &formula.split('\n').collect::<Vec<_>>().join(" ");
        out += "`";
        last = end;
    }
    Ok(out + &text[last..])
}

/// `text` with each code span that holds a formula made that formula.
fn show(text: &str) -> String {
    let mut out = String::new();
    let mut last = 0;
    for (start, end, inner) in hidden(text) {
        out += &text[last..start];
        out += &text[inner.0..inner.1];
        last = end;
    }
    out + &text[last..]
}

/// The code spans of `text` whose text is a formula, `$` to `$` with no backtick:
/// each span's start and end, and its text's.
fn hidden(text: &str) -> Vec<(usize, usize, (usize, usize))> {
    let bytes = text.as_bytes();
    let mut spans = vec![];
    let mut i = 0;
    while let Some(open) = text[i..].find('`').map(|k| i + k) {
        let run = backticks(bytes, open);
        let Some(close) = closing(bytes, open + run, run) else {
            break;
        };
        let inner = &text[open + run..close];
        if inner.len() >= 2
            && inner.starts_with('$')
            && inner.ends_with('$')
            && !inner.contains('`')
        {
            spans.push((open, close + run, (open + run, close)));
        }
        i = close + run;
    }
    spans
}

/// The length of the run of backticks at `at`.
fn backticks(bytes: &[u8], at: usize) -> usize {
    bytes[at..].iter().take_while(|&&b| b == b'`').count()
}

/// Where a run of exactly `run` backticks starts, from `from` on: the end of a code
/// span opened by such a run.
fn closing(bytes: &[u8], from: usize, run: usize) -> Option<usize> {
    let mut j = from;
    while j < bytes.len() {
        if bytes[j] == b'`' {
            let length = backticks(bytes, j);
            if length == run {
                return Some(j);
            }
            j += length;
        } else {
            j += 1;
        }
    }
    None
}

/// The start and end of each formula of `text`, its delimiters included, found as
/// mdbook-katex's scanner finds them: `$$...$$` or `$...$`, not inside code spans, a
/// backslash escaping the next character.
fn formulas(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut found = vec![];
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'$' => {
                let delimiter = if text[i..].starts_with("$$") {
                    "$$"
                } else {
                    "$"
                };
                let Some(end) = formula_end(text, i + delimiter.len(), delimiter) else {
                    return found;
                };
                found.push((i, end));
                i = end;
            }
            b'\\' => i += 2,
            b'`' => {
                let run = backticks(bytes, i);
                let Some(close) = closing(bytes, i + run, run) else {
                    return found;
                };
                i = close + run;
            }
            _ => i += 1,
        }
    }
    found
}

/// The end of a formula opened by `delimiter`, whose text starts at `from`: just past
/// the first `delimiter` not escaped by a backslash.
fn formula_end(text: &str, from: usize, delimiter: &str) -> Option<usize> {
    let mut j = from;
    loop {
        let k = j + text[j..].find(delimiter)?;
        let backslashes = text[..k].len() - text[..k].trim_end_matches('\\').len();
        if backslashes.is_multiple_of(2) {
            return Some(k + delimiter.len());
        }
        j = k + delimiter.len();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_cross_as_code_spans_and_come_back() {
        let text = "A ray $O + t\\,d$ and\n$$\n[X] = -1\n$$ cost `$5` and \\$3.";
        let hidden = hide(text, "test").unwrap();
        assert_eq!(
            hidden,
            "A ray `$O + t\\,d$` and\n`$$ [X] = -1 $$` cost `$5` and \\$3."
        );
        assert_eq!(
            show(&hidden),
            "A ray $O + t\\,d$ and\n$$ [X] = -1 $$ cost `$5` and \\$3."
        );
    }

    #[test]
    fn a_code_span_that_looks_hidden_is_refused() {
        let error = hide("see `$x$` here", "book/x.md").unwrap_err();
        assert!(error.starts_with("book/x.md: a code span"), "{error}");
    }

    #[test]
    fn only_spans_of_a_whole_formula_are_shown() {
        assert_eq!(show("``$a$`` and `$b` and `c$`"), "$a$ and `$b` and `c$`");
    }
}
