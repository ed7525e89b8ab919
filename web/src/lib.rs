//! The course in the browser: `raycourse` compiled to WebAssembly, exposed to the
//! book's pages by wasm-bindgen. The renderer is the crate's own, not a copy: a demo
//! renders a stage's scene file, edited by the page's controls, with the course's
//! functions ([`Demo`]); the check page runs `raycourse check` on a dropped image
//! ([`check_image`]) and grades a whole class ([`Class`]). What a page cannot do stays out: files (the stages' meshes and
//! textures are compiled in, [`assets`]), clocks (the page times the work with its
//! own) and threads (rayon runs on the page's one thread; a page that wants more
//! starts one worker per core, each rendering its own rows).
//!
//! | file | what it holds |
//! |---|---|
//! | [`assets`] | the files the stages name, compiled in |
//! | [`edits`] | a scene file with some of its keys changed by the page's controls |
//! | [`demo`] | a stage rendered row by row, and its cost image |
//! | [`functions`] | the course functions a scene's render runs |
//! | [`checking`] | `check` on a student's image |
//! | [`grading`] | `check --all` on a class's folder, or a student's |
//! | [`words`] | the page's words, from the program's message catalogue |
//! | `command_line` | for the tests: a stage as the command line renders it |

pub mod assets;
pub mod checking;
#[cfg(test)]
mod command_line;
pub mod demo;
pub mod edits;
pub mod functions;
pub mod grading;
pub mod words;

pub use checking::check_image;
pub use demo::Demo;
pub use grading::Class;

use wasm_bindgen::prelude::*;

/// The stages of the course as JSON: for each, its session, figure, name, title,
/// scene-file path and text, the file's keys and values (`file`) and its render
/// settings with the keys it leaves out at their defaults (`settings`: samples,
/// bounces, gamma), from which a demo's controls take their starting values; in
/// course order.
#[wasm_bindgen]
pub fn stages() -> String {
    let list: Vec<serde_json::Value> = raycourse::stages()
        .map(|s| {
            serde_json::json!({
                "session": s.session,
                "figure": s.figure,
                "name": s.name,
                "title": s.title,
                "path": s.path,
                "source": s.source,
                "file": s.source.parse::<toml::Table>().ok(),
                "settings": settings(s).map(|r| serde_json::json!({
                    "samples": r.samples,
                    "bounces": r.bounces,
                    "gamma": r.gamma,
                })),
            })
        })
        .collect();
    serde_json::Value::Array(list).to_string()
}

/// The render settings of `stage`'s scene file, as the renderer reads them: the
/// keys the file leaves out at their defaults.
fn settings(stage: &raycourse::Stage) -> Option<raycourse::scene::Settings> {
    use raycourse::scene_file::format::SceneFile;
    use raycourse::scene_file::load::{parse_table, read_table};
    let path = stage.file();
    let table = parse_table(stage.source, &path).ok()?;
    let file = read_table::<SceneFile>(table, stage.source, &path).ok()?;
    Some(raycourse::scene_file::session1::settings(&file))
}

/// The stage called `name`, or an error naming the stages there are.
fn find(name: &str) -> Result<&'static raycourse::Stage, String> {
    raycourse::stages().find(|s| s.name == name).ok_or_else(|| {
        let names: Vec<&str> = raycourse::stages().map(|s| s.name).collect();
        format!("no stage `{name}`: the stages are {}", names.join(", "))
    })
}

#[cfg(test)]
mod tests {
    /// Each stage's `settings`, by name, from [`super::stages`]'s JSON.
    fn settings(name: &str) -> serde_json::Value {
        let all: serde_json::Value = serde_json::from_str(&super::stages()).unwrap();
        let stage = all.as_array().unwrap().iter().find(|s| s["name"] == name);
        stage.unwrap()["settings"].clone()
    }

    #[test]
    fn each_stage_carries_its_settings_with_the_defaults_the_renderer_reads() {
        let gamma = settings("gamma");
        assert_eq!(
            (gamma["samples"].as_u64(), gamma["bounces"].as_u64()),
            (Some(1), Some(5))
        );
        assert_eq!(gamma["gamma"].as_f64(), Some(2.2));
        assert_eq!(settings("white-disk")["gamma"].as_f64(), Some(1.0));
        assert_eq!(settings("indirect")["samples"].as_u64(), Some(100));
        let all: serde_json::Value = serde_json::from_str(&super::stages()).unwrap();
        let missing: Vec<&serde_json::Value> = all
            .as_array()
            .unwrap()
            .iter()
            .filter(|s| s["settings"].is_null())
            .collect();
        assert!(missing.is_empty(), "stages without settings: {missing:?}");
    }
}
