//! The live demos' list of the course functions a render runs
//! (`web/src/functions.rs`) held against the code: every name it can show is a
//! function of `src/` (`Type::method` in an impl of that type, `module::function`
//! in that module's file, or a free function), and one that a render can reach,
//! following calls by name from `render_reporting`, the course's and the engines'
//! entry. A renamed, removed or never-called function fails here, not in a reader's
//! page.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use syn::visit::Visit;

/// A function of the library: where it is defined and the names its body calls.
#[derive(Debug, Default)]
struct Function {
    /// The type of its `impl` block (its last name), if it is a method.
    owner: Option<String>,
    /// The stem of its file (`paths_at_once`).
    module: String,
    /// The last names of the paths its body calls or passes on.
    calls: BTreeSet<String>,
}

/// Every function of the files under `src`, by name (a name may have several).
fn functions(src: &Path) -> BTreeMap<String, Vec<Function>> {
    let mut all: BTreeMap<String, Vec<Function>> = BTreeMap::new();
    let files = crate::view::rust_files_under(src).expect("the crate's sources");
    let library = files.iter().filter(|f| {
        !f.components().any(|c| c.as_os_str() == "commands") && !f.ends_with("main.rs")
    });
    for file in library {
        let text = std::fs::read_to_string(file).expect("a source file");
        let parsed = syn::parse_file(&text).unwrap_or_else(|e| panic!("{file:?}: {e}"));
        let module = file.file_stem().unwrap().to_string_lossy().into_owned();
        let mut definitions = Definitions {
            module,
            owner: None,
            found: vec![],
        };
        definitions.visit_file(&parsed);
        for (name, function) in definitions.found {
            all.entry(name).or_default().push(function);
        }
    }
    all
}

/// Collects a file's functions, with the impl block each is in.
struct Definitions {
    module: String,
    owner: Option<String>,
    found: Vec<(String, Function)>,
}

impl<'a> Visit<'a> for Definitions {
    fn visit_item_impl(&mut self, item: &'a syn::ItemImpl) {
        let outer = self.owner.take();
        if let syn::Type::Path(path) = &*item.self_ty {
            self.owner = path.path.segments.last().map(|s| s.ident.to_string());
        }
        syn::visit::visit_item_impl(self, item);
        self.owner = outer;
    }

    fn visit_item_fn(&mut self, item: &'a syn::ItemFn) {
        let outer = self.owner.take();
        self.add(&item.sig.ident, &item.block);
        syn::visit::visit_item_fn(self, item);
        self.owner = outer;
    }

    fn visit_impl_item_fn(&mut self, item: &'a syn::ImplItemFn) {
        self.add(&item.sig.ident, &item.block);
        syn::visit::visit_impl_item_fn(self, item);
    }
}

impl Definitions {
    /// Records the function `name` with the calls of `body`.
    fn add(&mut self, name: &syn::Ident, body: &syn::Block) {
        let mut calls = Calls::default();
        calls.visit_block(body);
        let function = Function {
            owner: self.owner.clone(),
            module: self.module.clone(),
            calls: calls.0,
        };
        self.found.push((name.to_string(), function));
    }
}

/// The last names of the paths and methods a body names.
#[derive(Default)]
struct Calls(BTreeSet<String>);

impl<'a> Visit<'a> for Calls {
    fn visit_expr_path(&mut self, path: &'a syn::ExprPath) {
        if let Some(last) = path.path.segments.last() {
            self.0.insert(last.ident.to_string());
        }
        syn::visit::visit_expr_path(self, path);
    }

    fn visit_expr_method_call(&mut self, call: &'a syn::ExprMethodCall) {
        self.0.insert(call.method.to_string());
        syn::visit::visit_expr_method_call(self, call);
    }
}

/// The names of every function that calls from `root` can reach, `root` included.
fn reachable(all: &BTreeMap<String, Vec<Function>>, root: &str) -> BTreeSet<String> {
    let mut seen = BTreeSet::from([root.to_owned()]);
    let mut next = vec![root.to_owned()];
    while let Some(name) = next.pop() {
        for function in all.get(&name).into_iter().flatten() {
            for call in &function.calls {
                if all.contains_key(call) && seen.insert(call.clone()) {
                    next.push(call.clone());
                }
            }
        }
    }
    seen
}

/// The names `web/src/functions.rs` can list: the string literals of its code
/// (not its doc comments or tests, not the patterns that match a search's name),
/// each without a
/// parenthesised remark (`intersect_triangle (watertight)`).
fn listed(text: &str) -> BTreeSet<String> {
    #[derive(Default)]
    struct Strings(BTreeSet<String>);
    impl<'a> Visit<'a> for Strings {
        fn visit_expr_lit(&mut self, lit: &'a syn::ExprLit) {
            if let syn::Lit::Str(s) = &lit.lit {
                let name = s.value();
                self.0
                    .insert(name.split(" (").next().unwrap_or("").to_owned());
            }
        }
        fn visit_pat(&mut self, _: &'a syn::Pat) {}
        fn visit_attribute(&mut self, _: &'a syn::Attribute) {}
        fn visit_item_mod(&mut self, _: &'a syn::ItemMod) {}
    }
    let mut strings = Strings::default();
    strings.visit_file(&syn::parse_file(text).expect("web/src/functions.rs parses"));
    strings.0
}

/// Whether `name` (`Type::method`, `module::function` or `function`) is defined.
fn defined(all: &BTreeMap<String, Vec<Function>>, name: &str) -> bool {
    let (qualifier, function) = name
        .rsplit_once("::")
        .map_or((None, name), |(q, f)| (Some(q), f));
    all.get(function)
        .into_iter()
        .flatten()
        .any(|f| match qualifier {
            None => f.owner.is_none(),
            Some(q) => f.owner.as_deref() == Some(q) || (f.owner.is_none() && f.module == q),
        })
}

#[test]
fn every_function_the_demos_list_is_one_a_render_reaches() {
    let root = crate::root();
    let all = functions(&root.join("src"));
    let reached = reachable(&all, "render_reporting");
    let names = listed(&std::fs::read_to_string(root.join("web/src/functions.rs")).unwrap());
    assert!(names.len() > 40, "{names:?}");
    for name in &names {
        assert!(
            defined(&all, name),
            "the demos list `{name}`, which src/ does not define"
        );
        let function = name.rsplit("::").next().unwrap();
        assert!(
            reached.contains(function),
            "the demos list `{name}`, which no render reaches"
        );
    }
}

#[test]
fn a_function_is_found_by_its_type_or_module_and_reached_through_calls() {
    let code = "impl Scene { fn nearest(&self) { self.hit(); helper(); } }\n\
                fn hit() {} fn helper() { more() } fn more() {} fn alone() {}";
    let mut definitions = Definitions {
        module: "scene".into(),
        owner: None,
        found: vec![],
    };
    definitions.visit_file(&syn::parse_file(code).unwrap());
    let mut all: BTreeMap<String, Vec<Function>> = BTreeMap::new();
    for (name, function) in definitions.found {
        all.entry(name).or_default().push(function);
    }
    assert!(defined(&all, "Scene::nearest") && defined(&all, "scene::helper"));
    assert!(!defined(&all, "Camera::nearest") && !defined(&all, "nearest"));
    let reached = reachable(&all, "nearest");
    assert_eq!(
        reached,
        ["helper", "hit", "more", "nearest"]
            .map(String::from)
            .into()
    );
}
