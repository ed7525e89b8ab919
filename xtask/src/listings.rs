//! The book's listings, as an mdBook preprocessor: `{{#listing sN FILE ANCHOR}}`
//! in a chapter becomes the code between `// ANCHOR: ANCHOR` and
//! `// ANCHOR_END: ANCHOR` in FILE of the view of session N, captioned with its
//! file; the lines it gained in session N, found by comparing with the view of
//! session N - 1, end with `// +`. The views are written afresh into
//! `target/book-views/` each time the book is built, so a listing shows exactly
//! what a student has after that session: no gate, no later session's code.
//! `{{#listing beyond FILE ANCHOR}}`, for the appendices, takes the code from the
//! crate itself: what goes beyond the course is in no view.
//!
//! `{{#exercises sN}}` becomes the table of session N's exercises, read from their
//! markers in the view's code (see [`crate::exercise`]) and their checklist lines
//! from `tests/exercises/sN.rs`; the French edition names each exercise with the
//! French title the checklist's catalogue gives it (`exercise-sN-K` of
//! `messages/fr/checklist.ftl`, as `cargo test -- --lang fr` says it).
//! `{{#timings FILE}}` becomes the table `raycourse bench` printed into
//! `book/src/FILE`, in French in the French edition ([`crate::timings`]),
//! `{{#output NAME}}` what the program printed, in the edition's language
//! (`book/src/outputs/CODE/NAME.txt`), and the
//! entries between `{{#sorted}}` and `{{#sorted-end}}` are put in the order of their
//! terms in the edition's language ([`crate::glossary`]).
//!
//! An image alone on its line, `![Figure 1: a white disk](figures/white-disk.png)`,
//! becomes a figure whose text is shown under it as its caption (and kept as the
//! image's `alt` text).

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use raycourse::messages::language::Language;
use serde_json::Value;

use crate::view::write_view;

/// Reads mdBook's `[context, book]` from stdin, writes the book with its listings
/// filled in to stdout.
pub fn preprocess(root: &Path) -> Result<(), String> {
    let views = root.join("target/book-views");
    for n in 1..=crate::cfg::last_session() {
        write_view(root, n, &views.join(format!("s{n}")))?;
    }
    let (context, mut book) = crate::preprocessor::read()?;
    let language = context["config"]["book"]["language"].as_str();
    let words = &Words::of(Language::from_locale(language.unwrap_or("en")));
    let mut seen = HashSet::new();
    let places = Places {
        views,
        src: root.join("book/src"),
    };
    walk(&mut book, &places, words, &mut seen)?;
    println!("{book}");
    Ok(())
}

/// The words the preprocessor writes around the code, in the book's language,
/// from the book's catalogue (`messages/<code>/book.ftl`).
struct Words {
    /// The edition's language: it names the exercises (by their checklist entry's
    /// French title in French, their marker's English one otherwise), writes the
    /// `bench` tables and chooses the folder of the outputs.
    language: Language,
    /// A listing's session, before its number.
    session: String,
    /// After a listing's session: the lines it gained are marked.
    gained: String,
    /// After a listing's session: the code is the session before's.
    unchanged: String,
    /// In place of a session: the code goes beyond the course.
    beyond: String,
    /// The exercises table's header.
    header: String,
    /// Between two functions of one exercise.
    and: String,
}

impl Words {
    /// The words of the edition in `language`.
    fn of(language: Language) -> Words {
        let say = |id: &str| crate::words::catalogue(language).say(id, &[]);
        Words {
            language,
            session: say("book-session"),
            gained: say("book-gained"),
            unchanged: say("book-unchanged"),
            beyond: say("book-beyond"),
            header: say("book-exercises-header"),
            and: say("book-and"),
        }
    }
}

/// Where the preprocessor reads what it fills in.
struct Places {
    /// The session views, `target/book-views/sN/`.
    views: PathBuf,
    /// The book's chapters, `book/src/`, beside which the `bench` tables are kept.
    src: PathBuf,
}

