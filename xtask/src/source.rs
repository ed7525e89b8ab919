//! A source file's text, and the byte range of any syn node in it.

use proc_macro2::{LineColumn, Span};
use std::ops::Range;

/// The text of a file, with where each line starts.
pub struct Source {
    /// The text.
    pub text: String,
    /// Byte offset of the start of each line.
    lines: Vec<usize>,
}

impl Source {
    /// The file's text, indexed by line.
    pub fn new(text: String) -> Source {
        let mut lines = vec![0];
        lines.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        Source { text, lines }
    }

    /// The byte offset of a line and column (columns count characters).
    pub fn offset(&self, at: LineColumn) -> usize {
        let start = self.lines[at.line - 1];
        let line = &self.text[start..];
        start
            + line
                .char_indices()
                .nth(at.column)
                .map_or(line.len(), |(i, _)| i)
    }

    /// The byte range a span covers.
    pub fn range(&self, span: Span) -> Range<usize> {
        self.offset(span.start())..self.offset(span.end())
    }

    /// The text a span covers.
    pub fn slice(&self, span: Span) -> &str {
        &self.text[self.range(span)]
    }
}
