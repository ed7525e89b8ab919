//! Beyond the course: which engine renders a scene. A scene renders through the
//! course's functions ([`render::render_reporting`](crate::render::render_reporting))
//! unless the settings beyond the course ([`Beyond`], read with the scene by
//! [`scene_file::beyond`](crate::scene_file::beyond)) ask for more. A sampler or
//! adaptive sampling (`[render] sampler`, `noise`) takes the samplers' pixel loop
//! ([`samplers::pixel`]). The fast engine (`[render] fast = true`, `--fast`) gives the
//! course's bytes in less time: it follows four paths at a time where every object
//! is diffuse (spheres, and meshes, which always are; [`paths_at_once`]), a mesh's
//! hierarchy is its own when the scene file is read, and any other scene takes the
//! course's code (or the samplers').

use std::path::Path;

use crate::Render;
use crate::check::expected::Renderer;
use crate::fast::paths::paths_at_once;
use crate::fast::paths::sphere_lanes::SphereLanes;
use crate::files::Files;
use crate::maths::Colour;
use crate::render::render_rows;
use crate::render::rows::render_row;
use crate::samplers;
use crate::scene::Scene;
use crate::scene::beyond::{Beyond, Sampler};
use crate::scene_file::beyond::{BeyondOverrides, parse_with_beyond};
use crate::scene_file::{Overrides, SceneError};

/// The engine that a scene's settings beyond the course choose, ready to render
/// its rows one at a time: for [`render_reporting`], and for a page that shows each
/// row as it comes.
pub struct Engine<'s> {
    scene: &'s Scene,
    beyond: Beyond,
    /// The scene's spheres for the fast engine's four paths at a time, where it
    /// follows them.
    spheres: Option<SphereLanes>,
}

impl<'s> Engine<'s> {
    /// The engine that `beyond` chooses for `scene`.
    pub fn new(scene: &'s Scene, beyond: Beyond) -> Self {
        let four_at_a_time = beyond.fast && paths_at_once::applies(scene);
        let spheres = four_at_a_time.then(|| SphereLanes::new(&scene.spheres));
        Engine {
            scene,
            beyond,
            spheres,
        }
    }

    /// Renders row `row` into `line` (each pixel's radiance) and `taken` (the samples
    /// each took); returns the rays traced and the samples dropped, as the course's
    /// [`render_row`] does.
    pub fn row(&self, row: u32, line: &mut [Colour], taken: &mut [u32]) -> (u64, u64) {
        let (scene, beyond) = (self.scene, &self.beyond);
        if let Some(spheres) = &self.spheres {
            return paths_at_once::row(scene, beyond, spheres, row, line, taken);
        }
        if beyond.sampler != Sampler::Independent || beyond.noise.is_some() {
            return samplers::pixel::row(scene, beyond, row, line, taken);
        }
        render_row(scene, row, line, taken)
    }
}

/// Renders `scene` on the current rayon thread pool with the engine that `beyond`
/// chooses ([`Engine`]), calling `progress` as [`render_rows`] does.
pub fn render_reporting(scene: &Scene, beyond: &Beyond, progress: &(dyn Fn(u64) + Sync)) -> Render {
    let engine = Engine::new(scene, *beyond);
    render_rows(scene, progress, |row, line, taken| {
        engine.row(row, line, taken)
    })
}

/// Renders `scene` with the engine that `beyond` chooses: [`render_reporting`] with
/// no one to report to.
pub fn render(scene: &Scene, beyond: &Beyond) -> Render {
    render_reporting(scene, beyond, &|_| {})
}

/// The fast engine as `check`'s renderer: the course's references, in less time.
pub struct Fast;

impl Renderer for Fast {
    fn scene(
        &self,
        text: &str,
        path: &Path,
        overrides: &Overrides,
        files: &dyn Files,
    ) -> Result<Scene, SceneError> {
        let fast = BeyondOverrides {
            fast: true,
            ..BeyondOverrides::default()
        };
        Ok(parse_with_beyond(text, path, overrides, &fast, files)?.0)
    }

    fn render(&self, scene: &Scene, progress: &(dyn Fn(u64) + Sync)) -> Render {
        let fast = Beyond {
            fast: true,
            ..Beyond::default()
        };
        render_reporting(scene, &fast, progress)
    }
}
