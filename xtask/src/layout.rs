//! The library's own claim about its layout, held: `src/lib.rs` lists its modules
//! "in the order they depend on each other", so no module may use one listed after
//! it, and the table of its doc comment lists them in the order of its `mod` lines.

use std::collections::BTreeSet;
use std::path::Path;

use syn::visit::Visit;

/// The modules `src/lib.rs` declares, in the order of its `mod` lines.
fn declared(lib: &str) -> Vec<String> {
    let file = syn::parse_file(lib).expect("src/lib.rs parses");
    file.items
        .iter()
        .filter_map(|item| match item {
            syn::Item::Mod(m) => Some(m.ident.to_string()),
            _ => None,
        })
        .collect()
}

/// The modules named in the table of `src/lib.rs`'s doc comment under "The parts
/// of a ray tracer", in its order: the first cell of each row, without its link.
fn tabled(lib: &str) -> Vec<String> {
    lib.lines()
        .skip_while(|line| !line.starts_with("//! ## The parts"))
        .filter_map(|line| line.strip_prefix("//! | "))
        .filter_map(|row| row.split(" |").next())
        .filter_map(|cell| cell.split('`').nth(1))
        .filter(|name| *name != "module")
        .map(str::to_owned)
        .collect()
}

/// The top-level modules a file's code names as `crate::name` (in `use` lines and
/// paths; doc comments' links are not uses).
#[derive(Default)]
struct Uses(BTreeSet<String>);

impl<'a> Visit<'a> for Uses {
    fn visit_use_path(&mut self, path: &'a syn::UsePath) {
        if path.ident == "crate" {
            let mut names = BTreeSet::new();
            first_names(&path.tree, &mut names);
            self.0.extend(names);
        }
        syn::visit::visit_use_path(self, path);
    }

    fn visit_path(&mut self, path: &'a syn::Path) {
        let mut segments = path.segments.iter();
        if segments.next().is_some_and(|s| s.ident == "crate")
            && let Some(next) = segments.next()
        {
            self.0.insert(next.ident.to_string());
        }
        syn::visit::visit_path(self, path);
    }
}

/// The first name of each branch of a `use crate::...` tree.
fn first_names(tree: &syn::UseTree, names: &mut BTreeSet<String>) {
    match tree {
        syn::UseTree::Path(p) => {
            names.insert(p.ident.to_string());
        }
        syn::UseTree::Name(n) => {
            names.insert(n.ident.to_string());
        }
        syn::UseTree::Rename(r) => {
            names.insert(r.ident.to_string());
        }
        syn::UseTree::Group(g) => g.items.iter().for_each(|t| first_names(t, names)),
        syn::UseTree::Glob(_) => {}
    }
}

/// Every top-level module that the files of module `name` use, but itself.
fn uses_of(src: &Path, name: &str) -> BTreeSet<String> {
    let folder = src.join(name);
    let files = if folder.is_dir() {
        crate::view::rust_files_under(&folder).expect("a folder")
    } else {
        vec![src.join(format!("{name}.rs"))]
    };
    let mut uses = Uses::default();
    for file in files {
        let text = std::fs::read_to_string(&file).expect("a source file");
        let parsed = syn::parse_file(&text).unwrap_or_else(|e| panic!("{file:?}: {e}"));
        uses.visit_file(&parsed);
    }
    uses.0.remove(name);
    uses.0
}

#[test]
fn each_module_of_the_library_uses_only_those_listed_before_it() {
    let src = crate::root().join("src");
    let lib = std::fs::read_to_string(src.join("lib.rs")).unwrap();
    let order = declared(&lib);
    assert!(order.len() > 10, "{order:?}");
    for (place, name) in order.iter().enumerate() {
        let later: Vec<&String> = uses_of(&src, name)
            .into_iter()
            .filter_map(|used| order.iter().skip(place + 1).find(|m| **m == used))
            .collect();
        assert!(
            later.is_empty(),
            "src/{name} uses {later:?}, listed after it in src/lib.rs"
        );
    }
}

#[test]
fn the_table_of_the_library_lists_its_modules_in_the_mod_lines_order() {
    let lib = std::fs::read_to_string(crate::root().join("src/lib.rs")).unwrap();
    assert_eq!(tabled(&lib), declared(&lib));
}

#[test]
fn a_use_of_a_later_module_is_found_in_use_lines_and_paths_not_in_docs() {
    let code = "/// See [`crate::render`].\nuse crate::{maths::Real, geometry::Ray};\nfn f() { crate::scene::nearest(); }";
    let mut uses = Uses::default();
    uses.visit_file(&syn::parse_file(code).unwrap());
    let found: Vec<&str> = uses.0.iter().map(String::as_str).collect();
    assert_eq!(found, ["geometry", "maths", "scene"]);
}
