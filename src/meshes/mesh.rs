//! Triangle meshes: loaded from OBJ files, placed in the scene, intersected by brute
//! force, behind their bounding box, or through a BVH.

use std::path::Path;

use crate::geometry::aabb::Aabb;
use crate::geometry::hit::Hit;
use crate::geometry::ray::Ray;
use crate::geometry::triangle::{TriangleHit, TriangleTest, intersect_triangle};
use crate::geometry::watertight::ShearedRay;
use crate::materials::material::Material;
use crate::maths::numbers::{Colour, Mat3, Real, Vec3, error_bound};

/// How a mesh's triangles are searched for the nearest hit. All give the same hit;
/// only the time differs.
#[derive(Clone, Debug, PartialEq)]
pub enum Search {
    /// Every triangle, for every ray.
    BruteForce,
    /// Every triangle, but only for rays that meet the mesh's bounding box.
    BoundingBox,
    /// Only the triangles of the boxes of a bounding volume hierarchy that the ray meets.
    #[cfg(feature = "s6")]
    Bvh(crate::acceleration::bvh::Bvh),
    /// A hierarchy built with the surface area heuristic and laid out for speed.
    #[cfg(feature = "s6")]
    FastBvh(crate::acceleration::fast_bvh::FastBvh),
}

/// Which normal shades a mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shading {
    /// The triangle's own normal: facets show.
    Flat,
    /// The vertex normals interpolated across the triangle.
    #[cfg(feature = "s6")]
    Smooth,
}

/// The colour of a diffuse mesh.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshAlbedo {
    /// The same everywhere.
    Constant(Colour),
    /// Read from an image at the hit's texture coordinates.
    #[cfg(feature = "s7")]
    Texture(crate::materials::texture::Texture),
}

/// A placed triangle mesh and how it is drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Vertex positions, in scene coordinates.
    pub positions: Vec<Vec3>,
    /// Unit vertex normals, one per position, or none if the file had none.
    pub normals: Vec<Vec3>,
    /// Texture coordinates `(u, v)`, one per position, or none if the file had none.
    pub uvs: Vec<[Real; 2]>,
    /// Three vertex indices per triangle, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// The box around every vertex.
    pub bounds: Aabb,
    /// How the nearest triangle is found.
    pub search: Search,
    /// How one triangle is tested.
    pub triangle_test: TriangleTest,
    /// Which normal shades it.
    pub shading: Shading,
    /// Its diffuse colour.
    pub albedo: MeshAlbedo,
}

/// The nearest triangle hit: which triangle, where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshHit {
    /// Index of the triangle in [`Mesh::triangles`].
    pub triangle: u32,
    /// Distance and barycentric coordinates.
    pub at: TriangleHit,
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

