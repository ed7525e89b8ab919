//! Reading a scene file: the text parsed, checked against this build's sessions and
//! for consistency, and turned into a [`Scene`], session by session.

use std::num::NonZeroU32;
use std::path::Path;

use serde::de::DeserializeOwned;
use toml::Spanned;
use toml::de::DeTable;

use crate::files::{Disk, Files};
use crate::maths::Real;
use crate::maths::values::Finite;
use crate::scene::Scene;
use crate::scene_file::consistency::check_consistency;
use crate::scene_file::error::value_rule;
use crate::scene_file::format::SceneFile;
use crate::scene_file::sessions::{check_materials, check_sessions};
use crate::scene_file::{SceneError, one_line};

#[cfg(not(feature = "s3"))]
use crate::scene_file::session1::scene;
#[cfg(all(feature = "s3", not(feature = "s4")))]
use crate::scene_file::session3::scene;
#[cfg(all(feature = "s4", not(feature = "s5")))]
use crate::scene_file::session4::scene;
#[cfg(all(feature = "s5", not(feature = "s6")))]
use crate::scene_file::session5::scene;
#[cfg(all(feature = "s6", not(feature = "s7")))]
use crate::scene_file::session6::scene;
#[cfg(feature = "s7")]
use crate::scene_file::session7::scene;

/// Render settings given on the command line, replacing those of the scene file
/// before it is checked.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Overrides {
    /// Image width in pixels.
    pub width: Option<NonZeroU32>,
    /// Image height in pixels.
    pub height: Option<NonZeroU32>,
    /// Samples per pixel.
    pub samples: Option<NonZeroU32>,
    /// Bounce limit.
    pub bounces: Option<u32>,
    /// Random seed.
    pub seed: Option<u64>,
    /// The camera's plunge angle in degrees (the animation's variable).
    pub plunge: Option<Real>,
}

impl Overrides {
    /// A render of `width` x `height` pixels at `samples` per pixel, the rest as the
    /// scene file has it: what the tests, the checklist and the page render a stage
    /// at. A 0 keeps the file's value.
    pub fn sized(width: u32, height: u32, samples: u32) -> Overrides {
        Overrides {
            width: NonZeroU32::new(width),
            height: NonZeroU32::new(height),
            samples: NonZeroU32::new(samples),
            ..Overrides::default()
        }
    }

    /// Puts the overrides into `file`; an error names the key if the plunge is not a
    /// finite angle.
    pub fn apply(&self, file: &mut SceneFile) -> Result<(), (&'static str, String)> {
        if let Some(p) = self.plunge {
            file.camera.plunge = Some(Finite::try_from(p).map_err(|e| ("camera.plunge", e))?);
        }
        let r = &mut file.render;
        r.width = self.width.unwrap_or(r.width);
        r.height = self.height.unwrap_or(r.height);
        r.samples = self.samples.unwrap_or(r.samples);
        r.bounces = self.bounces.unwrap_or(r.bounces);
        r.seed = self.seed.unwrap_or(r.seed);
        Ok(())
    }
}

/// Reads and checks the scene file at `path`, with `overrides` applied; the files it
/// names are read from disk.
pub fn load_scene(path: &Path, overrides: &Overrides) -> Result<Scene, SceneError> {
    parse_scene(&read_source(path)?, path, overrides)
}

/// The text of the scene file at `path`; an error names the file.
pub fn read_source(path: &Path) -> Result<String, SceneError> {
    std::fs::read_to_string(path).map_err(|source| SceneError::Read {
        path: path.to_owned(),
        source,
    })
}

/// Parses and checks scene-file text, with `overrides` applied; `path` names it in
/// error messages, and files it refers to are read from disk next to it
/// ([`parse_scene_from`] with [`Disk`]).
pub fn parse_scene(source: &str, path: &Path, overrides: &Overrides) -> Result<Scene, SceneError> {
    parse_scene_from(source, path, overrides, &Disk)
}

// ANCHOR: parse_scene
/// Parses and checks scene-file text, with `overrides` applied; `path` names it in
/// error messages, and files it refers to are found next to it in `files`. The scene
/// is built by the latest session of this build, each session starting from the
/// scene of the one before and adding what it brings.
pub fn parse_scene_from(
    source: &str,
    path: &Path,
    overrides: &Overrides,
    files: &dyn Files,
) -> Result<Scene, SceneError> {
    check_materials(source, path)?;
    let file = read_table(parse_table(source, path)?, source, path)?;
    let file = checked(file, path, overrides)?;
    scene(&file, path, files)
}
// ANCHOR_END: parse_scene

/// `file` with `overrides` applied, checked against this build's sessions and for
/// consistency.
pub fn checked(
    mut file: SceneFile,
    path: &Path,
    overrides: &Overrides,
) -> Result<SceneFile, SceneError> {
    overrides
        .apply(&mut file)
        .map_err(|(key, message)| SceneError::Inconsistent {
            path: path.to_owned(),
            key: key.into(),
            message: value_rule(&message).expect("a rule of the catalogue"),
        })?;
    check_sessions(&file, path)?;
    check_consistency(&file, path)?;
    Ok(file)
}

/// The scene-file text `source` parsed as TOML, each key and value with the span of
/// text it came from; an error names the line and the column.
pub fn parse_table<'s>(source: &'s str, path: &Path) -> Result<Spanned<DeTable<'s>>, SceneError> {
    DeTable::parse(source).map_err(|e| invalid(source, path, e.span(), String::new(), e.message()))
}

/// The TOML `table` parsed from `source` read as a `T` (a [`SceneFile`]); an error
/// names the line, the column and the key.
pub fn read_table<T: DeserializeOwned>(
    table: Spanned<DeTable>,
    source: &str,
    path: &Path,
) -> Result<T, SceneError> {
    serde_path_to_error::deserialize(toml::Deserializer::from(table)).map_err(|e| {
        let key = e.path().to_string();
        let inner = e.into_inner();
        invalid(source, path, inner.span(), key, inner.message())
    })
}

/// The error of an invalid scene file: the text at `span` of `source`, read from
/// `path`, is not what `key` takes.
fn invalid(
    source: &str,
    path: &Path,
    span: Option<std::ops::Range<usize>>,
    key: String,
    message: &str,
) -> SceneError {
    let (line, column) = line_and_column(source, span.map_or(0, |s| s.start));
    SceneError::Invalid {
        path: path.to_owned(),
        line,
        column,
        key,
        message: one_line(message),
    }
}

/// 1-based line and column of byte `offset` in `source`.
fn line_and_column(source: &str, offset: usize) -> (usize, usize) {
    let before = &source[..offset.min(source.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}
