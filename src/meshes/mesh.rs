//! A triangle mesh placed in the scene: its triangles, how a ray meets one, and the
//! hit record of the nearest.

use std::sync::Arc;

use crate::geometry::{
    Aabb, Hit, Ray, ShearedRay, TriangleHit, TriangleTest, cost, intersect_triangle,
};
use crate::materials::Material;
use crate::maths::{Colour, Real, Vec3, error_bound};
use crate::meshes::clearance::{clearance, offset_clearing};

#[cfg(feature = "s7")]
use crate::materials::texture::Texture;

// ANCHOR: mesh
/// A placed triangle mesh and how it is drawn.
#[derive(Clone, Debug)]
pub struct Mesh {
    /// Vertex positions, in scene coordinates.
    pub positions: Vec<Vec3>,
    /// Unit vertex normals, one per position, or none: those of the file, kept for
    /// smooth shading (session 6), which interpolates them.
    pub normals: Vec<Vec3>,
    /// Texture coordinates `(u, v)`, one per position, or none if the file had none.
    pub uvs: Vec<[Real; 2]>,
    /// Three vertex indices per triangle, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// The box around every vertex.
    pub bounds: Aabb,
    /// How the nearest triangle is found.
    pub search: Arc<dyn Search>,
    /// How one triangle is tested.
    pub triangle_test: TriangleTest,
    /// Its diffuse colour.
    pub albedo: MeshAlbedo,
    /// The picture the OBJ file's material names (`map_Kd`), for textures (session 7).
    pub texture_file: Option<std::path::PathBuf>,
}
// ANCHOR_END: mesh

// ANCHOR: search
/// A way of finding the triangles of a mesh that a ray meets. Every search finds
/// the same hits; only the time differs. Session 5 tests every triangle
/// ([`BruteForce`](crate::meshes::BruteForce)), then only behind the mesh's bounding box; session 6 builds a
/// bounding volume hierarchy.
pub trait Search: std::fmt::Debug + Send + Sync {
    /// Its name in tables and tests, such as `brute force`.
    fn name(&self) -> &'static str;

    /// The nearest triangle of `mesh` that `ray` meets closer than `t_max`.
    fn nearest(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> Option<MeshHit>;

    /// Whether `ray` meets any triangle of `mesh` closer than `t_max`: a shadow ray's
    /// question, which a search may answer at the first triangle it finds.
    fn occluded(&self, mesh: &Mesh, ray: &Ray, t_max: Real) -> bool {
        self.nearest(mesh, ray, t_max).is_some()
    }
}
// ANCHOR_END: search

/// The colour of a diffuse mesh.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshAlbedo {
    /// The same everywhere.
    Constant(Colour),
    /// Read from an image at the hit's texture coordinates (session 7).
    #[cfg(feature = "s7")]
    Texture(Texture),
}

/// The nearest triangle hit: which triangle, where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshHit {
    /// Index of the triangle in [`Mesh::triangles`].
    pub triangle: u32,
    /// Distance and barycentric coordinates.
    pub at: TriangleHit,
}

impl Mesh {
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
    /// the caller, however many leaves of a hierarchy the ray visits. Every one of
    /// `triangles` is tested, and counted for `--aov cost`.
    pub fn nearest_among(
        &self,
        ray: &Ray,
        sheared: &ShearedRay,
        triangles: impl ExactSizeIterator<Item = u32>,
        mut best: Option<MeshHit>,
        t_max: Real,
    ) -> Option<MeshHit> {
        cost::count_triangles(triangles.len());
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
    /// The nearest triangle that `ray` meets closer than `t_max`, found by the mesh's
    /// search.
    pub fn intersect(&self, ray: &Ray, t_max: Real) -> Option<MeshHit> {
        self.search.nearest(self, ray, t_max)
    }
    // ANCHOR_END: mesh_intersect

    /// Whether `ray` meets any triangle closer than `t_max`: the shadow-ray test,
    /// which a BVH answers at the first triangle it finds.
    pub fn occluded(&self, ray: &Ray, t_max: Real) -> bool {
        self.search.occluded(self, ray, t_max)
    }

    // ANCHOR: hit_record
    /// The hit record of `hit`, for the mesh numbered `object` in the scene. The
    /// point is interpolated from the corners, `b_A P_A + b_B P_B + b_C P_C`, whose error
    /// is at most `delta_7 (|b_A P_A| + |b_B P_B| + |b_C P_C|)` (pbrt-v4). The
    /// geometric normal, the triangle's own `(P_B - P_A) x (P_C - P_A)` normalised,
    /// decides on which side a new ray starts and whether the ray came from outside;
    /// the shading normal, `normal`, starts as that same normal.
    pub fn hit_record(&self, ray: &Ray, hit: MeshHit, object: usize) -> Hit {
        let corners = self.corners(hit.triangle);
        let weights = [1.0 - hit.at.beta - hit.at.gamma, hit.at.beta, hit.at.gamma];
        let [a, b, c] = [0, 1, 2].map(|k| weights[k] * corners[k]);
        let point = a + b + c;
        let error = error_bound(7) * (a.abs() + b.abs() + c.abs());
        let [a, b, c] = corners;
        let area_normal = (b - a).cross(c - a);
        let geometric = area_normal.normalize();
        let clearance = clearance(corners, point, area_normal.length());
        let normal = geometric;
        #[cfg(feature = "s6")]
        let normal = self.smooth_normal(hit.triangle, weights, normal);
        let albedo = match &self.albedo {
            MeshAlbedo::Constant(colour) => *colour,
            #[cfg(feature = "s7")]
            MeshAlbedo::Texture(texture) => texture.colour(self.uv_at(hit.triangle, weights)),
        };
        Hit {
            t: hit.at.t,
            point,
            normal,
            error,
            offset: offset_clearing(geometric, error, clearance),
            material: Material::Diffuse { albedo },
            emission: Colour::ZERO,
            object,
            from_outside: ray.direction.dot(geometric) < 0.0,
        }
    }
    // ANCHOR_END: hit_record
}