// ANCHOR: obj_read
/// Reads the OBJ file at `path` with tobj: polygons are split into triangles and
/// every corner gets one index for position, normal and texture coordinates. The
/// models of the file are merged; normals or texture coordinates are kept only if
/// every model has them. A missing or broken MTL file only loses the texture. The
/// file is read once: its face indices are checked, then tobj parses the same bytes.
pub fn read_obj(path: &Path) -> Result<ObjData, String> {
    let bytes = std::fs::read(path).map_err(|e| e.to_string())?;
    check_face_indices(&String::from_utf8_lossy(&bytes))?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let folder = path.parent().unwrap_or(Path::new(""));
    let (models, materials) = tobj::load_obj_buf(&mut bytes.as_slice(), &options, |mtl| {
        tobj::load_mtl(folder.join(mtl))
    })
    .map_err(|e| e.to_string())?;
    let mut data = ObjData {
        positions: Vec::new(),
        normals: Vec::new(),
        uvs: Vec::new(),
        triangles: Vec::new(),
        diffuse_texture: materials.ok().and_then(|m| {
            let name = m.first()?.diffuse_texture.clone()?;
            Some(folder.join(name))
        }),
    };
    let with_normals = models.iter().all(|m| !m.mesh.normals.is_empty());
    let with_uvs = models.iter().all(|m| !m.mesh.texcoords.is_empty());
    for model in &models {
        let mesh = &model.mesh;
        let first = data.positions.len() as u32;
        let vec3 = |c: &[f32]| Vec3::new(c[0] as Real, c[1] as Real, c[2] as Real);
        data.positions
            .extend(mesh.positions.chunks_exact(3).map(vec3));
        if with_normals {
            data.normals.extend(mesh.normals.chunks_exact(3).map(vec3));
        }
        if with_uvs {
            let uv = |c: &[f32]| [c[0] as Real, c[1] as Real];
            data.uvs.extend(mesh.texcoords.chunks_exact(2).map(uv));
        }
        for corners in mesh.indices.chunks_exact(3) {
            data.triangles
                .push([corners[0] + first, corners[1] + first, corners[2] + first]);
        }
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
// ANCHOR_END: obj_read

/// Checks every index of every `f` line before tobj sees the file: an index counts
/// from 1, or from the end of what was read so far when negative (`-1` is the last),
/// and must name a `v`, `vt` or `vn` line already read. tobj itself would turn an
/// out-of-range negative index into an overflowing arithmetic on `usize`.
fn check_face_indices(text: &str) -> Result<(), String> {
    let mut counts = [0i64; 3];
    for (number, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => counts[0] += 1,
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            Some("f") => {
                for corner in words {
                    for ((what, count), field) in ["vertex", "texture coordinate", "normal"]
                        .iter()
                        .zip(counts)
                        .zip(corner.split('/'))
                    {
                        let Ok(index) = field.parse::<i64>() else {
                            continue;
                        };
                        if index == 0 || index.unsigned_abs() > count.unsigned_abs() {
                            return Err(format!(
                                "line {}: {what} index {index} is out of range ({count} read so far)",
                                number + 1
                            ));
                        }
                    }
                }
            }
            _ => {}
        }
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
            search: Search::BruteForce,
            triangle_test: TriangleTest::default(),
            shading: Shading::Flat,
            albedo: MeshAlbedo::Constant(Colour::ONE),
        }
    }

    /// The corners of triangle `index`.
    #[inline]
    pub fn corners(&self, index: u32) -> [Vec3; 3] {
        self.triangles[index as usize].map(|i| self.positions[i as usize])
    }

    // ANCHOR: nearest_triangle
    /// Where `ray` meets the triangle numbered `triangle` closer than `t_max`, with
    /// the mesh's test (`sheared` is the ray's frame, for the watertight one).
    #[inline]
    pub fn hit_triangle(
        &self,
        ray: &Ray,
        sheared: &ShearedRay,
        triangle: u32,
        t_max: Real,
    ) -> Option<TriangleHit> {
        let [a, b, c] = self.corners(triangle);
        match self.triangle_test {
            TriangleTest::MollerTrumbore => intersect_triangle(ray, a, b, c, t_max),
            TriangleTest::Watertight => sheared.intersect(a, b, c, t_max),
        }
    }

    /// The nearest hit among `triangles`, closer than `best` if given. Equal
    /// distances go to the lower triangle index, so that every search order finds
    /// the same triangle. `sheared` is `ShearedRay::new(ray)`, made once per ray by
    /// the caller, however many leaves of a hierarchy the ray visits.
    pub fn nearest_among(
        &self,
        ray: &Ray,
        sheared: &ShearedRay,
        triangles: impl Iterator<Item = u32>,
        mut best: Option<MeshHit>,
        t_max: Real,
    ) -> Option<MeshHit> {
        for triangle in triangles {
            let limit = best.map_or(t_max, |b| b.at.t.next_up());
            if let Some(at) = self.hit_triangle(ray, sheared, triangle, limit)
                && best.is_none_or(|b| (at.t, triangle) < (b.at.t, b.triangle))
            {
                best = Some(MeshHit { triangle, at });
            }
        }
        best
    }
    // ANCHOR_END: nearest_triangle

    /// Whether `ray` meets any of `triangles` closer than `t_max`; stops at the
    /// first it finds. `sheared` is `ShearedRay::new(ray)`, as for
    /// [`Mesh::nearest_among`].
    pub fn hits_any(
        &self,
        ray: &Ray,
        sheared: &ShearedRay,
        mut triangles: impl Iterator<Item = u32>,
        t_max: Real,
    ) -> bool {
        triangles.any(|triangle| self.hit_triangle(ray, sheared, triangle, t_max).is_some())
    }

    // ANCHOR: mesh_intersect
    /// The nearest triangle that `ray` meets closer than `t_max`.
    pub fn intersect(&self, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        let all = 0..self.triangles.len() as u32;
        match &self.search {
            Search::BruteForce => self.nearest_among(ray, &ShearedRay::new(ray), all, None, t_max),
            Search::BoundingBox => {
                self.bounds.entry(ray, ray.direction.recip(), t_max)?;
                self.nearest_among(ray, &ShearedRay::new(ray), all, None, t_max)
            }
            #[cfg(feature = "s6")]
            Search::Bvh(bvh) => bvh.intersect(self, ray, t_max),
            #[cfg(feature = "s6")]
            Search::FastBvh(bvh) => bvh.intersect(self, ray, t_max),
        }
    }
    // ANCHOR_END: mesh_intersect

    /// Whether `ray` meets any triangle closer than `t_max`: the shadow-ray test,
    /// which a BVH answers at the first triangle it finds.
    pub fn occluded(&self, ray: &Ray, t_max: Real) -> bool {
        match &self.search {
            #[cfg(feature = "s6")]
            Search::Bvh(bvh) => bvh.occluded(self, ray, t_max),
            #[cfg(feature = "s6")]
            Search::FastBvh(bvh) => bvh.occluded(self, ray, t_max),
            _ => self.intersect(ray, t_max).is_some(),
        }
    }

    /// The hit record of `hit`, for the mesh numbered `object` in the scene. The
    /// point is interpolated from the corners, `alpha A + beta B + gamma C`, whose
    /// error is at most `gamma(7) (|alpha A| + |beta B| + |gamma C|)` (pbrt-v4).
    pub fn hit_record(&self, ray: &Ray, hit: MeshHit, object: usize) -> Hit {
        let [a, b, c] = self.corners(hit.triangle);
        let (beta, gamma) = (hit.at.beta, hit.at.gamma);
        let alpha = 1.0 - beta - gamma;
        let point = alpha * a + beta * b + gamma * c;
        let error = error_bound(7) * ((alpha * a).abs() + (beta * b).abs() + (gamma * c).abs());
        let normal = (b - a).cross(c - a).normalize();
        let weights = [alpha, beta, gamma];
        Hit {
            t: hit.at.t,
            point,
            normal,
            shading_normal: self.shading_normal(hit.triangle, weights, normal),
            error,
            material: Material::Diffuse {
                albedo: self.albedo_at(hit.triangle, weights),
            },
            emission: Colour::ZERO,
            object,
            from_outside: ray.direction.dot(normal) < 0.0,
        }
    }

    /// The normal that shades the point of barycentric `weights` in `triangle`.
    #[cfg_attr(
        not(feature = "s6"),
        expect(unused_variables, reason = "flat until session 6")
    )]
    fn shading_normal(&self, triangle: u32, weights: [Real; 3], geometric: Vec3) -> Vec3 {
        match self.shading {
            Shading::Flat => geometric,
            #[cfg(feature = "s6")]
            Shading::Smooth => self.smooth_normal(triangle, weights, geometric),
        }
    }

    /// The albedo at the point of barycentric `weights` in `triangle`.
    #[cfg_attr(
        not(feature = "s7"),
        expect(unused_variables, reason = "uniform until session 7")
    )]
    fn albedo_at(&self, triangle: u32, weights: [Real; 3]) -> Colour {
        match &self.albedo {
            MeshAlbedo::Constant(colour) => *colour,
            #[cfg(feature = "s7")]
            MeshAlbedo::Texture(texture) => texture.colour(self.uv_at(triangle, weights)),
        }
    }
}

impl crate::scene::objects::Scene {
    /// The nearest mesh hit closer than `t_max`, numbered after the spheres.
    pub fn nearest_mesh(&self, ray: &Ray, t_max: Real) -> Option<Hit> {
        let mut best: Option<(MeshHit, usize)> = None;
        for (k, mesh) in self.meshes.iter().enumerate() {
            let limit = best.map_or(t_max, |(b, _)| b.at.t);
            if let Some(hit) = mesh.intersect(ray, limit) {
                best = Some((hit, k));
            }
        }
        best.map(|(hit, k)| self.meshes[k].hit_record(ray, hit, self.spheres.len() + k))
    }
}
