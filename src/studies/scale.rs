//! A scene made larger or smaller and moved: the same picture, in other numbers.

use crate::maths::{Real, Vec3, to_double};

// ANCHOR: scaled
/// The scene file `source` with its scene made `factor` times larger about the
/// origin, then moved by `shift`: every point `p` becomes `factor p + shift`, every
/// length `factor` times longer, and the light's power `factor^2` times larger, so
/// that the light reaching each point is unchanged (a point light gives
/// `I cos / (4 pi d^2)`, a sphere light glows with `I / (4 pi^2 R^2)`). The renderer
/// has no length of its own, so any difference between the two images is rounding:
/// how the scale sweep of the tests and the book measures it. The scaled file is
/// read like any other, so every part of the scene, meshes and their hierarchies
/// included, is built again at its new size.
pub fn scaled(source: &str, factor: Real, shift: Vec3) -> Result<String, String> {
    let mut file: toml::Table = source.parse().map_err(|e: toml::de::Error| e.to_string())?;
    let (factor, shift) = (to_double(factor), shift.to_array().map(to_double));
    if let Some(camera) = table(&mut file, "camera") {
        move_point(camera, "position", factor, shift);
        move_point(camera, "look_at", factor, shift);
        if let Some(lens) = table(camera, "lens") {
            multiply(lens, "aperture", factor);
            multiply(lens, "focus", factor);
        }
    }
    if let Some(light) = table(&mut file, "light") {
        move_point(light, "position", factor, shift);
        multiply(light, "radius", factor);
        multiply(light, "intensity", factor * factor);
    }
    for sphere in entries(&mut file, "spheres") {
        move_point(sphere, "centre", factor, shift);
        multiply(sphere, "radius", factor);
    }
    for mesh in entries(&mut file, "meshes") {
        mesh.entry("scale").or_insert(1.0.into());
        mesh.entry("translation").or_insert(vec![0.0; 3].into());
        multiply(mesh, "scale", factor);
        move_point(mesh, "translation", factor, shift);
    }
    toml::to_string(&file).map_err(|e| e.to_string())
}
// ANCHOR_END: scaled

/// Moves the point `[x, y, z]` of `key` in `table`, if there is one, to
/// `factor p + shift`.
fn move_point(table: &mut toml::Table, key: &str, factor: f64, shift: [f64; 3]) {
    if let Some(point) = table.get_mut(key).and_then(toml::Value::as_array_mut) {
        for (x, s) in point.iter_mut().zip(shift) {
            *x = (number(x) * factor + s).into();
        }
    }
}

/// Multiplies the number of `key` in `table`, if there is one, by `by`.
fn multiply(table: &mut toml::Table, key: &str, by: f64) {
    if let Some(value) = table.get_mut(key) {
        *value = (number(value) * by).into();
    }
}

/// The table `name` of `file` (`[camera]`, `[light]`), if there is one.
fn table<'a>(file: &'a mut toml::Table, name: &str) -> Option<&'a mut toml::Table> {
    file.get_mut(name).and_then(toml::Value::as_table_mut)
}

/// The tables of the array `name` of `file` (`[[spheres]]`, `[[meshes]]`).
fn entries<'a>(file: &'a mut toml::Table, name: &str) -> impl Iterator<Item = &'a mut toml::Table> {
    let array = file.get_mut(name).and_then(toml::Value::as_array_mut);
    array
        .into_iter()
        .flatten()
        .filter_map(toml::Value::as_table_mut)
}

/// A TOML number as a float, whether written as an integer or not (0 otherwise).
fn number(value: &toml::Value) -> f64 {
    value
        .as_float()
        .or_else(|| value.as_integer().map(|i| i as f64))
        .unwrap_or(0.0)
}
