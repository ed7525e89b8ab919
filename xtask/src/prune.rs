//! A Rust source file as it stands after a session: every item, field, variant,
//! match arm, statement, parameter, struct-literal field and array element gated on
//! a later session removed, every gate of sessions 1..N dropped, and `cfg_attr`s
//! on sessions resolved. The file is parsed with syn and cut by byte ranges, so
//! comments and formatting are kept.

use std::ops::Range;

use syn::spanned::Spanned;
use syn::visit::{self, Visit};
use syn::{Attribute, Expr, Meta};

use crate::cfg::{Cfg, evaluate, mentions_session};
use crate::source::Source;

/// A file after pruning.
pub struct Pruned {
    /// Its text.
    pub text: String,
    /// The `mod name;` declarations kept, whose files belong to the view.
    pub modules: Vec<String>,
}

/// A change to the text: `range` replaced by `with`.
struct Edit {
    range: Range<usize>,
    with: String,
}

/// How a node sits in the text, which decides what goes with it when it is removed.
#[derive(Clone, Copy, PartialEq)]
enum Place {
    /// One of a comma-separated list (field, variant, parameter, arm, element).
    InList,
    /// An item or a statement.
    Alone,
}

/// Prunes `text` for the view of `session`; `None` when the whole file is gated on
/// a later session (`#![cfg(feature = "sN")]`).
pub fn prune(text: &str, session: u32) -> Result<Option<Pruned>, String> {
    let file = syn::parse_file(text).map_err(|e| format!("{e} at {:?}", e.span().start()))?;
    let source = Source::new(text.to_owned());
    let mut pruner = Pruner {
        source: &source,
        session,
        edits: vec![],
        modules: vec![],
        removed: vec![],
    };
    if !pruner.gate(&file.attrs, file.span(), Place::Alone) {
        return Ok(None);
    }
    for item in &file.items {
        pruner.visit_item(item);
    }
    let Pruner {
        edits,
        modules,
        removed,
        ..
    } = pruner;
    let text = without_rows(&tidy(&apply(text, edits)), &removed);
    Ok(Some(Pruned { text, modules }))
}

/// Walks the syntax tree, noting the edits.
struct Pruner<'s> {
    source: &'s Source,
    session: u32,
    edits: Vec<Edit>,
    /// Modules kept (`mod name;` without a body).
    modules: Vec<String>,
    /// Modules removed.
    removed: Vec<String>,
}

impl Pruner<'_> {
    /// Handles the attributes of the node at `span`: `false` (and the node removed)
    /// when a `cfg` on sessions is false; otherwise the session gates dropped and the
    /// node kept.
    fn gate(&mut self, attrs: &[Attribute], span: proc_macro2::Span, place: Place) -> bool {
        for attr in attrs {
            let Some((keep, with)) = self.attribute(attr) else {
                continue;
            };
            if !keep {
                let start = attrs
                    .iter()
                    .map(|a| self.source.range(a.span()).start)
                    .chain([self.source.range(span).start])
                    .min()
                    .unwrap_or(0);
                let end = self.source.range(span).end;
                let range = self.whole(start..end, place);
                self.edits
                    .retain(|e| e.range.end <= range.start || e.range.start >= range.end);
                self.edits.push(Edit {
                    range,
                    with: MARK.to_string(),
                });
                return false;
            }
            let range = self.source.range(attr.span());
            let (range, with) = match with.is_empty() {
                true => (range.start..self.next_token(range.end), MARK.to_string()),
                false => (range, with),
            };
            self.edits.push(Edit { range, with });
        }
        true
    }

    /// What becomes of `attr` in the view: `None` if it is not about sessions;
    /// otherwise whether the node stays, and the attribute's replacement (empty: it
    /// goes).
    fn attribute(&self, attr: &Attribute) -> Option<(bool, String)> {
        let name = attr.path().get_ident()?.to_string();
        let Meta::List(list) = &attr.meta else {
            return None;
        };
        let args: Vec<Meta> = list
            .parse_args_with(syn::punctuated::Punctuated::<Meta, syn::Token![,]>::parse_terminated)
            .ok()?
            .into_iter()
            .collect();
        let predicate = args.first()?;
        if !mentions_session(predicate) {
            return None;
        }
        let cfg = evaluate(predicate, self.session, self.source);
        let outer = if attr.style == syn::AttrStyle::Outer {
            "#"
        } else {
            "#!"
        };
        match (name.as_str(), cfg) {
            ("cfg", Cfg::Known(keep)) => Some((keep, String::new())),
            ("cfg", Cfg::Other(text)) => Some((true, format!("{outer}[cfg({text})]"))),
            ("cfg_attr", Cfg::Known(false)) => Some((true, String::new())),
            ("cfg_attr", Cfg::Known(true)) => {
                let rest: Vec<&str> = args[1..]
                    .iter()
                    .map(|m| self.source.slice(m.span()))
                    .collect();
                Some((true, format!("{outer}[{}]", rest.join(", "))))
            }
            ("cfg_attr", Cfg::Other(text)) => {
                let rest: Vec<&str> = args[1..]
                    .iter()
                    .map(|m| self.source.slice(m.span()))
                    .collect();
                Some((
                    true,
                    format!("{outer}[cfg_attr({text}, {})]", rest.join(", ")),
                ))
            }
            _ => None,
        }
    }

    /// The byte offset of the first character after `at` that is not white space.
    fn next_token(&self, at: usize) -> usize {
        let text = &self.source.text;
        at + text[at..].len() - text[at..].trim_start().len()
    }

    /// `range` widened to what goes with a removed node: the white space before it
    /// on its line, a following comma for a list element (or the comma before it
    /// when it ends the list on one line), and the end of its line when nothing
    /// else is on it.
    fn whole(&self, range: Range<usize>, place: Place) -> Range<usize> {
        let text = &self.source.text;
        let line_start = text[..range.start].rfind('\n').map_or(0, |i| i + 1);
        let start = if text[line_start..range.start].trim().is_empty() {
            line_start
        } else {
            range.start
        };
        let mut end = range.end;
        if place == Place::InList {
            let (before, after) = (text[..start].trim_end(), text[end..].trim_start());
            if after.starts_with(',') {
                end = self.next_token(end) + 1;
            } else if after.starts_with([')', ']', '}'])
                && before.ends_with(',')
                && !text[..end].ends_with(',')
            {
                return before.len() - 1..end;
            }
        }
        let rest = &text[end..];
        let line_end = rest.find('\n').map_or(rest.len(), |i| i + 1);
        if rest[..line_end].trim().is_empty() && start == line_start {
            end += line_end;
        }
        start..end
    }
}

