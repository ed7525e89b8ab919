//! `cargo xtask names DIR`: the names that the Rust files under `DIR` define (its
//! items, the methods of its impl blocks, the variants of its enums), one a line,
//! sorted. `.ci/check-book` compares the crate's with each session's view to find
//! what a later session brings, which that session's chapter must not show.

use std::collections::BTreeSet;
use std::path::Path;

use syn::visit::Visit;

/// The names defined under `folder`, sorted.
pub fn defined_under(folder: &Path) -> Result<BTreeSet<String>, String> {
    let mut names = Names::default();
    for file in crate::view::rust_files_under(folder)? {
        let text =
            std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
        let parsed = syn::parse_file(&text).map_err(|e| format!("{}: {e}", file.display()))?;
        names.visit_file(&parsed);
    }
    Ok(names.0)
}

/// The names a file defines.
#[derive(Default)]
struct Names(BTreeSet<String>);

impl<'a> Visit<'a> for Names {
    fn visit_item(&mut self, item: &'a syn::Item) {
        let ident = match item {
            syn::Item::Const(i) => Some(&i.ident),
            syn::Item::Enum(i) => Some(&i.ident),
            syn::Item::Fn(i) => Some(&i.sig.ident),
            syn::Item::Mod(i) => Some(&i.ident),
            syn::Item::Static(i) => Some(&i.ident),
            syn::Item::Struct(i) => Some(&i.ident),
            syn::Item::Trait(i) => Some(&i.ident),
            syn::Item::Type(i) => Some(&i.ident),
            _ => None,
        };
        self.0.extend(ident.map(ToString::to_string));
        syn::visit::visit_item(self, item);
    }

    fn visit_variant(&mut self, variant: &'a syn::Variant) {
        self.0.insert(variant.ident.to_string());
        syn::visit::visit_variant(self, variant);
    }

    fn visit_impl_item_fn(&mut self, item: &'a syn::ImplItemFn) {
        self.0.insert(item.sig.ident.to_string());
        syn::visit::visit_impl_item_fn(self, item);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_methods_and_variants_are_named() {
        let code = "mod m { pub struct Lens; impl Lens { fn refocus() { let local = 1; } } }\n\
                    enum Material { Mirror, Glass { index: f64 } }\nconst LIMIT: u32 = 1;";
        let mut names = Names::default();
        names.visit_file(&syn::parse_file(code).unwrap());
        let found: Vec<&str> = names.0.iter().map(String::as_str).collect();
        assert_eq!(
            found,
            [
                "Glass", "LIMIT", "Lens", "Material", "Mirror", "m", "refocus"
            ]
        );
    }
}
