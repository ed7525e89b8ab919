//! A scene file with some of its keys changed: what a demo's controls do. Each edit
//! names a key by its path, its parts separated by dots, a number picking an item of
//! an array (`spheres.0.material`), and gives the new value; `null` removes the key.
//! The edited text is then read and checked like any scene file, so a wrong key or
//! value is refused there, by name.

/// `source` with the edits of the JSON object `edits` applied, as TOML text.
pub fn apply(source: &str, edits: &str) -> Result<String, String> {
    let mut file: toml::Table = source.parse().map_err(|e: toml::de::Error| e.to_string())?;
    let edits: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(edits).map_err(|e| format!("the edits are not a JSON object: {e}"))?;
    for (key, value) in edits {
        let value = match value {
            serde_json::Value::Null => None,
            value => Some(toml::Value::try_from(&value).map_err(|e| format!("key `{key}`: {e}"))?),
        };
        set(&mut file, &key, value)?;
    }
    toml::to_string(&file).map_err(|e| e.to_string())
}

/// Sets the key at the dotted path `key` of `file` to `value`, or removes it for
/// `None`. A list's item is named by its number; a missing table on the way is made.
fn set(file: &mut toml::Table, key: &str, value: Option<toml::Value>) -> Result<(), String> {
    let wrong = |what: String| format!("key `{key}`: {what}");
    let parts: Vec<&str> = key.split('.').collect();
    let (last, path) = parts.split_last().expect("split gives at least one part");
    let mut table = file;
    let mut parts = path.iter();
    while let Some(part) = parts.next() {
        let next = table
            .entry(*part)
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        table = match next {
            toml::Value::Table(t) => t,
            toml::Value::Array(items) => {
                let index = parts.next().and_then(|i| i.parse::<usize>().ok());
                let index = index.ok_or_else(|| {
                    wrong(format!("`{part}` is a list: name an item by its number"))
                })?;
                items
                    .get_mut(index)
                    .and_then(toml::Value::as_table_mut)
                    .ok_or_else(|| wrong(format!("`{part}` has no item {index}")))?
            }
            _ => return Err(wrong(format!("`{part}` is not a table"))),
        };
    }
    match value {
        Some(value) => table.insert(last.to_string(), value),
        None => table.remove(*last),
    };
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const ROOM: &str = "[camera]\nfov = 60\n[[spheres]]\nradius = 1\n[[spheres]]\nradius = 2\n";

    #[test]
    fn keys_of_tables_and_items_of_lists_change() {
        let edited = apply(ROOM, r#"{"camera.fov": 40, "spheres.1.radius": 5}"#).unwrap();
        let file: toml::Table = edited.parse().unwrap();
        assert_eq!(file["camera"]["fov"].as_integer(), Some(40));
        assert_eq!(file["spheres"][0]["radius"].as_integer(), Some(1));
        assert_eq!(file["spheres"][1]["radius"].as_integer(), Some(5));
    }

    #[test]
    fn null_removes_a_key_and_missing_tables_are_made() {
        let edited = apply(ROOM, r#"{"camera.fov": null, "render.gamma": 2.2}"#).unwrap();
        let file: toml::Table = edited.parse().unwrap();
        assert!(file["camera"].get("fov").is_none());
        assert_eq!(file["render"]["gamma"].as_float(), Some(2.2));
    }

    #[test]
    fn a_wrong_path_is_refused_by_name() {
        let error = apply(ROOM, r#"{"spheres.7.radius": 1}"#).unwrap_err();
        assert_eq!(error, "key `spheres.7.radius`: `spheres` has no item 7");
        let error = apply(ROOM, r#"{"spheres.radius": 1}"#).unwrap_err();
        assert!(error.contains("name an item by its number"), "{error}");
        let error = apply(ROOM, r#"{"camera.fov.x": 1}"#).unwrap_err();
        assert!(error.contains("`fov` is not a table"), "{error}");
        assert!(
            apply(ROOM, "[1]")
                .unwrap_err()
                .contains("not a JSON object")
        );
    }
}