/// The attributes of an expression that can stand as a statement or an element.
fn expr_attrs(expr: &Expr) -> &[Attribute] {
    match expr {
        Expr::Lit(e) => &e.attrs,
        Expr::Field(e) => &e.attrs,
        Expr::If(e) => &e.attrs,
        Expr::Call(e) => &e.attrs,
        Expr::MethodCall(e) => &e.attrs,
        Expr::Assign(e) => &e.attrs,
        Expr::Block(e) => &e.attrs,
        Expr::ForLoop(e) => &e.attrs,
        Expr::Match(e) => &e.attrs,
        Expr::Macro(e) => &e.attrs,
        Expr::Return(e) => &e.attrs,
        Expr::Path(e) => &e.attrs,
        Expr::Try(e) => &e.attrs,
        Expr::Struct(e) => &e.attrs,
        _ => &[],
    }
}

/// The attributes of an item.
fn item_attrs(item: &syn::Item) -> &[Attribute] {
    use syn::Item::*;
    match item {
        Const(i) => &i.attrs,
        Enum(i) => &i.attrs,
        ExternCrate(i) => &i.attrs,
        Fn(i) => &i.attrs,
        Impl(i) => &i.attrs,
        Macro(i) => &i.attrs,
        Mod(i) => &i.attrs,
        Static(i) => &i.attrs,
        Struct(i) => &i.attrs,
        Trait(i) => &i.attrs,
        Type(i) => &i.attrs,
        Union(i) => &i.attrs,
        Use(i) => &i.attrs,
        _ => &[],
    }
}

