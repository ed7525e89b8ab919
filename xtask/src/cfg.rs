//! `cfg` predicates as a session view sees them: every `feature = "sN"` is known
//! (true for the sessions the view holds), and so are `feature = "beyond"` and
//! `feature = "plots"` (false: no view holds what goes beyond the course);
//! everything else is left as it was.

use syn::Meta;
use syn::punctuated::Punctuated;
use syn::spanned::Spanned;

use crate::source::Source;

/// A predicate after the session features are replaced by what they are in the view.
#[derive(Clone, Debug, PartialEq)]
pub enum Cfg {
    /// Known: the code is kept (and its gate dropped) or removed.
    Known(bool),
    /// Not about sessions (such as `test` or `feature = "f32"`): kept as this text.
    Other(String),
}

/// The session of `feature = "sN"`, if `meta` is one.
fn session_feature(meta: &Meta) -> Option<u32> {
    let Meta::NameValue(nv) = meta else {
        return None;
    };
    if !nv.path.is_ident("feature") {
        return None;
    }
    let syn::Expr::Lit(syn::ExprLit {
        lit: syn::Lit::Str(name),
        ..
    }) = &nv.value
    else {
        return None;
    };
    session_of(&name.value())
}

/// The features beyond the course: `beyond`, and `plots`, its commands that draw.
const BEYOND: [&str; 2] = ["beyond", "plots"];

/// The session that brings the Cargo feature `name`: `sN` is session N, and the
/// features beyond the course, which no view holds, count as the session after
/// the last.
pub fn session_of(name: &str) -> Option<u32> {
    if BEYOND.contains(&name) {
        return Some(last_session() + 1);
    }
    let number = name.strip_prefix('s')?.parse().ok()?;
    (1..=last_session()).contains(&number).then_some(number)
}

/// The course's last session: the highest of the session features (`s1`, `s2`,
/// ...) in the crate's `Cargo.toml`, read once.
pub fn last_session() -> u32 {
    static LAST: std::sync::OnceLock<u32> = std::sync::OnceLock::new();
    *LAST.get_or_init(|| {
        let manifest = std::fs::read_to_string(crate::root().join("Cargo.toml"));
        last_session_in(&manifest.unwrap_or_default())
    })
}

/// The highest session feature `sN` of the manifest `text` (0 when it has none).
pub fn last_session_in(text: &str) -> u32 {
    let Ok(doc) = text.parse::<toml_edit::DocumentMut>() else {
        return 0;
    };
    let features = doc.get("features").and_then(|f| f.as_table_like());
    features
        .into_iter()
        .flat_map(|table| table.iter().map(|(name, _)| name.to_owned()))
        .filter_map(|name| name.strip_prefix('s')?.parse().ok())
        .max()
        .unwrap_or(0)
}

/// Whether `meta` mentions a session feature anywhere.
pub fn mentions_session(meta: &Meta) -> bool {
    if session_feature(meta).is_some() {
        return true;
    }
    match meta {
        Meta::List(list) => list
            .parse_args_with(Punctuated::<Meta, syn::Token![,]>::parse_terminated)
            .is_ok_and(|inner| inner.iter().any(mentions_session)),
        _ => false,
    }
}

/// `meta` (from `source`) in the view of session `session`.
pub fn evaluate(meta: &Meta, session: u32, source: &Source) -> Cfg {
    if let Some(n) = session_feature(meta) {
        return Cfg::Known(n <= session);
    }
    let Meta::List(list) = meta else {
        return Cfg::Other(source.slice(meta.span()).to_owned());
    };
    let name = list
        .path
        .get_ident()
        .map(|i| i.to_string())
        .unwrap_or_default();
    let inner: Vec<Meta> = list
        .parse_args_with(Punctuated::<Meta, syn::Token![,]>::parse_terminated)
        .map(|p| p.into_iter().collect())
        .unwrap_or_default();
    let parts: Vec<Cfg> = inner.iter().map(|m| evaluate(m, session, source)).collect();
    match name.as_str() {
        "not" => match &parts[..] {
            [Cfg::Known(b)] => Cfg::Known(!b),
            [Cfg::Other(text)] => Cfg::Other(format!("not({text})")),
            _ => Cfg::Other(source.slice(meta.span()).to_owned()),
        },
        "all" => combine(parts, false, "all"),
        "any" => combine(parts, true, "any"),
        _ => Cfg::Other(source.slice(meta.span()).to_owned()),
    }
}

/// `all(...)` (`absorbing` false) or `any(...)` (`absorbing` true) of `parts`: an
/// absorbing constant decides it, the other constant drops out.
fn combine(parts: Vec<Cfg>, absorbing: bool, name: &str) -> Cfg {
    let mut others = vec![];
    for part in parts {
        match part {
            Cfg::Known(b) if b == absorbing => return Cfg::Known(absorbing),
            Cfg::Known(_) => {}
            Cfg::Other(text) => others.push(text),
        }
    }
    match others.len() {
        0 => Cfg::Known(!absorbing),
        1 => Cfg::Other(others.remove(0)),
        _ => Cfg::Other(format!("{name}({})", others.join(", "))),
    }
}
