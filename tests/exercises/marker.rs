//! An exercise's marker: the line of the doc comment beside the function a student
//! writes,
//!
//! ```text
//! /// Exercise s1.2, the ray-sphere distance: book session 1, "A white disk".
//! ```
//!
//! Read here by the checklist, and by `cargo xtask exercise`, which includes this
//! file, so that both read markers alike.

/// What a marker says.
#[derive(Clone, Debug, PartialEq)]
pub struct MarkerLine {
    /// The exercise's number, such as `s1.2`.
    pub id: String,
    /// What it computes, such as `the ray-sphere distance`.
    pub title: String,
    /// Where the book teaches it, such as `book session 1, "A white disk"`.
    pub book: String,
}

/// The marker in the text of a doc comment's line (after `///`), if it is one.
pub fn parse_marker(text: &str) -> Option<MarkerLine> {
    let rest = text.trim().strip_prefix("Exercise ")?;
    let (id, rest) = rest.split_once(", ")?;
    let (title, book) = rest.split_once(": ")?;
    Some(MarkerLine {
        id: id.to_owned(),
        title: title.to_owned(),
        book: book.trim_end_matches('.').to_owned(),
    })
}
