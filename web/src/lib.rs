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
/// scene-file path and text, and the file's keys and values (`file`), from which a
/// demo's controls take their starting values; in course order.
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
            })
        })
        .collect();
    serde_json::Value::Array(list).to_string()
}

/// The stage called `name`, or an error naming the stages there are.
fn find(name: &str) -> Result<&'static raycourse::Stage, String> {
    raycourse::stages().find(|s| s.name == name).ok_or_else(|| {
        let names: Vec<&str> = raycourse::stages().map(|s| s.name).collect();
        format!("no stage `{name}`: the stages are {}", names.join(", "))
    })
}
