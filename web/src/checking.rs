//! `raycourse check` in a page: a student's image of a stage, dropped on the book's
//! check page, compared with the stage's reference rendered in the page by the same
//! code as the command's. Nothing leaves the page.

use raycourse::check::expected::Source;
use raycourse::check::report::{Verdict, check};
use raycourse::messages::language::Language;
use raycourse::messages::say;
use raycourse::render::cache::InMemory;
use wasm_bindgen::prelude::*;

use std::sync::atomic::{AtomicU64, Ordering};

use crate::assets;

/// What the checker says of an image.
#[wasm_bindgen]
pub struct Checked {
    matches: bool,
    lines: Vec<String>,
    difference: Vec<u8>,
}

#[wasm_bindgen]
impl Checked {
    /// Whether the image is the stage's.
    pub fn matches(&self) -> bool {
        self.matches
    }

    /// The report, as the lines `raycourse check` prints.
    pub fn text(&self) -> String {
        self.lines.join("\n")
    }

    /// The picture of the differences (`check --diff`) as a PNG file's bytes.
    pub fn difference_png(&self) -> Vec<u8> {
        self.difference.clone()
    }
}

#[wasm_bindgen]
extern "C" {
    /// The page's progress bar: the worker's global `raycourseProgress(rows)`. An
    /// imported function, not a closure over a JavaScript value, so that the render
    /// may call it from any of its (here, one) threads.
    #[wasm_bindgen(js_name = raycourseProgress)]
    pub fn report_progress(rows: f64);
}

/// Checks the image in `file` (a PNG, JPEG or PPM file's bytes) against the stage called
/// `stage`, as `raycourse check STAGE IMAGE --lang LANGUAGE` does (`en` or `fr`),
/// telling the worker's `raycourseProgress` how many rows of the reference are
/// rendered.
#[wasm_bindgen]
pub fn check_image(stage: &str, file: &[u8], language: &str) -> Result<Checked, JsError> {
    let language = Language::from_locale(language);
    checked(stage, file, language, &|rows| report_progress(rows as f64))
        .map_err(|e| JsError::new(&e))
}

/// The checker's answer on `file` for `stage`, in `language`, or what is wrong with
/// the input; `progress` is told the rows of the reference rendered so far.
pub fn checked(
    stage: &str,
    file: &[u8],
    language: Language,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<Checked, String> {
    let stage = crate::find(stage)?;
    let format = image::guess_format(file).ok();
    let lossy = format == Some(image::ImageFormat::Jpeg);
    let image = image::load_from_memory(file)
        .map_err(|e| {
            say(
                language,
                "check-unreadable",
                &[("error", e.to_string().into())],
            )
        })?
        .to_rgb8();
    let rows = AtomicU64::new(0);
    let count = |_| progress(rows.fetch_add(1, Ordering::Relaxed) + 1);
    let source = Source {
        stage,
        size: image.dimensions(),
        cache: &InMemory::default(),
        files: assets::stage_files(),
        progress: &count,
        renderer: &raycourse::engines::Fast,
    };
    let report = check(&source, &image, lossy).map_err(|e| e.to_string())?;
    let picture = report.difference_image(&image);
    Ok(Checked {
        matches: report.verdict == Verdict::Matches,
        lines: report.lines(stage, language),
        difference: raycourse::render::png::encode_rgb8(
            picture.as_raw(),
            picture.width(),
            picture.height(),
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::command_line::command_line_render;
    use raycourse::maths::Real;

    /// The stage `name`'s image at `size` x `size` as a plain PPM (`P3`), the text a
    /// renderer in C++ writes by hand, with `gamma` for the display.
    fn plain_ppm(name: &str, size: u32, gamma: Option<Real>) -> Vec<u8> {
        let rgb = command_line_render(name, size, gamma);
        let mut text = format!("P3\n# written by hand\n{size} {size}\n255\n");
        for pixel in rgb.chunks(3) {
            text.push_str(&format!("{} {} {}\n", pixel[0], pixel[1], pixel[2]));
        }
        text.into_bytes()
    }

    /// The page reads a PPM as the command does: the right image matches, one
    /// without gamma differs, and a file that is not an image is refused by name.
    #[test]
    fn the_page_checks_a_ppm_written_by_hand() {
        let check = |file: &[u8]| checked("glass", file, Language::English, &|_| {});
        assert!(check(&plain_ppm("glass", 32, None)).unwrap().matches());
        assert!(!check(&plain_ppm("glass", 32, Some(1.0))).unwrap().matches());
        let refused = check(b"P3\nnot a picture").err().unwrap();
        assert!(
            refused.contains("not a PNG, JPEG or PPM image"),
            "{refused}"
        );
    }
}
