//! What a scene file may ask beyond the course: another sampler
//! (`render.sampler`), adaptive sampling (`render.noise`) and the fast engine
//! (`render.fast`, whose hierarchy has leaves of at most `render.leaf_size`
//! triangles). These keys are taken out of the text's `[render]` table first; the
//! rest is the course's scene file, read and built by the course's code.

use std::num::NonZeroU16;
use std::path::Path;
use std::sync::Arc;

use serde::Deserialize;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use crate::fast::{FastBruteForce, FastBvh};
use crate::files::{Disk, Files};
use crate::maths::Real;
use crate::maths::values::Positive;
use crate::meshes::{Mesh, Search};
use crate::messages::said::Said;
use crate::scene::Scene;
use crate::scene::beyond::{Beyond, Sampler};
use crate::scene_file::error::value_rule;
use crate::scene_file::field_names::field_names;
use crate::scene_file::format::{AccelerationSpec, SceneFile};
use crate::scene_file::load::{checked, parse_table, read_table};
use crate::scene_file::sessions::check_materials;
use crate::scene_file::{Overrides, SceneError, Stage, session7};

/// The keys of `[render]` beyond the course.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BeyondKeys {
    /// Most triangles in a leaf of the fast engine's hierarchy (default 8).
    pub leaf_size: Option<NonZeroU16>,
    /// How the random numbers of a pixel's samples are chosen (default
    /// independent).
    #[serde(default)]
    pub sampler: Sampler,
    /// Adaptive sampling's target: the relative standard error at which a pixel
    /// stops taking samples (absent: every pixel takes `samples`).
    pub noise: Option<Positive>,
    /// Whether the fast engine renders (default false: the course's code; the same
    /// image either way, the course's more slowly).
    #[serde(default)]
    pub fast: bool,
}

/// A scene file's keys beyond the course, under `[render]` as in the file.
#[derive(Deserialize)]
struct BeyondFile {
    #[serde(default)]
    render: BeyondKeys,
}

/// Render settings beyond the course given on the command line, replacing those of
/// the scene file.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BeyondOverrides {
    /// Adaptive sampling's target relative standard error.
    pub noise: Option<Real>,
    /// Render with the fast engine; `false` leaves the scene file's choice.
    pub fast: bool,
}

impl BeyondOverrides {
    /// Puts the overrides into `keys`; an error names the key if the noise is not a
    /// positive number.
    fn apply(&self, keys: &mut BeyondKeys, path: &Path) -> Result<(), SceneError> {
        if let Some(noise) = self.noise {
            keys.noise =
                Some(
                    Positive::try_from(noise).map_err(|message| SceneError::Inconsistent {
                        path: path.to_owned(),
                        key: "render.noise".into(),
                        message: value_rule(&message).expect("a rule of the catalogue"),
                    })?,
                );
        }
        keys.fast |= self.fast;
        Ok(())
    }
}

/// The scene of `stage` at the course's settings but for `overrides` and `beyond`,
/// the files it refers to read from this crate's folder.
pub fn stage_with_beyond(
    stage: &Stage,
    overrides: &Overrides,
    beyond: &BeyondOverrides,
) -> Result<(Scene, Beyond), SceneError> {
    parse_with_beyond(stage.source, &stage.file(), overrides, beyond, &Disk)
}

/// Parses and checks scene-file text as the course's
/// [`parse_scene_from`](crate::scene_file::parse_scene_from) does, its keys beyond
/// the course taken out first and `beyond` applied to them: the course's scene, each
/// mesh searched by the fast engine's hierarchy where `render.fast` and
/// `render.acceleration` ask for one, and what its render uses beyond the course.
pub fn parse_with_beyond(
    source: &str,
    path: &Path,
    overrides: &Overrides,
    beyond: &BeyondOverrides,
    files: &dyn Files,
) -> Result<(Scene, Beyond), SceneError> {
    check_materials(source, path)?;
    let mut table = parse_table(source, path)?;
    let taken = take_keys(&mut table);
    let mut keys = read_table::<BeyondFile>(taken, source, path)?.render;
    beyond.apply(&mut keys, path)?;
    let file = checked(read_table(table, source, path)?, path, overrides)?;
    let scene = scene(&file, &keys, path, files)?;
    let beyond = Beyond {
        sampler: keys.sampler,
        noise: keys.noise.map(|n| n.0),
        fast: keys.fast,
    };
    Ok((scene, beyond))
}

/// Takes the keys beyond the course out of `table`'s `[render]` table, and returns
/// them as a table of their own, under `render`, each with its span in the text.
fn take_keys<'s>(table: &mut Spanned<DeTable<'s>>) -> Spanned<DeTable<'s>> {
    let span = table.span();
    let mut render = DeTable::new();
    if let Some(DeValue::Table(course)) = table.get_mut().get_mut("render").map(|v| v.get_mut()) {
        for &key in field_names::<BeyondKeys>() {
            if let Some((key, value)) = course.remove_entry(key) {
                render.insert(key, value);
            }
        }
    }
    let mut taken = DeTable::new();
    let render = Spanned::new(span.clone(), DeValue::Table(render));
    taken.insert(Spanned::new(span.clone(), "render".into()), render);
    Spanned::new(span, taken)
}

/// The course's scene of `file`, each mesh searched by the fast engine where `keys`
/// ask for it: its hierarchy where `render.acceleration` asks for one, and session
/// 5's searches on lanes ([`FastBruteForce`]) where it asks for none or for the
/// bounding box.
fn scene(
    file: &SceneFile,
    keys: &BeyondKeys,
    path: &Path,
    files: &dyn Files,
) -> Result<Scene, SceneError> {
    let acceleration = file.render.acceleration;
    let fast_bvh = keys.fast && acceleration == AccelerationSpec::Bvh;
    if keys.leaf_size.is_some() && !fast_bvh {
        return Err(SceneError::Inconsistent {
            path: path.to_owned(),
            key: "render.leaf_size".into(),
            message: Said::new("scene-leaf-size-needs-fast"),
        });
    }
    if !keys.fast {
        return session7::scene(file, path, files);
    }
    // The course's hierarchy would be built only to be replaced.
    let mut course = file.clone();
    if fast_bvh {
        course.render.acceleration = AccelerationSpec::None;
    }
    let mut scene = session7::scene(&course, path, files)?;
    let leaf_size = keys.leaf_size.map_or(8, NonZeroU16::get);
    for mesh in &mut scene.meshes {
        if let Some(search) = fast_search(mesh, acceleration, leaf_size) {
            mesh.search = search;
        }
    }
    Ok(scene)
}

/// The fast engine's search of `mesh` for the scene file's `acceleration`: its
/// hierarchy, with leaves of at most `leaf_size` triangles, or session 5's searches
/// on lanes; `None` where it has none (the watertight test without a hierarchy),
/// which leaves the course's search in place.
fn fast_search(
    mesh: &Mesh,
    acceleration: AccelerationSpec,
    leaf_size: u16,
) -> Option<Arc<dyn Search>> {
    match acceleration {
        AccelerationSpec::Bvh => Some(Arc::new(FastBvh::build(mesh, leaf_size))),
        other => FastBruteForce::build(mesh, other == AccelerationSpec::Bbox)
            .map(|search| Arc::new(search) as Arc<dyn Search>),
    }
}
