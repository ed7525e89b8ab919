//! A session's exercise crate: the session's view in which the body of each of that
//! session's exercises is replaced by `todo!`, for the student to write.
//!
//! An exercise is marked once, in the doc comment of its function:
//!
//! ```text
//! /// Exercise s1.2, the ray-sphere distance: book session 1, "A white disk".
//! ```
//!
//! The marker gives the exercise's number, what it computes and where the book
//! teaches it; the stub's message repeats it, so that the panic of a test that
//! reaches the stub says which exercise to write and where to read.

use std::fs;
use std::path::{Path, PathBuf};

use syn::spanned::Spanned;
use syn::visit::{self, Visit};
use syn::{Attribute, Block, Expr, Lit, Meta};

use crate::marker::{MarkerLine, parse_marker};
use crate::source::Source;

/// An exercise, as its marker names it.
#[derive(Clone, Debug, PartialEq)]
pub struct Marker {
    /// Its number, such as `s1.2`.
    pub id: String,
    /// The session that teaches it.
    pub session: u32,
    /// What it computes, such as `the ray-sphere distance`.
    pub title: String,
    /// Where the book teaches it, such as `book session 1, "A white disk"`.
    pub book: String,
    /// The function it marks, such as `Sphere::intersect` (empty until found).
    pub function: String,
}

impl Marker {
    /// The marker in a doc line (its text after `///`), if it is one.
    pub fn parse(line: &str) -> Option<Marker> {
        let MarkerLine { id, title, book } = parse_marker(line)?;
        let session = id.strip_prefix('s')?.split('.').next()?.parse().ok()?;
        Some(Marker {
            id,
            session,
            title,
            book,
            function: String::new(),
        })
    }

    /// The name of its test in the checklist: `s1_2_sphere_intersect` for `s1.2` on
    /// `Sphere::intersect`, `s1_4_point_light_lambert` on `PointLight::lambert`.
    pub fn test_name(&self) -> String {
        let mut name = self.id.replace('.', "_");
        for part in self.function.split("::") {
            name.push('_');
            for (i, c) in part.chars().enumerate() {
                if c.is_uppercase() && i > 0 {
                    name.push('_');
                }
                name.push(c.to_ascii_lowercase());
            }
        }
        name
    }

    /// The message of the exercise's stub.
    pub fn message(&self) -> String {
        format!("exercise {}, {}: {}", self.id, self.title, self.book)
    }
}

/// What a stub does.
#[derive(Clone, Copy, PartialEq)]
pub enum Stub {
    /// `todo!` in place of the body: the student's crate.
    Todo,
    /// `todo!` only while the environment variable `RAYCOURSE_STUB` names the
    /// exercise, the body kept otherwise: one build proves, exercise by exercise,
    /// that the tests fail without the body.
    Switch,
}

/// A function found with a marker: its marker, where its body lies, where a line of
/// attributes may go before its signature, and the statements its stub keeps.
struct Found {
    marker: Marker,
    body: std::ops::Range<usize>,
    signature: usize,
    kept: Vec<std::ops::Range<usize>>,
}

/// Whether a statement stays in an exercise's stub: a call into the renderer's
/// `cost` counters, which `--aov cost` reads, is not the exercise's to write.
fn kept_in_stub(statement: &syn::Stmt) -> bool {
    match statement {
        syn::Stmt::Expr(Expr::Call(call), Some(_)) => match &*call.func {
            Expr::Path(path) => path.path.segments.iter().any(|s| s.ident == "cost"),
            _ => false,
        },
        _ => false,
    }
}

/// Finds the marked functions of a file.
struct Finder<'s> {
    source: &'s Source,
    found: Vec<Found>,
    /// The type of the `impl` block being walked, if any.
    within: Option<String>,
}

