//! Films cached: a reference image (what `check` compares a student's image with,
//! what a study measures its renders against) is expensive, so it is rendered once
//! per scene and setting, and kept in a folder on disk (the command's) or in memory
//! (the book's check page, which has no disk, grading a class).

use std::collections::HashMap;
use std::hash::{DefaultHasher, Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::maths::{Colour, Real, to_double};
use crate::render::Film;
use crate::render::write_atomically;
use crate::scene::Scene;

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

/// What names the reference of `scene`: `text`, the scene file's text, edits
/// included, with the size, the samples and the seed.
pub fn reference_key(text: &str, scene: &Scene) -> String {
    let (camera, settings) = (scene.camera, scene.settings);
    format!(
        "{text}\n{}x{}, {} spp, seed {}",
        camera.width, camera.height, settings.samples, settings.seed
    )
}

/// Where the reference of `scene` is kept in `dir` ([`reference_key`] names the
/// file, see [`reference_path`]).
pub fn reference_file(dir: &Path, text: &str, scene: &Scene) -> PathBuf {
    reference_path(dir, &reference_key(text, scene))
}

/// Where references are kept, each under its [`reference_key`].
pub trait Films: Sync {
    /// The film kept under `key`, if there is one.
    fn load(&self, key: &str) -> Option<Film>;
    /// Keeps `film` under `key`.
    fn save(&self, key: &str, film: &Film) -> std::io::Result<()>;
    /// The folder where files a reference needs (a changed texture) may be written,
    /// if the references are kept in one.
    fn folder(&self) -> Option<&Path> {
        None
    }
}

/// References kept as files in a folder ([`reference_path`]), from one run to the
/// next.
pub struct Folder<'a>(pub &'a Path);

impl Films for Folder<'_> {
    fn load(&self, key: &str) -> Option<Film> {
        load_reference(&reference_path(self.0, key))
    }

    fn save(&self, key: &str, film: &Film) -> std::io::Result<()> {
        save_reference(&reference_path(self.0, key), film)
    }

    fn folder(&self) -> Option<&Path> {
        Some(self.0)
    }
}

/// References kept in memory for as long as the value lives: a page grading a class
/// renders each stage's reference once for all its students.
#[derive(Default)]
pub struct InMemory(Mutex<HashMap<String, Film>>);

impl InMemory {
    /// How many references are kept.
    pub fn len(&self) -> usize {
        self.0.lock().map_or(0, |films| films.len())
    }

    /// Whether none is.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl Films for InMemory {
    fn load(&self, key: &str) -> Option<Film> {
        self.0.lock().ok()?.get(key).cloned()
    }

    fn save(&self, key: &str, film: &Film) -> std::io::Result<()> {
        if let Ok(mut films) = self.0.lock() {
            films.insert(key.to_owned(), film.clone());
        }
        Ok(())
    }
}

/// The film of `scene` from the references `films`, if it was rendered before,
/// else rendered by `render` (which tells `progress` its work as it goes) and kept
/// there. `text` is the scene file's text, edits included: with the size, the
/// samples and the seed it names the reference ([`reference_key`]), so that any
/// change renders anew. A film found in `films` tells `progress` all its work at
/// once. The second value says whether the film could be kept: a folder that cannot
/// be written only costs time on the next run, so the caller decides what to say.
pub fn cached_render(
    films: &dyn Films,
    text: &str,
    scene: &Scene,
    progress: &(dyn Fn(u64) + Sync),
    render: impl FnOnce(&(dyn Fn(u64) + Sync)) -> Film,
) -> (Film, std::io::Result<()>) {
    let key = reference_key(text, scene);
    if let Some(film) = films.load(&key) {
        progress(u64::from(scene.camera.height) * u64::from(scene.settings.samples));
        return (film, Ok(()));
    }
    let film = render(progress);
    let saved = films.save(&key, &film);
    (film, saved)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_film_kept_in_memory_is_found_under_its_key_alone() {
        let films = InMemory::default();
        let film = Film {
            width: 1,
            height: 1,
            pixels: vec![Colour::new(0.25, 1e30, 0.0)],
        };
        assert!(films.is_empty() && films.folder().is_none());
        films.save("a", &film).unwrap();
        assert_eq!(films.load("a"), Some(film));
        assert_eq!(films.load("b"), None);
        assert_eq!(films.len(), 1);
    }

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
    fn a_render_is_kept_and_read_back_with_its_work_told_at_once() {
        let dir = tempfile::tempdir().unwrap();
        let mut scene = Scene::default();
        scene.camera.width = 2;
        scene.camera.height = 1;
        scene.settings.samples = 3;
        let film = Film {
            width: 2,
            height: 1,
            pixels: vec![Colour::new(0.25, 0.5, 1.0), Colour::ZERO],
        };
        let told = std::sync::atomic::AtomicU64::new(0);
        let progress = |n| {
            told.fetch_add(n, std::sync::atomic::Ordering::Relaxed);
        };
        let (first, saved) = cached_render(&Folder(dir.path()), "a", &scene, &progress, |_| {
            film.clone()
        });
        assert!(saved.is_ok() && first == film);
        assert_eq!(told.load(std::sync::atomic::Ordering::Relaxed), 0);
        let (again, _) = cached_render(
            &Folder(dir.path()),
            "a",
            &scene,
            &progress,
            |_| unreachable!(),
        );
        assert_eq!(again, film);
        assert_eq!(
            told.load(std::sync::atomic::Ordering::Relaxed),
            3,
            "1 row x 3 samples"
        );
        let (other, _) = cached_render(&Folder(dir.path()), "b", &scene, &progress, |_| Film {
            pixels: vec![Colour::ONE; 2],
            ..film.clone()
        });
        assert_ne!(other, film, "another text is another file");
        // Under a file, the folder cannot be made: the film comes back with the error.
        let file = dir.path().join("file");
        std::fs::write(&file, "").unwrap();
        let (kept, saved) = cached_render(&Folder(&file), "a", &scene, &progress, |_| film.clone());
        assert!(kept == film && saved.is_err());
    }

    #[test]
    fn the_key_names_the_file() {
        let dir = Path::new("cache");
        assert_eq!(reference_path(dir, "a"), reference_path(dir, "a"));
        assert_ne!(reference_path(dir, "a"), reference_path(dir, "b"));
    }
}