/// Fills the listings of every chapter under `value`.
fn walk(
    value: &mut Value,
    places: &Places,
    words: &Words,
    seen: &mut HashSet<String>,
) -> Result<(), String> {
    match value {
        Value::Object(map) => {
            if let Some(Value::Object(chapter)) = map.get_mut("Chapter")
                && let Some(Value::String(content)) = chapter.get_mut("content")
            {
                *content = fill(content, places, words, seen)?;
            }
            map.values_mut()
                .try_for_each(|v| walk(v, places, words, seen))
        }
        Value::Array(items) => items
            .iter_mut()
            .try_for_each(|v| walk(v, places, words, seen)),
        _ => Ok(()),
    }
}

/// `content` with each `{{#listing ...}}` replaced by its listing, each
/// `{{#exercises ...}}` by its table and each `{{#timings ...}}` by its `bench` table,
/// and each `{{#sorted}}` block sorted.
fn fill(
    content: &str,
    places: &Places,
    words: &Words,
    seen: &mut HashSet<String>,
) -> Result<String, String> {
    let listings = crate::directive::replace(content, "listing", |directive| {
        if !seen.insert(directive.to_owned()) {
            return Err(format!("listing `{directive}` is shown twice in the book"));
        }
        listing(directive, &places.views, words)
    })?;
    let tables = exercise_tables(&listings, &places.views, words)?;
    let tables = timing_tables(&tables, &places.src, words)?;
    let outputs = outputs(&tables, &places.src, words)?;
    Ok(captioned(&crate::glossary::sorted(&outputs)?))
}

/// `content` with each image alone on its line made a `<figure>` with a visible
/// `<figcaption>` (outside code blocks). A small image can be shown larger with its
/// pixels kept square: the title `"pixelated WIDTH"`, as in
/// `![Figure 13: a mesh](figures/mesh.png "pixelated 384")`, shows it WIDTH pixels
/// wide.
fn captioned(content: &str) -> String {
    let mut fenced = false;
    let mut out = String::new();
    for line in content.split_inclusive('\n') {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        }
        match image_line(line.trim()).filter(|_| !fenced) {
            Some(Image {
                text,
                source,
                pixelated,
            }) => {
                let text = escape(text);
                let size = pixelated.map_or(String::new(), |width| {
                    format!(" width=\"{width}\" style=\"image-rendering: pixelated\"")
                });
                out += &format!(
                    "\n<figure>\n<img src=\"{source}\" alt=\"{text}\"{size}>\n<figcaption>{text}</figcaption>\n</figure>\n\n"
                );
            }
            None => out += line,
        }
    }
    out
}

/// An image alone on its line: `![text](source)`, or `![text](source "pixelated
/// WIDTH")`.
struct Image<'a> {
    /// Its text, the caption and the `alt` text.
    text: &'a str,
    /// Its file.
    source: &'a str,
    /// The width it is shown at, its pixels kept square, if its title asks.
    pixelated: Option<u32>,
}

/// The image `line` is, if it is one image alone.
fn image_line(line: &str) -> Option<Image<'_>> {
    let inner = line.strip_prefix("![")?.strip_suffix(')')?;
    let (text, target) = inner.rsplit_once("](")?;
    let (source, pixelated) = match target.split_once(' ') {
        None => (target, None),
        Some((source, title)) => {
            let width = title.strip_prefix("\"pixelated ")?.strip_suffix('"')?;
            (source, Some(width.parse().ok()?))
        }
    };
    Some(Image {
        text,
        source,
        pixelated,
    })
}

/// Text made safe for HTML, inside an attribute or an element.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// `content` with each `{{#exercises sN}}` replaced by session N's table.
fn exercise_tables(content: &str, views: &Path, words: &Words) -> Result<String, String> {
    crate::directive::replace(content, "exercises", |session| {
        exercise_table(crate::session(session)?, views, words)
    })
}

/// `content` with each `{{#timings FILE}}` replaced by the `bench` table kept in
/// `src/FILE`, in the edition's language ([`crate::timings`]).
fn timing_tables(content: &str, src: &Path, words: &Words) -> Result<String, String> {
    crate::directive::replace(content, "timings", |file| {
        let file = src.join(file);
        let table = std::fs::read_to_string(&file)
            .map_err(|e| format!("the timings {}: {e}", file.display()))?;
        Ok(crate::timings::in_language(&table, words.language))
    })
}

