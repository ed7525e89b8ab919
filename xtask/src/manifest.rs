//! The view's `Cargo.toml`: the crate's own, without session features.

use toml_edit::{DocumentMut, Item, Value};

use crate::cfg::session_of;

/// `Cargo.toml` text as it stands after `session`: its version marked with the
/// session (`0.1.0-s3`, so that views built side by side stay apart); no features
/// `s1`..`s7`, no `cli` (a view always has its command line: the feature's
/// dependencies plain, no target requiring it) and no default features; dependencies that a session brings (`dep:tobj`) plain when
/// the view has that session, absent otherwise (those beyond the course always); a workspace of its own (an empty
/// `[workspace]` table, so that the view builds wherever it is written, even
/// inside this repository's `target/`).
pub fn view_manifest(text: &str, session: u32) -> Result<String, String> {
    let mut doc: DocumentMut = text.parse().map_err(|e| format!("Cargo.toml: {e}"))?;
    doc["workspace"] = toml_edit::table();
    let version = doc["package"]["version"]
        .as_str()
        .unwrap_or("0.1.0")
        .to_owned();
    doc["package"]["version"] = toml_edit::value(format!("{version}-s{session}"));
    let mut brought = vec![];
    if let Some(features) = doc.get_mut("features").and_then(Item::as_table_mut) {
        // The command line's feature goes as a session every view holds would.
        let named: Vec<(u32, String)> = features
            .iter()
            .filter_map(|(name, _)| {
                let session = if name == CLI {
                    Some(0)
                } else {
                    session_of(name)
                };
                session.map(|n| (n, name.to_owned()))
            })
            .collect();
        for (n, name) in named {
            let deps: Vec<String> = features
                .get(&name)
                .and_then(Item::as_array)
                .map(|a| {
                    a.iter()
                        .filter_map(Value::as_str)
                        .map(str::to_owned)
                        .collect()
                })
                .unwrap_or_default();
            for dep in deps.iter().filter_map(|d| d.strip_prefix("dep:")) {
                brought.push((dep.to_owned(), n));
            }
            features.remove(&name);
        }
        features.remove("default");
        features.decor_mut().set_prefix("\n");
    }
    if let Some(deps) = doc
        .get_mut("dependencies")
        .and_then(Item::as_table_like_mut)
    {
        for (dep, n) in brought {
            if n > session {
                deps.remove(&dep);
            } else if let Some(table) = deps.get_mut(&dep).and_then(Item::as_table_like_mut) {
                table.remove("optional");
            }
        }
    }
    for targets in ["bin", "test"] {
        if let Some(tables) = doc.get_mut(targets).and_then(Item::as_array_of_tables_mut) {
            for table in tables.iter_mut() {
                table.remove("required-features");
            }
        }
    }
    Ok(doc.to_string())
}

/// The feature of the command line, which every view holds.
const CLI: &str = "cli";

#[cfg(test)]
mod tests {
    use super::view_manifest;

    const MANIFEST: &str = r#"[workspace]
members = [".", "xtask"]

[package]
name = "raycourse"
version = "0.1.0"

[features]
default = ["s7"]
s1 = []
s5 = ["s1", "dep:tobj"]
s7 = ["s5"]
beyond = ["s7", "dep:wide"]
f32 = []

cli = ["dep:clap"]

[dependencies]
clap = { version = "4", optional = true }
glam = "0.30"
tobj = { version = "4", optional = true }
wide = { version = "1", optional = true }

[[bin]]
name = "raycourse"
required-features = ["cli"]
"#;

    #[test]
    fn a_view_has_no_session_feature_and_a_workspace_of_its_own() {
        let text = view_manifest(MANIFEST, 4).unwrap();
        let doc: toml_edit::DocumentMut = text.parse().unwrap();
        assert!(doc["workspace"].as_table().unwrap().is_empty());
        assert_eq!(doc["package"]["version"].as_str(), Some("0.1.0-s4"));
        let features = doc["features"].as_table().unwrap();
        assert_eq!(features.iter().map(|(k, _)| k).collect::<Vec<_>>(), ["f32"]);
        assert!(doc["dependencies"].get("tobj").is_none());
    }

    #[test]
    fn a_dependency_a_held_session_brings_is_plain() {
        let text = view_manifest(MANIFEST, 5).unwrap();
        let doc: toml_edit::DocumentMut = text.parse().unwrap();
        let tobj = doc["dependencies"]["tobj"].as_inline_table().unwrap();
        assert!(tobj.get("optional").is_none());
    }

    #[test]
    fn a_view_always_has_its_command_line() {
        let text = view_manifest(MANIFEST, 1).unwrap();
        let doc: toml_edit::DocumentMut = text.parse().unwrap();
        assert!(doc["features"].get("cli").is_none(), "{text}");
        let clap = doc["dependencies"]["clap"].as_inline_table().unwrap();
        assert!(clap.get("optional").is_none(), "{text}");
        let bin = &doc["bin"].as_array_of_tables().unwrap().get(0).unwrap();
        assert!(bin.get("required-features").is_none(), "{text}");
    }

    #[test]
    fn no_view_holds_what_goes_beyond_the_course() {
        let text = view_manifest(MANIFEST, 7).unwrap();
        let doc: toml_edit::DocumentMut = text.parse().unwrap();
        assert!(doc["features"].get("beyond").is_none(), "{text}");
        assert!(doc["dependencies"].get("wide").is_none(), "{text}");
    }
}
