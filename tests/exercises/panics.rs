//! A panic named by the exercise whose function panicked. The panic's place (the
//! file and line Rust reports) is looked up in the crate's sources: the function
//! that holds that line follows its exercise's marker. The message is then read
//! for the rule that explains it, when Rust's words point to one.

use std::path::Path;

use crate::SESSIONS;
use crate::marker::{MarkerLine, parse_marker};
use crate::say;
use crate::words::french;

/// A line of the failure of a panic at `place` (`src/geometry/sphere.rs:42`) with
/// `message`: the exercise whose function holds that line, if one does, and the
/// rule its message points to.
pub fn explain(message: &str, place: &str) -> String {
    let rule = rule(message)
        .map(|r| say!("; {r}", "\u{a0}; {r}"))
        .unwrap_or_default();
    match exercise_at(place) {
        Some(marker) => say!(
            "panicked in exercise {}, at {place}: {message}{rule}",
            "panique dans l'exercice {}, en {place}\u{a0}: {message}{rule}",
            title(&marker)
        ),
        None => say!(
            "panicked: {message} ({place}){rule}",
            "panique\u{a0}: {message} ({place}){rule}"
        ),
    }
}

/// The marker's exercise with its title in the checklist's language: `s1.2, the
/// ray-sphere distance`.
fn title(marker: &MarkerLine) -> String {
    let id = &marker.id;
    let exercise = SESSIONS.iter().flat_map(|s| s.iter()).find(|e| e.id == id);
    match exercise {
        Some(e) if french() => format!("{id}, {}", e.french[0]),
        _ => format!("{id}, {}", marker.title),
    }
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
        Some(say!(
            "an unsigned integer (u32, usize) went below 0: convert to Real before subtracting, since the chapter computes in real numbers",
            "un entier non signé (u32, usize) est passé sous 0\u{a0}: convertissez en Real avant de soustraire, car le chapitre calcule en nombres réels"
        ))
    } else if message.contains("with overflow") {
        Some(say!(
            "an integer went past its largest value: compute in Real",
            "un entier a dépassé sa plus grande valeur\u{a0}: calculez en Real"
        ))
    } else if message.contains("index out of bounds") {
        Some(say!(
            "an index past the end of a list: a list of n things is indexed from 0 to n - 1",
            "un indice au-delà de la fin d'une liste\u{a0}: une liste de n éléments s'indexe de 0 à n - 1"
        ))
    } else if message.contains("on a `None` value") {
        Some(say!(
            "unwrap() on None: None (no hit, say) is a case of its own, to handle with match or if let",
            "unwrap() sur None\u{a0}: None (l'absence d'intersection, par exemple) est un cas à part entière, à traiter avec match ou if let"
        ))
    } else if message.contains("divide by zero") {
        Some(say!(
            "an integer division by 0: divide in Real, or test the divisor",
            "une division entière par 0\u{a0}: divisez en Real, ou testez le diviseur"
        ))
    } else {
        None
    }
}
