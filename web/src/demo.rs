//! A stage rendered in a page: its scene file, edited by the demo's controls, read as
//! the command line reads it and rendered row by row with the course's code (or,
//! where the file asks for `render.fast`, the fast engine), so that a page can show
//! rows as they come and stay responsive between them.

use std::cell::Cell;
use std::num::NonZeroU32;

use raycourse::engines::Engine;
use raycourse::inspect::aov::{Aov, see};
use raycourse::maths::Colour;
use raycourse::render::film::display;
use raycourse::scene::beyond::Beyond;
use raycourse::scene_file::beyond::{BeyondOverrides, parse_with_beyond};
use raycourse::{Overrides, Scene};
use wasm_bindgen::prelude::*;

use crate::{assets, edits, functions};

/// A stage's scene ready to render, how (beyond the course), and the rays traced so
/// far.
#[wasm_bindgen]
pub struct Demo {
    scene: Scene,
    beyond: Beyond,
    rays: Cell<u64>,
}

#[wasm_bindgen]
impl Demo {
    /// The scene of the stage called `stage`, its scene file changed by `edits` (a
    /// JSON object of keys and values, see [`edits::apply`]), at `width` x `height`
    /// pixels and `samples` per pixel (0 keeps the file's). An error says what is
    /// wrong, as the command line would.
    #[wasm_bindgen(constructor)]
    pub fn new(
        stage: &str,
        edits: &str,
        width: u32,
        height: u32,
        samples: u32,
    ) -> Result<Demo, JsError> {
        let (scene, beyond) =
            scene(stage, edits, width, height, samples).map_err(|e| JsError::new(&e))?;
        Ok(Demo {
            scene,
            beyond,
            rays: Cell::new(0),
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.scene.camera.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.scene.camera.height
    }

    /// Samples per pixel.
    pub fn samples(&self) -> u32 {
        self.scene.settings.samples
    }

    /// Rays traced by [`Demo::rows`] so far (a number, as JavaScript's are).
    pub fn rays(&self) -> f64 {
        self.rays.get() as f64
    }

    /// Rows `first` to `first + count - 1` (those inside the image), rendered by the
    /// course's `render_row` (or the engine the file's settings beyond the course
    /// choose), as RGBA bytes for a canvas: each channel the 8-bit value the PNG
    /// would hold (`min(255, L^(1/gamma))`), alpha opaque.
    pub fn rows(&self, first: u32, count: u32) -> Vec<u8> {
        let width = self.width() as usize;
        let last = (first + count).min(self.height());
        let gamma = self.scene.settings.gamma;
        let mut rgba = Vec::with_capacity(width * 4 * (last - first.min(last)) as usize);
        let mut line = vec![Colour::ZERO; width];
        let mut taken = vec![0; width];
        let engine = Engine::new(&self.scene, self.beyond);
        for row in first..last {
            let (rays, _) = engine.row(row, &mut line, &mut taken);
            self.rays.set(self.rays.get() + rays);
            for colour in &line {
                let [r, g, b] = colour.to_array().map(|v| display(v, gamma));
                rgba.extend_from_slice(&[r, g, b, 255]);
            }
        }
        rgba
    }

    /// The `cost` image (`--aov cost`): for the camera ray through each pixel's
    /// centre, the spheres, boxes and triangles tested to find its hit, on a colour
    /// scale, with the legend under it; RGBA bytes, [`Demo::width`] wide.
    pub fn cost(&self) -> CostImage {
        let image = see(&self.scene, Aov::Cost);
        CostImage {
            height: image.height,
            mean: image.mean.map_or(0.0, raycourse::maths::to_double),
            rgba: image
                .rgb
                .chunks(3)
                .flat_map(|c| [c[0], c[1], c[2], 255])
                .collect(),
        }
    }

    /// The course functions this render runs, as a JSON list of names.
    pub fn functions(&self) -> String {
        let names = functions::ran(&self.scene, &self.beyond);
        serde_json::to_string(&names).expect("names serialise")
    }
}

/// The `cost` image of a demo.
#[wasm_bindgen]
pub struct CostImage {
    height: u32,
    mean: f64,
    rgba: Vec<u8>,
}

#[wasm_bindgen]
impl CostImage {
    /// Height in pixels, the legend included.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Tests per camera ray, on average.
    pub fn mean(&self) -> f64 {
        self.mean
    }

    /// The pixels, RGBA.
    pub fn rgba(&self) -> Vec<u8> {
        self.rgba.clone()
    }
}

/// The scene of [`Demo::new`] and its settings beyond the course, or what is wrong.
pub fn scene(
    stage: &str,
    edits: &str,
    width: u32,
    height: u32,
    samples: u32,
) -> Result<(Scene, Beyond), String> {
    let stage = crate::find(stage)?;
    let text = edits::apply(stage.source, edits)?;
    let overrides = Overrides {
        width: Some(NonZeroU32::new(width).ok_or("the width must be at least 1")?),
        height: Some(NonZeroU32::new(height).ok_or("the height must be at least 1")?),
        samples: NonZeroU32::new(samples),
        ..Overrides::default()
    };
    let files = assets::stage_files();
    let nothing_more = BeyondOverrides::default();
    parse_with_beyond(&text, &stage.file(), &overrides, &nothing_more, files)
        .map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::command_line::command_line_render;

    #[test]
    fn rows_in_bands_make_the_command_lines_image_with_either_engine() {
        let fast = r#"{"render.fast": true}"#;
        let cases = ["glass", "indirect", "textures"].map(|name| (name, "{}"));
        for (name, edits) in cases.into_iter().chain([("indirect", fast), ("bvh", fast)]) {
            let demo = scene(name, edits, 24, 24, 0).map(|(scene, beyond)| Demo {
                scene,
                beyond,
                rays: Cell::new(0),
            });
            let demo = demo.unwrap();
            assert_eq!(demo.beyond.fast, edits == fast, "{name}");
            let bands: Vec<u8> = [0, 7, 14, 21]
                .iter()
                .flat_map(|&f| demo.rows(f, 7))
                .collect();
            let rgb: Vec<u8> = bands
                .chunks(4)
                .flat_map(|p| {
                    assert_eq!(p[3], 255);
                    [p[0], p[1], p[2]]
                })
                .collect();
            assert_eq!(rgb, command_line_render(name, 24, None), "{name}");
            assert!(demo.rays() >= 24.0 * 24.0, "{name}: {} rays", demo.rays());
        }
    }

    #[test]
    fn an_edit_changes_the_image_and_a_bad_one_is_named() {
        let plain = scene("shading", "{}", 16, 16, 0).unwrap().0;
        let wide = scene("shading", r#"{"camera.fov": 90}"#, 16, 16, 0)
            .unwrap()
            .0;
        assert!(wide.camera.fov > plain.camera.fov);
        let error = scene("shading", r#"{"camera.fov": "wide"}"#, 16, 16, 0).unwrap_err();
        assert!(error.contains("camera.fov"), "{error}");
        assert!(
            scene("nowhere", "{}", 16, 16, 0)
                .unwrap_err()
                .contains("no stage")
        );
    }
}
