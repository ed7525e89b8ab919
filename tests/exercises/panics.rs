//! A panic named by the exercise whose function panicked. The panic's place (the
//! file and line Rust reports) is looked up in the crate's sources: the function
//! that holds that line follows its exercise's marker. The message is then read
//! for the rule that explains it, when Rust's words point to one.

use std::path::Path;

use crate::checklist::translated;
use crate::marker::{MarkerLine, parse_marker};
use crate::say;

/// A line of the failure of a panic at `place` (`src/geometry/sphere.rs:42`) with
/// `message`: the exercise whose function holds that line, if one does, and the
/// rule its message points to.
pub fn explain(message: &str, place: &str) -> String {
    let rule = rule(message)
        .map(|r| say!("panics-message", r = r))
        .unwrap_or_default();
    match exercise_at(place) {
        Some(marker) => say!(
            "panics-panicked-in-exercise-at",
            title_marker = title(&marker),
            place = place,
            message = message,
            rule = rule
        ),
        None => say!(
            "panics-panicked",
            message = message,
            place = place,
            rule = rule
        ),
    }
}

/// The marker's exercise with its title in the checklist's language: `s1.2, the
/// ray-sphere distance`.
fn title(marker: &MarkerLine) -> String {
    let marker = translated(marker);
    format!("{}, {}", marker.id, marker.title)
}

/// The exercise whose function holds the line of `place`, read from the crate's
/// sources: the nearest marker above the line whose function's braces close
/// below it.
fn exercise_at(place: &str) -> Option<MarkerLine> {
    let (file, line) = place.rsplit_once(':')?;
    let line: usize = line.parse().ok()?;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
    let text = std::fs::read_to_string(path).ok()?;
    let lines: Vec<&str> = text.lines().collect();
    let (start, marker) = lines[..line.min(lines.len())]
        .iter()
        .enumerate()
        .rev()
        .find_map(|(k, l)| Some((k, parse_marker(l.trim().strip_prefix("///")?)?)))?;
    let end = function_end(&lines, start)?;
    (line <= end + 1).then_some(marker)
}

/// The index of the line where the function after the marker at `marker` closes:
/// where its braces, counted from its `fn` line, balance again.
fn function_end(lines: &[&str], marker: usize) -> Option<usize> {
    let start = marker + lines[marker..].iter().position(|l| l.contains("fn "))?;
    let mut depth = 0i32;
    for (k, l) in lines.iter().enumerate().skip(start) {
        depth += l.matches('{').count() as i32 - l.matches('}').count() as i32;
        if depth == 0 && l.contains('}') {
            return Some(k);
        }
    }
    None
}

/// The rule a panic's message points to, in the checklist's language.
fn rule(message: &str) -> Option<String> {
    if message.contains("subtract with overflow") {
        Some(say!("panics-an-unsigned-integer-u32-usize-went"))
    } else if message.contains("with overflow") {
        Some(say!("panics-an-integer-went-past-its-largest"))
    } else if message.contains("index out of bounds") {
        Some(say!("panics-an-index-past-the-end-of"))
    } else if message.contains("on a `None` value") {
        Some(say!("panics-unwrap-on-none-none-no-hit"))
    } else if message.contains("divide by zero") {
        Some(say!("panics-an-integer-division-by-0-divide"))
    } else {
        None
    }
}
