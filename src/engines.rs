//! Beyond the course: which engine renders a scene. Every stage renders through the
//! course's functions ([`render::render_reporting`](crate::render::render_reporting))
//! unless its settings ask for more. A sampler or adaptive sampling (`[render]
//! sampler`, `noise`) takes the samplers' pixel loop ([`samplers::pixel`]). The fast
//! engine (`[render] fast = true`, `--fast`) gives the course's bytes in less time:
//! it follows four paths at a time where every object is diffuse (spheres, and
//! meshes, which always are; [`paths_at_once`]), a mesh's hierarchy is its own when
//! the scene file is read (`scene_file/session6.rs`), and any other scene takes the
//! course's code (or the samplers').

use crate::Render;
use crate::fast::paths::paths_at_once;
use crate::fast::paths::sphere_lanes::SphereLanes;
use crate::render::render_rows;
use crate::samplers;
use crate::scene::Scene;
use crate::scene::beyond::Sampler;

/// Renders `scene` on the current rayon thread pool with the engine its settings
/// choose, calling `progress` as [`render_rows`] does.
pub fn render_reporting(scene: &Scene, progress: &(dyn Fn(u64) + Sync)) -> Render {
    if scene.settings.beyond.fast && paths_at_once::applies(scene) {
        let spheres = SphereLanes::new(&scene.spheres);
        return render_rows(scene, progress, |row, line, taken| {
            paths_at_once::row(scene, &spheres, row, line, taken)
        });
    }
    let beyond = scene.settings.beyond;
    if beyond.sampler != Sampler::Independent || beyond.noise.is_some() {
        return render_rows(scene, progress, |row, line, taken| {
            samplers::pixel::row(scene, row, line, taken)
        });
    }
    crate::render::render_reporting(scene, progress)
}

/// Renders `scene` with the engine its settings choose: [`render_reporting`] with no
/// one to report to.
pub fn render(scene: &Scene) -> Render {
    render_reporting(scene, &|_| {})
}
