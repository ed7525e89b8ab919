//! Variants of a scene: the same scene file with some of its keys changed, so that
//! two methods can be compared on exactly the same scene.

use std::fmt;

/// One change: the value of a scene-file key. A key under `meshes` changes every
/// mesh; any other names a table and a key, such as `render.bounces`.
#[derive(Clone, Debug, PartialEq)]
pub struct Edit {
    /// The dotted key, such as `render.light_sampling`.
    pub key: String,
    /// Its new value.
    pub value: toml::Value,
}

/// A labelled set of edits.
#[derive(Clone, Debug, PartialEq)]
pub struct Variant {
    /// The name shown in tables and plots.
    pub label: String,
    /// What changes.
    pub edits: Vec<Edit>,
}

/// A variant that could not be read or applied.
#[derive(Debug, PartialEq, thiserror::Error)]
#[error("variant `{text}`: {message}")]
pub struct VariantError {
    /// The variant as written.
    pub text: String,
    /// What is wrong.
    pub message: String,
}

impl Variant {
    /// Reads `label:key=value,key=value`. Values are TOML (`2`, `true`, `0.5`); a
    /// bare word is a string (`acceleration=bvh`). Without a label, the edits,
    /// separated by spaces, name the variant. The label is a column of the CSV, so it
    /// may not hold a comma.
    pub fn parse(text: &str) -> Result<Variant, VariantError> {
        let error = |message: String| VariantError {
            text: text.to_owned(),
            message,
        };
        let (label, list) = match text.split_once(':') {
            Some((label, list)) => (label.trim().to_owned(), list),
            None => (
                text.split(',').map(str::trim).collect::<Vec<_>>().join(" "),
                text,
            ),
        };
        if label.contains(',') {
            return Err(error(format!(
                "the label `{label}` holds a comma, which would split its CSV column"
            )));
        }
        let mut edits = vec![];
        for item in list.split(',').map(str::trim).filter(|i| !i.is_empty()) {
            let (key, value) = item
                .split_once('=')
                .ok_or_else(|| error(format!("`{item}` is not `key=value`")))?;
            let key = key.trim();
            if !key.contains('.') {
                return Err(error(format!(
                    "`{key}` names no table: write `render.{key}` or `meshes.{key}`"
                )));
            }
            edits.push(Edit {
                key: key.to_owned(),
                value: toml_value(value.trim()),
            });
        }
        if edits.is_empty() {
            return Err(error("no `key=value` edits".into()));
        }
        Ok(Variant { label, edits })
    }

    /// The scene file `source` with the edits applied. The result is checked like
    /// any scene file when it is read, so a misspelt key or a wrong value is refused
    /// there, by name.
    pub fn apply(&self, source: &str) -> Result<String, VariantError> {
        let error = |message: String| VariantError {
            text: self.to_string(),
            message,
        };
        let mut file: toml::Table = source
            .parse()
            .map_err(|e: toml::de::Error| error(e.message().to_owned()))?;
        for edit in &self.edits {
            let (table, key) = edit.key.split_once('.').unwrap_or(("", &edit.key));
            match file.get_mut(table) {
                Some(toml::Value::Table(t)) => {
                    t.insert(key.to_owned(), edit.value.clone());
                }
                Some(toml::Value::Array(items)) => {
                    for item in items.iter_mut().filter_map(toml::Value::as_table_mut) {
                        item.insert(key.to_owned(), edit.value.clone());
                    }
                }
                _ => return Err(error(format!("the scene has no `[{table}]` to change"))),
            }
        }
        toml::to_string(&file).map_err(|e| error(e.to_string()))
    }
}

impl fmt::Display for Variant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let edits: Vec<String> = self
            .edits
            .iter()
            .map(|e| format!("{}={}", e.key, e.value))
            .collect();
        write!(f, "{}:{}", self.label, edits.join(","))
    }
}

/// `text` as a TOML value, or as a string if it is not one.
fn toml_value(text: &str) -> toml::Value {
    format!("v = {text}")
        .parse::<toml::Table>()
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| toml::Value::String(text.to_owned()))
}