impl<'ast> Visit<'ast> for Pruner<'_> {
    fn visit_item(&mut self, item: &'ast syn::Item) {
        let kept = self.gate(item_attrs(item), item.span(), Place::Alone);
        if let syn::Item::Mod(module) = item
            && module.content.is_none()
        {
            let name = module.ident.to_string();
            match kept {
                true => self.modules.push(name),
                false => self.removed.push(name),
            }
        }
        if kept {
            visit::visit_item(self, item);
        }
    }

    fn visit_impl_item(&mut self, item: &'ast syn::ImplItem) {
        let attrs: &[Attribute] = match item {
            syn::ImplItem::Fn(f) => &f.attrs,
            syn::ImplItem::Const(c) => &c.attrs,
            syn::ImplItem::Type(t) => &t.attrs,
            _ => &[],
        };
        if self.gate(attrs, item.span(), Place::Alone) {
            visit::visit_impl_item(self, item);
        }
    }

    fn visit_field(&mut self, field: &'ast syn::Field) {
        if self.gate(&field.attrs, field.span(), Place::InList) {
            visit::visit_field(self, field);
        }
    }

    fn visit_variant(&mut self, variant: &'ast syn::Variant) {
        if self.gate(&variant.attrs, variant.span(), Place::InList) {
            visit::visit_variant(self, variant);
        }
    }

    fn visit_arm(&mut self, arm: &'ast syn::Arm) {
        if self.gate(&arm.attrs, arm.span(), Place::InList) {
            visit::visit_arm(self, arm);
        }
    }

    fn visit_fn_arg(&mut self, arg: &'ast syn::FnArg) {
        let attrs = match arg {
            syn::FnArg::Receiver(r) => &r.attrs,
            syn::FnArg::Typed(t) => &t.attrs,
        };
        if self.gate(attrs, arg.span(), Place::InList) {
            visit::visit_fn_arg(self, arg);
        }
    }

    fn visit_field_value(&mut self, field: &'ast syn::FieldValue) {
        if self.gate(&field.attrs, field.span(), Place::InList) {
            visit::visit_field_value(self, field);
        }
    }

    fn visit_stmt(&mut self, stmt: &'ast syn::Stmt) {
        let attrs: &[Attribute] = match stmt {
            syn::Stmt::Local(l) => &l.attrs,
            syn::Stmt::Expr(e, _) => expr_attrs(e),
            syn::Stmt::Macro(m) => &m.attrs,
            syn::Stmt::Item(_) => &[],
        };
        if self.gate(attrs, stmt.span(), Place::Alone) {
            visit::visit_stmt(self, stmt);
        }
    }

    fn visit_expr_array(&mut self, array: &'ast syn::ExprArray) {
        for element in &array.elems {
            if self.gate(expr_attrs(element), element.span(), Place::InList) {
                self.visit_expr(element);
            }
        }
    }
}

/// `text` with the `edits` made (they do not overlap).
fn apply(text: &str, mut edits: Vec<Edit>) -> String {
    edits.sort_by_key(|e| std::cmp::Reverse(e.range.start));
    let mut out = text.to_owned();
    for edit in edits {
        out.replace_range(edit.range, &edit.with);
    }
    out
}

/// Marks where a removal was, so that [`tidy`] only touches the blank lines around
/// removals (and never, say, those of a string literal).
const MARK: char = '\u{0}';

/// `text` with the blank lines that removals leave behind taken away: in a run of
/// blank lines next to a removal, at most one is kept, and none just inside
/// braces.
fn tidy(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let blank = |l: &str| l.trim_matches(MARK).trim().is_empty();
    let mut out: Vec<String> = vec![];
    let mut i = 0;
    while i < lines.len() {
        if !blank(lines[i]) {
            out.push(lines[i].replace(MARK, ""));
            i += 1;
            continue;
        }
        let end = (i..lines.len())
            .find(|&k| !blank(lines[k]))
            .unwrap_or(lines.len());
        let touched = lines[i.saturating_sub(1)..(end + 1).min(lines.len())]
            .iter()
            .any(|l| l.contains(MARK));
        if !touched {
            out.extend(lines[i..end].iter().map(|l| l.to_string()));
        } else {
            let after_open = out
                .last()
                .is_none_or(|l| l.trim_end().ends_with(['{', '(', '[']));
            let before_close = lines.get(end).is_none_or(|l| {
                l.replace(MARK, "")
                    .trim_start()
                    .starts_with(['}', ')', ']'])
            });
            if !after_open && !before_close {
                out.push(String::new());
            }
        }
        i = end;
    }
    out.join("\n") + "\n"
}