/// `content` with each `{{#output NAME}}` replaced by what the program printed in
/// this edition's language, kept in `src/outputs/CODE/NAME.txt` by the scripts that
/// run it (`book/outputs.sh` for `check`, `.ci/exercises` for the checklist).
fn outputs(content: &str, src: &Path, words: &Words) -> Result<String, String> {
    crate::directive::replace(content, "output", |name| {
        let file = src.join(format!("outputs/{}/{name}.txt", words.language.code()));
        let text = std::fs::read_to_string(&file)
            .map_err(|e| format!("the output {}: {e}", file.display()))?;
        Ok(text.trim_end().to_owned())
    })
}

/// The table of session `n`'s exercises: number, what it computes, the function
/// and its file, the checklist's line.
fn exercise_table(n: u32, views: &Path, words: &Words) -> Result<String, String> {
    let view = views.join(format!("s{n}"));
    let checks = std::fs::read_to_string(view.join(format!("tests/exercises/s{n}.rs")))
        .map_err(|e| format!("the checklist of session {n}: {e}"))?;
    let mut rows: Vec<(crate::exercise::Marker, String)> = vec![];
    for file in crate::exercise::rust_files_below(&view.join("src"))? {
        let text = std::fs::read_to_string(&file).map_err(|e| e.to_string())?;
        let relative = file
            .strip_prefix(&view)
            .unwrap_or(&file)
            .display()
            .to_string();
        for marker in crate::exercise::markers(&text)? {
            if marker.session == n {
                rows.push((marker, relative.clone()));
            }
        }
    }
    rows.sort_by_key(|(m, _)| crate::exercise::order(&m.id));
    let mut table = format!("{}\n|---|---|---|---|---|\n", words.header);
    let mut i = 0;
    while i < rows.len() {
        let id = rows[i].0.id.clone();
        let group: Vec<&(crate::exercise::Marker, String)> =
            rows[i..].iter().take_while(|(m, _)| m.id == id).collect();
        let functions: Vec<String> = group
            .iter()
            .map(|(m, _)| format!("`{}`", m.function))
            .collect();
        let prefix = format!("name: \"{}_", id.replace('.', "_"));
        let line = checks
            .lines()
            .find_map(|l| {
                l.trim()
                    .strip_prefix("name: \"")
                    .filter(|_| l.trim().starts_with(&prefix))
            })
            .map(|l| l.trim_end_matches("\",").to_owned())
            .ok_or_else(|| format!("exercise {id} has no line in tests/exercises/s{n}.rs"))?;
        let title = if words.language == Language::French {
            french_title(&view, &id).ok_or_else(|| {
                format!("exercise {id} has no French title in messages/fr/checklist.ftl")
            })?
        } else {
            group[0].0.title.clone()
        };
        table += &format!(
            "| {id} | {title} | {} | `{}` | `{line}` |\n",
            functions.join(&words.and),
            group[0].1
        );
        i += group.len();
    }
    Ok(table)
}

/// The French title of exercise `id` (`s1.2`), as the checklist's catalogue in the
/// view gives it (`exercise-s1-2` of `messages/fr/checklist.ftl`).
fn french_title(view: &Path, id: &str) -> Option<String> {
    use fluent_syntax::ast::{Entry, PatternElement};
    let text = std::fs::read_to_string(view.join("messages/fr/checklist.ftl")).ok()?;
    let resource = fluent_syntax::parser::parse(text.as_str()).ok()?;
    let wanted = format!("exercise-{}", id.replace('.', "-"));
    resource.body.iter().find_map(|entry| match entry {
        Entry::Message(m) if m.id.name == wanted => {
            let elements = &m.value.as_ref()?.elements;
            let texts = elements.iter().map(|e| match e {
                PatternElement::TextElement { value } => Some(*value),
                PatternElement::Placeable { .. } => None,
            });
            texts.collect::<Option<String>>()
        }
        _ => None,
    })
}

