//! What a stage should give at a student's image size: its reference images,
//! rendered once and cached.

use std::num::NonZeroU32;
use std::path::Path;

use crate::files::Files;
use crate::render::cache::{Films, cached_render};
use crate::render::{Film, Render};
use crate::render_reporting;
use crate::scene::Scene;
use crate::scene_file::{Overrides, SESSION, SceneError, Stage, parse_scene_from};

/// The seeds of the two halves of a Monte Carlo reference: other random numbers
/// than any stage's own.
const SEEDS: [u64; 2] = [0x00c0_ffee, 0x0bad_cafe];

/// The stage's reference at one size.
pub struct Expected {
    /// The stage's scene at the student's size, with the course's settings.
    pub scene: Scene,
    /// Whether the stage draws no random number: one sample per pixel.
    pub deterministic: bool,
    /// One film for a deterministic stage; for a Monte Carlo one, two independent
    /// films of half the course's samples each.
    pub films: Vec<Film>,
}

impl Expected {
    /// The reference film: the one film, or the mean of the two halves, which has
    /// the course's number of samples.
    pub fn film(&self) -> Film {
        let mut film = self.films[0].clone();
        if let Some(other) = self.films.get(1) {
            for (a, b) in film.pixels.iter_mut().zip(&other.pixels) {
                *a = (*a + *b) * 0.5;
            }
        }
        film
    }
}

/// What reads a stage's scene file and renders the references: the course's code
/// ([`Course`]), or any engine that gives the course's bytes in less time.
pub trait Renderer: Sync {
    /// The scene of scene-file text `text`, named `path` in errors, with `overrides`,
    /// the files it refers to read from `files`.
    fn scene(
        &self,
        text: &str,
        path: &Path,
        overrides: &Overrides,
        files: &dyn Files,
    ) -> Result<Scene, SceneError>;

    /// `scene` rendered on the current thread pool, `progress` told of each row's
    /// samples as they are done.
    fn render(&self, scene: &Scene, progress: &(dyn Fn(u64) + Sync)) -> Render;
}

/// The course's code: [`parse_scene_from`] and [`render_reporting`].
pub struct Course;

impl Renderer for Course {
    fn scene(
        &self,
        text: &str,
        path: &Path,
        overrides: &Overrides,
        files: &dyn Files,
    ) -> Result<Scene, SceneError> {
        parse_scene_from(text, path, overrides, files)
    }

    fn render(&self, scene: &Scene, progress: &(dyn Fn(u64) + Sync)) -> Render {
        render_reporting(scene, progress)
    }
}

/// Where an image is rendered from: the stage, the edits of its scene file, the size
/// and the folder of cached references.
pub struct Source<'a> {
    /// The stage.
    pub stage: &'a Stage,
    /// Width and height of the student's image.
    pub size: (u32, u32),
    /// Where the references are kept: a folder ([`crate::render::cache::Folder`]),
    /// or memory.
    pub cache: &'a dyn Films,
    /// Where the stage's meshes and textures are read.
    pub files: &'a dyn Files,
    /// Told how many samples of each row are done, for a progress bar.
    pub progress: &'a (dyn Fn(u64) + Sync),
    /// What reads the scene and renders it.
    pub renderer: &'a dyn Renderer,
}

impl Source<'_> {
    /// The stage's reference at the student's size (see [`Expected`]).
    pub fn expected(&self) -> Result<Expected, SceneError> {
        let scene = self.scene(self.stage.source, None, None)?;
        let samples = scene.settings.samples;
        let deterministic = samples == 1;
        let films = if deterministic {
            vec![self.film(self.stage.source, 1, None)?]
        } else {
            self.halves((samples / 2).max(1))?
        };
        Ok(Expected {
            scene,
            deterministic,
            films,
        })
    }

    /// Two independent renders of the stage at `samples` per pixel each: a reference
    /// with the noise of a student's render at those samples, whose clipping to full
    /// white (which biases noisy bright pixels downwards) it shares.
    pub fn halves(&self, samples: u32) -> Result<Vec<Film>, SceneError> {
        SEEDS
            .iter()
            .map(|&seed| self.film(self.stage.source, samples, Some(seed)))
            .collect()
    }

    /// The scene of the file text `text` at the student's size, with `samples` and
    /// `seed` when given, read by the source's renderer.
    pub fn scene(
        &self,
        text: &str,
        samples: Option<u32>,
        seed: Option<u64>,
    ) -> Result<Scene, SceneError> {
        let overrides = Overrides {
            width: NonZeroU32::new(self.size.0),
            height: NonZeroU32::new(self.size.1),
            samples: samples.and_then(NonZeroU32::new),
            seed,
            ..Overrides::default()
        };
        self.renderer
            .scene(text, &self.stage.file(), &overrides, self.files)
    }

    /// The film of the scene-file text `text` at the student's size, with `samples`
    /// and `seed`, from the cache or rendered and cached.
    pub fn film(&self, text: &str, samples: u32, seed: Option<u64>) -> Result<Film, SceneError> {
        let text = searched_by_hierarchy(text);
        let scene = self.scene(&text, Some(samples), seed)?;
        let render = |progress: &(dyn Fn(u64) + Sync)| self.renderer.render(&scene, progress).film;
        // A cache that cannot be written only costs time on the next check.
        let (film, _saved) = cached_render(self.cache, &text, &scene, self.progress, render);
        Ok(film)
    }
}

/// The scene file `text` with its meshes searched by a hierarchy where this build
/// has one (session 6): the same hits as brute force, in less time.
fn searched_by_hierarchy(text: &str) -> String {
    let Ok(mut file) = text.parse::<toml::Table>() else {
        return text.to_owned();
    };
    let render = file.get_mut("render").and_then(toml::Value::as_table_mut);
    match render {
        Some(render) if SESSION >= 6 => {
            render.insert("acceleration".into(), "bvh".into());
            toml::to_string(&file).unwrap_or_else(|_| text.to_owned())
        }
        _ => text.to_owned(),
    }
}
