//! Reading OBJ files, and placing the mesh they hold in the scene.

use std::path::Path;
use std::sync::Arc;

use crate::files::{Disk, Files};
use crate::geometry::{Aabb, TriangleTest};
use crate::maths::{Colour, Mat3, Real, Vec3};
use crate::meshes::{BruteForce, Mesh, MeshAlbedo};

/// The geometry read from an OBJ file, before it is placed.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjData {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// Vertex normals (empty if the file has none).
    pub normals: Vec<Vec3>,
    /// Texture coordinates (empty if the file has none).
    pub uvs: Vec<[Real; 2]>,
    /// Vertex indices, three per triangle.
    pub triangles: Vec<[u32; 3]>,
    /// The `map_Kd` texture of the first material, resolved next to the OBJ file.
    pub diffuse_texture: Option<std::path::PathBuf>,
}

/// Where a mesh stands in the scene: `p' = rotation (scale p) + translation`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Uniform scale factor.
    pub scale: Real,
    /// Rotation.
    pub rotation: Mat3,
    /// Translation.
    pub translation: Vec3,
}

/// Reads the OBJ file at `path` from disk: [`read_obj_from`] with [`Disk`].
pub fn read_obj(path: &Path) -> Result<ObjData, String> {
    read_obj_from(path, &Disk)
}

// ANCHOR: obj_read
/// Reads the OBJ file at `path` from `files` with tobj: polygons are split into
/// triangles and every corner gets one index for position, normal and texture
/// coordinates. The models of the file are merged; normals or texture coordinates are
/// kept only if every model has them. A missing or broken MTL file only loses the
/// texture. The file is read once: its lines are checked ([`check_lines`]), then tobj
/// parses the same text.
pub fn read_obj_from(path: &Path, files: &dyn Files) -> Result<ObjData, String> {
    let bytes = files.read(path).map_err(|e| e.to_string())?;
    let text = match std::str::from_utf8(&bytes) {
        Ok(text) if !text.contains('\0') => text,
        _ => return Err("not a text OBJ file".into()),
    };
    check_lines(text)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let folder = path.parent().unwrap_or(Path::new(""));
    let (models, materials) = tobj::load_obj_buf(&mut text.as_bytes(), &options, |mtl| {
        let text = files
            .read(&folder.join(mtl))
            .map_err(|_| tobj::LoadError::OpenFileFailed)?;
        tobj::load_mtl_buf(&mut text.as_slice())
    })
    .map_err(|e| e.to_string())?;
    let texture = materials.ok().and_then(|m| {
        let name = m.first()?.diffuse_texture.clone()?;
        Some(folder.join(name))
    });
    merge(&models, texture)
}
// ANCHOR_END: obj_read

/// The models of an OBJ file as one mesh, with the MTL file's `texture`; an error
/// when there is no triangle or an index is out of range.
fn merge(models: &[tobj::Model], texture: Option<std::path::PathBuf>) -> Result<ObjData, String> {
    let mut data = ObjData {
        positions: Vec::new(),
        normals: Vec::new(),
        uvs: Vec::new(),
        triangles: Vec::new(),
        diffuse_texture: texture,
    };
    let with_normals = models.iter().all(|m| !m.mesh.normals.is_empty());
    let with_uvs = models.iter().all(|m| !m.mesh.texcoords.is_empty());
    let vec3 = |c: &[f32]| Vec3::new(c[0] as Real, c[1] as Real, c[2] as Real);
    for mesh in models.iter().map(|m| &m.mesh) {
        let first = data.positions.len() as u32;
        data.positions
            .extend(mesh.positions.chunks_exact(3).map(vec3));
        if with_normals {
            data.normals.extend(mesh.normals.chunks_exact(3).map(vec3));
        }
        if with_uvs {
            let uv = |c: &[f32]| [c[0] as Real, c[1] as Real];
            data.uvs.extend(mesh.texcoords.chunks_exact(2).map(uv));
        }
        let corners = mesh.indices.chunks_exact(3);
        data.triangles
            .extend(corners.map(|c| [c[0] + first, c[1] + first, c[2] + first]));
    }
    let count = data.positions.len();
    if data.triangles.is_empty() {
        return Err("no triangles".into());
    }
    if let Some(i) = data
        .triangles
        .iter()
        .flatten()
        .find(|&&i| i as usize >= count)
    {
        return Err(format!(
            "vertex index {} out of range (the file has {count})",
            i + 1
        ));
    }
    Ok(data)
}

