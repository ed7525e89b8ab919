//! The program's messages in the reader's language. Every sentence that `check`,
//! the exercises' checklist and the book's pages show comes from one catalogue, a
//! set of Fluent files per language in `messages/` (`en/` the source, `fr/` its
//! translation), which a translator edits without touching Rust or JavaScript.
//! Numbers are written by each language's rules (`1.5`, `1,5`), plurals chosen by
//! them, by the catalogue's libraries, not by hand.
//!
//! | file | what it holds |
//! |---|---|
//! | [`language`] | English or French, as the locale or `--lang` asks |
//! | [`catalogue`] | the catalogue's files and its messages with their arguments |
//! | [`numbers`] | numbers in a message, as the language writes them |
//! | [`said`] | a message kept with its arguments, said once the language is known |

pub mod catalogue;
pub mod language;
pub mod numbers;
pub mod said;

pub use catalogue::{Argument, say};