impl Finder<'_> {
    fn note(
        &mut self,
        attrs: &[Attribute],
        sig: &syn::Signature,
        start: proc_macro2::Span,
        body: &Block,
    ) {
        if let Some(mut marker) = attrs.iter().find_map(doc_marker) {
            marker.function = match &self.within {
                Some(within) => format!("{within}::{}", sig.ident),
                None => sig.ident.to_string(),
            };
            let kept = body.stmts.iter().take_while(|s| kept_in_stub(s));
            self.found.push(Found {
                marker,
                body: self.source.range(body.span()),
                signature: self.source.offset(start.start()),
                kept: kept.map(|s| self.source.range(s.span())).collect(),
            });
        }
    }
}

impl<'ast> Visit<'ast> for Finder<'_> {
    fn visit_item_fn(&mut self, item: &'ast syn::ItemFn) {
        let start = first_token(&item.vis, item.sig.span());
        self.note(&item.attrs, &item.sig, start, &item.block);
        visit::visit_item_fn(self, item);
    }

    fn visit_item_impl(&mut self, item: &'ast syn::ItemImpl) {
        let within = match &*item.self_ty {
            syn::Type::Path(path) => path.path.segments.last().map(|s| s.ident.to_string()),
            _ => None,
        };
        let outer = std::mem::replace(&mut self.within, within);
        visit::visit_item_impl(self, item);
        self.within = outer;
    }

    fn visit_impl_item_fn(&mut self, item: &'ast syn::ImplItemFn) {
        let start = first_token(&item.vis, item.sig.span());
        self.note(&item.attrs, &item.sig, start, &item.block);
        visit::visit_impl_item_fn(self, item);
    }
}

/// Where a function's signature starts: at its visibility when it has one.
fn first_token(vis: &syn::Visibility, signature: proc_macro2::Span) -> proc_macro2::Span {
    match vis {
        syn::Visibility::Inherited => signature,
        _ => vis.span(),
    }
}

/// The marker in a `#[doc = "..."]` attribute, if any.
fn doc_marker(attr: &Attribute) -> Option<Marker> {
    let Meta::NameValue(pair) = &attr.meta else {
        return None;
    };
    if !pair.path.is_ident("doc") {
        return None;
    }
    match &pair.value {
        Expr::Lit(syn::ExprLit {
            lit: Lit::Str(text),
            ..
        }) => Marker::parse(&text.value()),
        _ => None,
    }
}

/// The markers of a Rust source text, in the order of the file.
pub fn markers(text: &str) -> Result<Vec<Marker>, String> {
    Ok(found(text)?.into_iter().map(|f| f.marker).collect())
}

fn found(text: &str) -> Result<Vec<Found>, String> {
    let file = syn::parse_file(text).map_err(|e| format!("{e} at {:?}", e.span().start()))?;
    let source = Source::new(text.to_owned());
    let mut finder = Finder {
        source: &source,
        found: vec![],
        within: None,
    };
    finder.visit_file(&file);
    Ok(finder.found)
}

/// `text` with the body of each exercise that `chosen` picks replaced by its stub.
pub fn stub(text: &str, chosen: &dyn Fn(&Marker) -> bool, how: Stub) -> Result<String, String> {
    let mut found: Vec<Found> = found(text)?
        .into_iter()
        .filter(|f| chosen(&f.marker))
        .collect();
    found.sort_by_key(|f| std::cmp::Reverse(f.body.start));
    let mut text = text.to_owned();
    for f in found {
        let line_start = text[..f.signature].rfind('\n').map_or(0, |i| i + 1);
        let indent = &text[line_start..f.signature].to_owned();
        let todo = format!("todo!({:?})", f.marker.message());
        let kept: String = f
            .kept
            .iter()
            .map(|range| format!("{indent}    {}\n", &text[range.clone()]))
            .collect();
        let body = match how {
            Stub::Todo => format!("{{\n{kept}{indent}    {todo}\n{indent}}}"),
            Stub::Switch => format!(
                "{{\n{indent}    if std::env::var_os(\"RAYCOURSE_STUB\").is_some_and(|s| s == {:?}) {{\n\
                 {indent}        {todo}\n{indent}    }}\n{indent}    {}\n{indent}}}",
                f.marker.id,
                &text[f.body.clone()]
            ),
        };
        text.replace_range(f.body.clone(), &body);
        if how == Stub::Todo {
            text.insert_str(
                f.signature,
                &format!("#[allow(unused_variables)]\n{indent}"),
            );
        }
    }
    Ok(text)
}