/// `text` without the rows of its module documentation's table (`//! | ... |`) that
/// name one of the `removed` modules in their first cell.
fn without_rows(text: &str, removed: &[String]) -> String {
    let first_cell = |line: &str| -> Option<String> {
        let row = line.trim_start().strip_prefix("//! |")?;
        let cell = row.split('|').next()?;
        let name = cell.split(['(', ']']).next()?;
        Some(name.trim().trim_matches(['[', '`', ' ']).to_owned())
    };
    text.lines()
        .filter(|line| first_cell(line).is_none_or(|name| !removed.contains(&name)))
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

#[cfg(test)]
mod tests {
    use super::prune;

    /// The text of `text` in the view of `session`.
    fn view(text: &str, session: u32) -> String {
        prune(text, session).unwrap().unwrap().text
    }

    #[test]
    fn a_later_sessions_statement_goes_and_an_earlier_gate_is_dropped() {
        let text = "fn f() {\n    let a = 1;\n    #[cfg(feature = \"s2\")]\n    let b = 2;\n    #[cfg(feature = \"s3\")]\n    let c = 3;\n}\n";
        assert_eq!(
            view(text, 2),
            "fn f() {\n    let a = 1;\n    let b = 2;\n}\n"
        );
        let at1 = view(text, 1);
        assert!(at1.contains("let a") && !at1.contains("let b"));
    }

    #[test]
    fn what_goes_beyond_the_course_is_in_no_view() {
        let text = "#[cfg(feature = \"beyond\")]\npub mod fast;\n\
                    #[cfg(all(feature = \"s7\", not(feature = \"beyond\")))]\nuse a::scene;\n\
                    #[cfg(feature = \"beyond\")]\nuse b::scene;\n\
                    fn f() -> R {\n    #[cfg(feature = \"beyond\")]\n    b::more()?;\n    Ok(())\n}\n";
        assert_eq!(
            view(text, 7),
            "use a::scene;\nfn f() -> R {\n    Ok(())\n}\n"
        );
    }

    #[test]
    fn a_gated_array_element_goes_with_its_comma() {
        let text = "const ALL: &[u8] = &[\n    a::ONE,\n    #[cfg(feature = \"s2\")]\n    b::TWO,\n    #[cfg(feature = \"s3\")]\n    3,\n];\n";
        assert_eq!(
            view(text, 2),
            "const ALL: &[u8] = &[\n    a::ONE,\n    b::TWO,\n];\n"
        );
    }

    #[test]
    fn a_gated_struct_element_goes_with_its_comma() {
        let text = "const ALL: &[P] = &[\n    P { a: 1 },\n    #[cfg(feature = \"s2\")]\n    P { a: 2 },\n    #[cfg(feature = \"s3\")]\n    P { a: 3 },\n];\n";
        assert_eq!(
            view(text, 2),
            "const ALL: &[P] = &[\n    P { a: 1 },\n    P { a: 2 },\n];\n"
        );
    }

    #[test]
    fn fields_variants_arms_and_parameters_go_with_their_commas() {
        let text = "struct S {\n    a: u8,\n    #[cfg(feature = \"s4\")]\n    b: u8,\n}\n\
                    enum E {\n    A,\n    #[cfg(feature = \"s4\")]\n    B,\n}\n\
                    fn g(x: u8, #[cfg(feature = \"s4\")] y: u8) -> u8 {\n    match x {\n        0 => 1,\n        #[cfg(feature = \"s4\")]\n        1 => y,\n        _ => 2,\n    }\n}\n";
        let at3 = view(text, 3);
        assert!(!at3.contains("b: u8") && !at3.contains("    B,") && !at3.contains("y"));
        assert!(at3.contains("fn g(x: u8) -> u8"), "{at3}");
        assert!(at3.contains("0 => 1,\n        _ => 2,"), "{at3}");
        assert!(!at3.contains("cfg"));
        let at4 = view(text, 4);
        assert!(at4.contains("b: u8") && at4.contains("1 => y") && !at4.contains("cfg"));
    }

    #[test]
    fn not_all_and_any_are_evaluated_and_other_predicates_kept() {
        let text = "#[cfg(not(feature = \"s3\"))]\nfn simple() {}\n\
                    #[cfg(all(feature = \"s2\", test))]\nfn tested() {}\n\
                    #[cfg(any(feature = \"s5\", feature = \"f32\"))]\nfn either() {}\n";
        let at2 = view(text, 2);
        assert!(at2.contains("fn simple"));
        assert!(at2.contains("#[cfg(test)]\nfn tested"), "{at2}");
        assert!(
            at2.contains("#[cfg(feature = \"f32\")]\nfn either"),
            "{at2}"
        );
        let at5 = view(text, 5);
        assert!(!at5.contains("fn simple"));
        assert!(at5.contains("\nfn either"), "{at5}");
        assert!(!at5.contains("f32"));
    }

    #[test]
    fn cfg_attr_on_a_session_becomes_the_attribute_or_nothing() {
        let text = "#[cfg_attr(feature = \"s3\", derive(Clone))]\nstruct S;\n";
        assert_eq!(view(text, 3), "#[derive(Clone)]\nstruct S;\n");
        assert_eq!(view(text, 2), "struct S;\n");
    }

    #[test]
    fn a_whole_file_of_a_later_session_is_absent_and_its_module_and_row_go() {
        assert!(
            prune("#![cfg(feature = \"s6\")]\nfn f() {}\n", 5)
                .unwrap()
                .is_none()
        );
        let text = "//! | file | session |\n//! | `early` | 1 |\n//! | `late` | 6 |\n\
                    mod early;\n#[cfg(feature = \"s6\")]\nmod late;\n";
        let pruned = prune(text, 5).unwrap().unwrap();
        assert_eq!(pruned.modules, ["early"]);
        assert!(!pruned.text.contains("late"), "{}", pruned.text);
        assert!(pruned.text.contains("`early` | 1"));
    }

    #[test]
    fn comments_and_string_blank_lines_are_kept() {
        let text = "// A comment.\nconst S: &str = \"a\n\n\nb\";\n#[cfg(feature = \"s7\")]\nconst T: u8 = 0;\n";
        assert_eq!(
            view(text, 6),
            "// A comment.\nconst S: &str = \"a\n\n\nb\";\n"
        );
    }
}