/// The listing of `sN FILE ANCHOR`: caption, then the code.
fn listing(directive: &str, views: &Path, words: &Words) -> Result<String, String> {
    let parts: Vec<&str> = directive.split_whitespace().collect();
    let [session, file, anchor] = parts[..] else {
        return Err(format!(
            "`{{{{#listing {directive}}}}}`: expected sN FILE ANCHOR, or beyond FILE ANCHOR"
        ));
    };
    if session == "beyond" {
        // The views are in `target/book-views/` of the crate.
        let root = views.ancestors().nth(2).unwrap_or(views);
        let code = anchored(&root.join(file), anchor)?
            .ok_or_else(|| format!("no anchor `{anchor}` in {file}"))?;
        let beyond = &words.beyond;
        return Ok(format!(
            "<p class=\"listing-caption\"><code>{file}</code> ({beyond})</p>\n\n```rust,ignore\n{code}```\n"
        ));
    }
    let n: u32 = session
        .strip_prefix('s')
        .and_then(|n| n.parse().ok())
        .filter(|n| (1..=crate::cfg::last_session()).contains(n))
        .ok_or_else(|| format!("`{session}` is not a session of the course"))?;
    let path = |n: u32| -> PathBuf { views.join(format!("s{n}")).join(file) };
    let code = anchored(&path(n), anchor)?
        .ok_or_else(|| format!("no anchor `{anchor}` in {file} of session {n}"))?;
    let before = match n {
        1 => None,
        _ => anchored(&path(n - 1), anchor)?,
    };
    let (code, note) = match before {
        Some(before) if before != code => (mark_gained(&before, &code), words.gained.as_str()),
        Some(_) => (code, words.unchanged.as_str()),
        None => (code, ""),
    };
    let session = &words.session;
    Ok(format!(
        "<p class=\"listing-caption\"><code>{file}</code> ({session} {n}{note})</p>\n\n```rust,ignore\n{code}```\n"
    ))
}

/// The lines between `// ANCHOR: anchor` and `// ANCHOR_END: anchor` in `file`,
/// without other anchor lines and without their common indentation; `None` when
/// the file or the anchor is absent.
fn anchored(file: &Path, anchor: &str) -> Result<Option<String>, String> {
    let Ok(text) = std::fs::read_to_string(file) else {
        return Ok(None);
    };
    let start = format!("ANCHOR: {anchor}");
    let end = format!("ANCHOR_END: {anchor}");
    let mut inside = false;
    let mut lines = vec![];
    for line in text.lines() {
        let trimmed = line.trim();
        if trimmed.ends_with(&start) && trimmed.starts_with("//") {
            inside = true;
        } else if trimmed.ends_with(&end) && trimmed.starts_with("//") {
            return Ok(Some(dedent(&lines)));
        } else if inside && !(trimmed.starts_with("// ANCHOR")) {
            lines.push(line);
        }
    }
    match inside {
        true => Err(format!(
            "{}: anchor `{anchor}` is not closed",
            file.display()
        )),
        false => Ok(None),
    }
}

/// `lines` without their common leading white space, each ended by a newline.
fn dedent(lines: &[&str]) -> String {
    let indent = lines
        .iter()
        .filter(|l| !l.trim().is_empty())
        .map(|l| l.len() - l.trim_start().len())
        .min()
        .unwrap_or(0);
    lines
        .iter()
        .map(|l| format!("{}\n", l.get(indent..).unwrap_or("").trim_end()))
        .collect()
}