/// Replaces, in every Rust file under `folder`, the bodies of the exercises that
/// `chosen` picks; the markers replaced, in the order found.
pub fn stub_folder(
    folder: &Path,
    chosen: &dyn Fn(&Marker) -> bool,
    how: Stub,
) -> Result<Vec<Marker>, String> {
    let mut stubbed = vec![];
    for file in rust_files_below(folder)? {
        let text = fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
        let picked: Vec<Marker> = markers(&text)
            .map_err(|e| format!("{}: {e}", file.display()))?
            .into_iter()
            .filter(|m| chosen(m))
            .collect();
        if !picked.is_empty() {
            let mut edited =
                stub(&text, chosen, how).map_err(|e| format!("{}: {e}", file.display()))?;
            if how == Stub::Todo {
                edited = allow_unused(&edited);
            }
            fs::write(&file, edited).map_err(|e| format!("{}: {e}", file.display()))?;
            stubbed.extend(picked);
        }
    }
    Ok(stubbed)
}

/// `text` with the imports and private helpers that only the stubbed bodies used
/// allowed to go unused, after the module's doc comment: the student's crate
/// builds without a warning before its exercises are written.
pub fn allow_unused(text: &str) -> String {
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim();
        if !(trimmed.is_empty() || trimmed.starts_with("//!") || trimmed.starts_with("#![")) {
            break;
        }
        at += line.len();
    }
    let allow = "// The exercises' stubs leave some imports and helpers unused until they are written.\n\
                 #![allow(unused_imports, dead_code)]\n\n";
    format!("{}{allow}{}", &text[..at], &text[at..])
}

/// Every exercise of the crate at `root`, with its file (relative to `root`), in the
/// course's order.
pub fn all(root: &Path) -> Result<Vec<(Marker, String)>, String> {
    let mut all = vec![];
    for file in rust_files_below(&root.join("src"))? {
        let text = fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
        let relative = file
            .strip_prefix(root)
            .unwrap_or(&file)
            .display()
            .to_string();
        for marker in markers(&text).map_err(|e| format!("{}: {e}", file.display()))? {
            all.push((marker, relative.clone()));
        }
    }
    all.sort_by_key(|(m, _)| order(&m.id));
    Ok(all)
}

/// The checklist's line of exercise `id`: an exercise of several functions (the
/// textbook sphere test, then the robust one) has one line, named after the last of
/// them, the one the renderer calls.
pub fn line_of(all: &[(Marker, String)], id: &str) -> String {
    all.iter()
        .rev()
        .find(|(marker, _)| marker.id == id)
        .map(|(marker, _)| marker.test_name())
        .unwrap_or_default()
}

/// The course's order of an exercise number: session, then number.
pub fn order(id: &str) -> (u32, u32) {
    let mut parts = id
        .trim_start_matches('s')
        .split('.')
        .map(|p| p.parse().unwrap_or(0));
    (parts.next().unwrap_or(0), parts.next().unwrap_or(0))
}

