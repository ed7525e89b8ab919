//! Films cached on disk: a reference image (what `check` compares a student's image
//! with, what a study measures its renders against) is expensive, so it is rendered
//! once per scene and setting.

use std::hash::{DefaultHasher, Hash, Hasher};
use std::path::{Path, PathBuf};

use crate::maths::{Colour, Real, to_double};
use crate::render::Film;
use crate::render::write_atomically;

/// The first line of a reference file.
const MAGIC: &[u8] = b"raycourse reference 1\n";

/// Where the reference described by `key` (the scene file's text after variants,
/// and every setting that changes the image) is kept in `dir`. The file name is a
/// hash of the key, so any change to the scene or its settings names a new file.
pub fn reference_path(dir: &Path, key: &str) -> PathBuf {
    let mut hasher = DefaultHasher::new();
    key.hash(&mut hasher);
    env!("CARGO_PKG_VERSION").hash(&mut hasher);
    dir.join(format!("{:016x}.ref", hasher.finish()))
}

/// The film stored at `path`, or `None` when there is none or it is not a
/// complete reference file (it is then rendered again).
pub fn load_reference(path: &Path) -> Option<Film> {
    let bytes = std::fs::read(path).ok()?;
    let rest = bytes.strip_prefix(MAGIC)?;
    let (size, values) = rest.split_at_checked(8)?;
    let width = u32::from_le_bytes(size[..4].try_into().ok()?);
    let height = u32::from_le_bytes(size[4..].try_into().ok()?);
    let count = width as usize * height as usize;
    if values.len() != count * 24 {
        return None;
    }
    let channel = |c: &[u8]| f64::from_le_bytes(c.try_into().expect("8 bytes")) as Real;
    let pixels = values
        .chunks_exact(24)
        .map(|p| Colour::new(channel(&p[..8]), channel(&p[8..16]), channel(&p[16..])))
        .collect();
    Some(Film {
        width,
        height,
        pixels,
    })
}

/// Stores `film` at `path` in double precision, whatever this build's precision,
/// atomically: an interrupted run leaves no half-written reference.
pub fn save_reference(path: &Path, film: &Film) -> std::io::Result<()> {
    let mut bytes = MAGIC.to_vec();
    bytes.extend(film.width.to_le_bytes());
    bytes.extend(film.height.to_le_bytes());
    for pixel in &film.pixels {
        for v in pixel.to_array() {
            bytes.extend(to_double(v).to_le_bytes());
        }
    }
    write_atomically(path, &bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_saved_reference_loads_bit_for_bit() {
        let dir = tempfile::tempdir().unwrap();
        let film = Film {
            width: 2,
            height: 1,
            pixels: vec![
                Colour::new(0.1, 1e30, 0.0),
                Colour::new(3.0, 2.5, 1e-300 as Real),
            ],
        };
        let path = reference_path(dir.path(), "scene");
        assert_eq!(load_reference(&path), None);
        save_reference(&path, &film).unwrap();
        assert_eq!(load_reference(&path), Some(film));
        std::fs::write(&path, &std::fs::read(&path).unwrap()[..40]).unwrap();
        assert_eq!(
            load_reference(&path),
            None,
            "a truncated file is not a reference"
        );
    }

    #[test]
    fn the_key_names_the_file() {
        let dir = Path::new("cache");
        assert_eq!(reference_path(dir, "a"), reference_path(dir, "a"));
        assert_ne!(reference_path(dir, "a"), reference_path(dir, "b"));
    }
}