/// `after` with `// +` at the end of each line that `before` does not have: the
/// lines outside a longest common subsequence of the two.
fn mark_gained(before: &str, after: &str) -> String {
    let (a, b): (Vec<&str>, Vec<&str>) = (before.lines().collect(), after.lines().collect());
    let mut common = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for i in (0..a.len()).rev() {
        for j in (0..b.len()).rev() {
            common[i][j] = if a[i] == b[j] {
                common[i + 1][j + 1] + 1
            } else {
                common[i + 1][j].max(common[i][j + 1])
            };
        }
    }
    let (mut i, mut j) = (0, 0);
    let mut out = String::new();
    while j < b.len() {
        if i < a.len() && a[i] == b[j] {
            out += &format!("{}\n", b[j]);
            i += 1;
            j += 1;
        } else if i < a.len() && common[i + 1][j] >= common[i][j + 1] {
            i += 1;
        } else {
            let line = b[j];
            out += &match line.trim().is_empty() {
                true => "\n".to_owned(),
                false => format!("{line} // +\n"),
            };
            j += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{Language, Words, captioned, french_title, mark_gained, outputs};

    /// The title is the exercise's own message of the French catalogue, not a
    /// neighbour's nor its section.
    #[test]
    fn an_exercise_is_named_by_its_own_french_title() {
        let view = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(view.path().join("messages/fr")).unwrap();
        let catalogue = "exercise-s1-1 = le premier\n    .section = livre, séance 1\n\
                         exercise-s1-2 = le\u{a0}second\n    .section = livre\n";
        std::fs::write(view.path().join("messages/fr/checklist.ftl"), catalogue).unwrap();
        let title = |id| french_title(view.path(), id);
        assert_eq!(title("s1.1").as_deref(), Some("le premier"));
        assert_eq!(title("s1.2").as_deref(), Some("le\u{a0}second"));
        assert_eq!(title("s1.3"), None);
    }

    /// Each edition shows the output in its own language, without the file's final
    /// newline; a missing output is an error that names its file.
    #[test]
    fn an_output_is_taken_in_the_edition_s_language() {
        let src = tempfile::tempdir().unwrap();
        for (code, text) in [("en", "glass: differs\n"), ("fr", "glass : diffère\n")] {
            std::fs::create_dir_all(src.path().join("outputs").join(code)).unwrap();
            std::fs::write(src.path().join(format!("outputs/{code}/check.txt")), text).unwrap();
        }
        let page = "```text\n{{#output check}}\n```";
        let filled = |words| outputs(page, src.path(), words).unwrap();
        let (english, french) = (Words::of(Language::English), Words::of(Language::French));
        assert_eq!(filled(&english), "```text\nglass: differs\n```");
        assert_eq!(filled(&french), "```text\nglass : diffère\n```");
        let missing = outputs("{{#output other}}", src.path(), &english).unwrap_err();
        assert!(missing.contains("outputs/en/other.txt"), "{missing}");
    }

    /// The captions' words come from the book's catalogue, in each edition's
    /// language.
    #[test]
    fn the_words_are_the_edition_s() {
        assert_eq!(Words::of(Language::English).session, "session");
        let french = Words::of(Language::French);
        assert_eq!(french.session, "séance");
        assert_eq!(french.and, " et ");
        assert!(
            french
                .header
                .starts_with("| exercice | ce que vous écrivez |")
        );
    }

    #[test]
    fn an_image_alone_on_its_line_gets_a_visible_caption() {
        let text = "Before.\n\n![Figure 1: a <white> disk](figures/white-disk.png)\n\n```text\n![not](an image)\n```\n";
        let out = captioned(text);
        assert!(out.contains("<img src=\"figures/white-disk.png\" alt=\"Figure 1: a &lt;white&gt; disk\">\n<figcaption>Figure 1: a &lt;white&gt; disk</figcaption>"), "{out}");
        assert!(out.contains("```text\n![not](an image)\n```"));
    }

    /// The title `"pixelated WIDTH"` sets the width and keeps pixels square; any
    /// other title leaves the line as it is.
    #[test]
    fn a_pixelated_image_is_shown_at_its_width() {
        let out = captioned("![Figure 13: a mesh](figures/mesh.png \"pixelated 384\")\n");
        assert!(out.contains("<img src=\"figures/mesh.png\" alt=\"Figure 13: a mesh\" width=\"384\" style=\"image-rendering: pixelated\">"), "{out}");
        let other = "![a mesh](figures/mesh.png \"a title\")\n";
        assert_eq!(captioned(other), other);
    }

    #[test]
    fn only_the_lines_a_session_added_are_marked() {
        let before = "fn f() {\n    a();\n    c();\n}\n";
        let after = "fn f() {\n    a();\n    b();\n\n    c();\n}\n";
        assert_eq!(
            mark_gained(before, after),
            "fn f() {\n    a();\n    b(); // +\n\n    c();\n}\n"
        );
        assert_eq!(mark_gained(after, after), after);
    }
}