/// Every `.rs` file below `folder`, sorted.
pub fn rust_files_below(folder: &Path) -> Result<Vec<PathBuf>, String> {
    let mut files = vec![];
    let entries = fs::read_dir(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    for entry in entries {
        let path = entry.map_err(|e| e.to_string())?.path();
        if path.is_dir() {
            files.extend(rust_files_below(&path)?);
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path);
        }
    }
    files.sort();
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "impl Sphere {\n    /// The distance.\n    ///\n    /// Exercise s1.2, the ray-sphere distance: book session 1, \"A white disk\".\n    pub fn intersect(&self, ray: &Ray) -> Option<Real> {\n        let s = ray.origin;\n        None\n    }\n}\n\nfn other() -> u8 {\n    1\n}\n";

    #[test]
    fn a_marker_gives_its_number_title_and_section() {
        let marker = Marker::parse(
            " Exercise s3.1, the cosine-weighted direction: book session 3, \"Indirect lighting\".",
        )
        .unwrap();
        assert_eq!(marker.id, "s3.1");
        assert_eq!(marker.session, 3);
        assert_eq!(marker.title, "the cosine-weighted direction");
        assert_eq!(marker.book, "book session 3, \"Indirect lighting\"");
        assert_eq!(Marker::parse(" An exercise for later."), None);
    }

    #[test]
    fn a_stub_replaces_the_marked_body_only_and_allows_its_unused_parameters() {
        let stubbed = stub(TEXT, &|_| true, Stub::Todo).unwrap();
        assert!(stubbed.contains(
            "    #[allow(unused_variables)]\n    pub fn intersect(&self, ray: &Ray) -> Option<Real> {\n        todo!(\"exercise s1.2, the ray-sphere distance: book session 1, \\\"A white disk\\\"\")\n    }\n"
        ), "{stubbed}");
        assert!(!stubbed.contains("let s = ray.origin"));
        assert!(stubbed.contains("fn other() -> u8 {\n    1\n}"));
        syn::parse_file(&stubbed).unwrap();
        let marker = &markers(TEXT).unwrap()[0];
        assert_eq!(marker.function, "Sphere::intersect");
        assert_eq!(marker.test_name(), "s1_2_sphere_intersect");
    }

    #[test]
    fn an_exercise_of_two_functions_has_one_line_named_after_the_last() {
        let marker = |function: &str| Marker {
            function: function.into(),
            ..Marker::parse(" Exercise s1.2, the ray-sphere distance: book session 1.").unwrap()
        };
        let all = vec![
            (marker("Sphere::intersect_textbook"), String::new()),
            (marker("Sphere::intersect"), String::new()),
        ];
        assert_eq!(line_of(&all, "s1.2"), "s1_2_sphere_intersect");
        assert_eq!(line_of(&all, "s1.3"), "");
    }

    #[test]
    fn a_switched_stub_keeps_the_body_behind_the_environment() {
        let switched = stub(TEXT, &|_| true, Stub::Switch).unwrap();
        assert!(
            switched.contains("is_some_and(|s| s == \"s1.2\")"),
            "{switched}"
        );
        assert!(switched.contains("let s = ray.origin"));
        syn::parse_file(&switched).unwrap();
    }

    #[test]
    fn the_unused_allowance_follows_the_module_doc() {
        let text = "//! A module.\n\nuse std::fmt;\n";
        let allowed = allow_unused(text);
        assert!(
            allowed.starts_with("//! A module.\n\n// The exercises"),
            "{allowed}"
        );
        assert!(allowed.ends_with("#![allow(unused_imports, dead_code)]\n\nuse std::fmt;\n"));
        syn::parse_file(&allowed).unwrap();
    }

    #[test]
    fn a_stub_keeps_the_leading_cost_counters() {
        let text = "impl Aabb {\n    /// Exercise s5.2, the slab test: book session 5, \"The bounding box\".\n    pub fn entry(&self) -> Option<Real> {\n        cost::count_box();\n        let near = 0.0;\n        cost::count_box();\n        Some(near)\n    }\n}\n";
        let stubbed = stub(text, &|_| true, Stub::Todo).unwrap();
        assert!(
            stubbed.contains("Option<Real> {\n        cost::count_box();\n        todo!("),
            "{stubbed}"
        );
        assert_eq!(stubbed.matches("count_box").count(), 1, "{stubbed}");
        syn::parse_file(&stubbed).unwrap();
    }

    #[test]
    fn exercises_not_chosen_keep_their_bodies() {
        assert_eq!(stub(TEXT, &|m| m.session == 2, Stub::Todo).unwrap(), TEXT);
    }
}
