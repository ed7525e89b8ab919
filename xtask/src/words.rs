//! The words the book's tools write into the book, in each edition's language: the
//! library's catalogue with the book's own messages (`messages/<code>/book.ftl`),
//! numbers written by the catalogue as each language writes them.

use std::sync::OnceLock;

use raycourse::messages::catalogue::{Catalogue, with_own};
use raycourse::messages::language::Language;

/// The book's own messages, beside the library's.
const BOOK: [(Language, &str); 2] = [
    (
        Language::English,
        include_str!("../../messages/en/book.ftl"),
    ),
    (Language::French, include_str!("../../messages/fr/book.ftl")),
];

/// The catalogue of `language`, read on first use.
pub fn catalogue(language: Language) -> &'static Catalogue {
    static CATALOGUES: [OnceLock<Catalogue>; 2] = [OnceLock::new(), OnceLock::new()];
    CATALOGUES[language as usize].get_or_init(|| with_own(language, "book.ftl", &BOOK))
}
