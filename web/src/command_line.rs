//! For the tests: a stage rendered as the command line renders it, to compare the
//! page's work with.

use raycourse::Overrides;
use raycourse::maths::Real;

use crate::assets;

/// The RGB bytes of the command line's render of the stage `name` at `size` x
/// `size`, displayed with `gamma`, or with the stage's own where `None`.
pub fn command_line_render(name: &str, size: u32, gamma: Option<Real>) -> Vec<u8> {
    let stage = raycourse::stages().find(|s| s.name == name).unwrap();
    let overrides = Overrides::sized(size, size, 0);
    let scene = stage.scene_from(&overrides, assets::stage_files()).unwrap();
    let gamma = gamma.unwrap_or(scene.settings.gamma);
    raycourse::render(&scene).film.to_rgb8(gamma)
}