/// The comparisons `raycourse converge --compare` knows: each one's name, its
/// variants (`label:key=value,...`) and the edits that make the reference (the
/// truth every variant is measured against; none: the scene as it is).
const COMPARISONS: &[(&str, &[&str], &str)] = &[
    (
        "light-sampling",
        &[
            "naive:render.light_sampling=false",
            "light sampling:render.light_sampling=true",
        ],
        "",
    ),
    (
        "sampler",
        &[
            "independent:render.sampler=independent",
            "stratified:render.sampler=stratified",
            "sobol:render.sampler=sobol",
        ],
        "",
    ),
    (
        "adaptive",
        &[
            "independent:render.sampler=independent",
            "adaptive 0.05:render.noise=0.05",
            "sobol + adaptive 0.05:render.sampler=sobol,render.noise=0.05",
        ],
        "",
    ),
    (
        "bounces",
        &[
            "1 bounce:render.bounces=1",
            "2 bounces:render.bounces=2",
            "4 bounces:render.bounces=4",
            "8 bounces:render.bounces=8",
        ],
        "render.bounces=16",
    ),
    (
        "roulette",
        &[
            "limit 2:render.bounces=2",
            "limit 2 + roulette:render.bounces=2,render.russian_roulette=0.5",
        ],
        "render.bounces=16",
    ),
    (
        "acceleration",
        &[
            "brute force:render.acceleration=none",
            "bounding box:render.acceleration=bbox",
            "BVH:render.acceleration=bvh",
            "fast BVH:render.acceleration=bvh,render.fast=true",
        ],
        "",
    ),
    (
        "leaf",
        &[
            "leaf 1:render.acceleration=bvh,render.fast=true,render.leaf_size=1",
            "leaf 4:render.acceleration=bvh,render.fast=true,render.leaf_size=4",
            "leaf 16:render.acceleration=bvh,render.fast=true,render.leaf_size=16",
            "leaf 64:render.acceleration=bvh,render.fast=true,render.leaf_size=64",
        ],
        "",
    ),
    (
        "filter",
        &[
            "nearest:meshes.texture_filter=nearest",
            "bilinear:meshes.texture_filter=bilinear",
        ],
        "",
    ),
    (
        "triangle-test",
        &[
            "Moller-Trumbore:render.triangle_test=moller-trumbore",
            "watertight:render.triangle_test=watertight",
        ],
        "",
    ),
];

/// The names of the comparisons [`comparison`] knows.
pub fn comparison_names() -> impl Iterator<Item = &'static str> {
    COMPARISONS.iter().map(|c| c.0)
}

/// The comparison called `name`: its variants, and the edits that make its
/// reference.
pub fn comparison(name: &str) -> Option<(Vec<Variant>, Vec<Edit>)> {
    let (_, variants, reference) = COMPARISONS.iter().find(|c| c.0 == name)?;
    let parse = |text: &str| Variant::parse(text).expect("built-in variants are well formed");
    let reference = match *reference {
        "" => vec![],
        edits => parse(&format!("reference:{edits}")).edits,
    };
    Some((variants.iter().map(|t| parse(t)).collect(), reference))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = "[render]\nwidth = 4\nheight = 4\n\n[[meshes]]\nobj = \"a.obj\"\n\n[[meshes]]\nobj = \"b.obj\"\n";

    #[test]
    fn edits_change_a_table_and_every_mesh() {
        let variant =
            Variant::parse("smooth: render.bounces=2, meshes.texture_filter=bilinear").unwrap();
        assert_eq!(variant.label, "smooth");
        let edited: toml::Table = variant.apply(SCENE).unwrap().parse().unwrap();
        assert_eq!(edited["render"]["bounces"].as_integer(), Some(2));
        assert_eq!(edited["render"]["width"].as_integer(), Some(4));
        for mesh in edited["meshes"].as_array().unwrap() {
            assert_eq!(mesh["texture_filter"].as_str(), Some("bilinear"));
        }
    }

    #[test]
    fn unlabelled_edits_name_the_variant_without_commas() {
        let variant = Variant::parse("render.bounces=2, render.samples=4").unwrap();
        assert_eq!(variant.label, "render.bounces=2 render.samples=4");
        assert_eq!(variant.edits.len(), 2);
    }

    #[test]
    fn values_are_toml_or_bare_words() {
        assert_eq!(toml_value("true"), toml::Value::Boolean(true));
        assert_eq!(toml_value("0.5"), toml::Value::Float(0.5));
        assert_eq!(toml_value("fast"), toml::Value::String("fast".into()));
        assert_eq!(toml_value("\"a b\""), toml::Value::String("a b".into()));
    }

    #[test]
    fn malformed_variants_are_refused_with_the_reason() {
        let message = |text: &str| Variant::parse(text).unwrap_err().to_string();
        assert_eq!(
            message("x:bounces=2"),
            "variant `x:bounces=2`: `bounces` names no table: write `render.bounces` or `meshes.bounces`"
        );
        assert!(message("x:render.bounces").contains("is not `key=value`"));
        assert!(message("x:").contains("no `key=value` edits"));
        assert!(message("a,b:render.bounces=2").contains("label `a,b` holds a comma"));
        let missing = Variant::parse("x:light.radius=2").unwrap().apply(SCENE);
        assert!(missing.unwrap_err().message.contains("no `[light]`"));
    }

    #[test]
    fn every_comparison_is_defined() {
        for name in comparison_names() {
            let (variants, _) = comparison(name).unwrap();
            assert!(variants.len() >= 2, "{name}");
        }
        assert!(comparison("nothing").is_none());
    }
}