/// Checks every line that tobj would read before it sees the file, so that a
/// mistake is reported by its line in words a student knows: a vertex needs 3
/// coordinates (4 with a weight, 6 with a colour), a texture coordinate 2, a normal
/// 3, each a finite number; a face needs at least 3 corners, each naming a `v`, `vt` or
/// `vn` line already read.
pub fn check_lines(text: &str) -> Result<(), String> {
    let mut counts = [0i64; 3];
    for (number, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let found = match words.next() {
            Some("v") => check_numbers(
                words,
                "a vertex has 3 coordinates",
                &[3, 4, 6],
                &mut counts[0],
            ),
            Some("vt") => check_numbers(
                words,
                "a texture coordinate has 2 numbers",
                &[2, 3],
                &mut counts[1],
            ),
            Some("vn") => check_numbers(words, "a normal has 3 coordinates", &[3], &mut counts[2]),
            Some("f") => check_face(words, counts),
            _ => Ok(()),
        };
        found.map_err(|message| format!("line {}: {message}", number + 1))?;
    }
    Ok(())
}

/// Checks the numbers of a `v`, `vt` or `vn` line: each must parse as a finite
/// number (`nan`, `inf` and values beyond single precision are refused: tobj would
/// read them without a word), and there must be one of the `allowed` counts; counts
/// the line in `read`.
fn check_numbers<'a>(
    words: impl Iterator<Item = &'a str>,
    rule: &str,
    allowed: &[usize],
    read: &mut i64,
) -> Result<(), String> {
    let mut found = 0;
    for word in words {
        let value = word
            .parse::<f32>()
            .map_err(|_| format!("`{word}` is not a number"))?;
        if !value.is_finite() {
            return Err(format!("`{word}` is not a finite number"));
        }
        found += 1;
    }
    *read += 1;
    if allowed.contains(&found) {
        Ok(())
    } else {
        Err(format!("{rule}, found {found}"))
    }
}

/// Checks the corners of an `f` line: at least 3, and every index counting from 1,
/// or from the end of what was read so far when negative (`-1` is the last), naming a
/// `v`, `vt` or `vn` line already read (`counts`). tobj itself would silently drop a
/// face of two corners, and turn an out-of-range negative index into an overflowing
/// arithmetic on `usize`.
fn check_face<'a>(words: impl Iterator<Item = &'a str>, counts: [i64; 3]) -> Result<(), String> {
    let mut corners = 0;
    for corner in words {
        corners += 1;
        let kinds = ["vertex", "texture coordinate", "normal"];
        for ((what, count), field) in kinds.iter().zip(counts).zip(corner.split('/')) {
            let Ok(index) = field.parse::<i64>() else {
                continue;
            };
            if index == 0 || index.unsigned_abs() > count.unsigned_abs() {
                return Err(format!(
                    "{what} index {index} is out of range ({count} read so far)"
                ));
            }
        }
    }
    if corners < 3 {
        return Err(format!("a face has {corners} corners; it needs at least 3"));
    }
    Ok(())
}

impl Mesh {
    /// The mesh of `data` placed by `placement`, searched brute force with the
    /// watertight test, flat-shaded with a white albedo; the scene file then chooses
    /// the rest.
    pub fn new(data: &ObjData, placement: &Placement) -> Mesh {
        let place = |p: Vec3| placement.rotation * (placement.scale * p) + placement.translation;
        let positions: Vec<Vec3> = data.positions.iter().map(|&p| place(p)).collect();
        let normals = data
            .normals
            .iter()
            .map(|&n| (placement.rotation * n).normalize_or_zero())
            .collect();
        let bounds = positions.iter().fold(Aabb::EMPTY, |b, &p| b.grow(p));
        Mesh {
            positions,
            normals,
            uvs: data.uvs.clone(),
            triangles: data.triangles.clone(),
            bounds,
            search: Arc::new(BruteForce),
            triangle_test: TriangleTest::default(),
            albedo: MeshAlbedo::Constant(Colour::ONE),
            texture_file: data.diffuse_texture.clone(),
        }
    }
}
