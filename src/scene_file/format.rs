//! The scene file format (TOML): what a stage declares. Every key of every session
//! is known here, so that a scene asking for a later session's feature is answered
//! by name ([`crate::scene_file::sessions`]); unknown keys are refused, so a
//! misspelt setting never goes unnoticed.

use std::num::NonZeroU32;

use serde::Deserialize;

use crate::materials::Material;
use crate::maths::values::{
    Albedo, Degrees, Finite, NonNegative, Point, Positive, Probability, Rgb,
};

/// The largest image, in pixels, a scene may ask for (8192 x 8192): beyond it the
/// film alone would take gigabytes.
pub const MAX_PIXELS: u64 = 8192 * 8192;

/// A whole scene file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// The `[stage]` table of a course stage's file: what the stage is. A render
    /// does not use it.
    pub stage: Option<StageSpec>,
    /// The `[render]` table.
    pub render: RenderSpec,
    /// The `[camera]` table.
    pub camera: CameraSpec,
    /// The `[light]` table, if the scene is lit.
    pub light: Option<LightSpec>,
    /// The `[[spheres]]` array.
    #[serde(default)]
    pub spheres: Vec<SphereSpec>,
    /// The `[[meshes]]` array (session 5).
    #[serde(default)]
    pub meshes: Vec<MeshSpec>,
}

/// `[stage]`: what a course stage's scene file says of itself, read by the build
/// script (`build.rs`) into the list of stages and by `bench` and `list`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StageSpec {
    /// The figure of the course it reproduces (absent: an extra stage).
    pub figure: Option<u32>,
    /// What the stage adds, in a few words.
    pub title: String,
    /// The time the course reported for it on its own machine, such as `35 s`.
    pub course_time: Option<String>,
}

/// One `[[meshes]]` entry: an OBJ file placed in the scene,
/// `p' = rotation (scale p) + translation`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshSpec {
    /// The OBJ file, relative to the scene file.
    pub obj: String,
    /// Uniform scale (default 1).
    pub scale: Option<Positive>,
    /// Rotation in degrees about `x`, then `y`, then `z` (default none).
    pub rotation: Option<Point>,
    /// Translation (default none).
    pub translation: Option<Point>,
    /// Diffuse albedo where there is no texture (default white).
    pub albedo: Option<Albedo>,
    /// Shade with interpolated vertex normals (session 6; default false).
    #[serde(default)]
    pub smooth_normals: bool,
    /// Colour from the OBJ material's `map_Kd` texture (session 7; default false).
    #[serde(default)]
    pub textured: bool,
    /// A texture file replacing the material's, relative to the scene file (session 7).
    pub texture: Option<String>,
    /// How the texture is read (session 7; default nearest).
    pub texture_filter: Option<FilterSpec>,
}

/// `texture_filter = "nearest"` or `"bilinear"`.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum FilterSpec {
    /// The texel the point falls in.
    Nearest,
    /// The four nearest texels, blended.
    Bilinear,
}

/// `acceleration = "none"`, `"bbox"` or `"bvh"`: how meshes are searched.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum AccelerationSpec {
    /// Every triangle for every ray (session 5).
    #[default]
    None,
    /// Test the mesh's bounding box first (session 5).
    Bbox,
    /// A bounding volume hierarchy (session 6).
    Bvh,
}

/// `triangle_test = "moller-trumbore"` or `"watertight"`: how a ray meets a triangle.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum TriangleTestSpec {
    /// The course's barycentric solve (the session-5 stages).
    MollerTrumbore,
    /// The watertight test (the default).
    #[default]
    Watertight,
}

/// `[render]`: image size and how the render is done.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderSpec {
    /// Image width in pixels.
    pub width: NonZeroU32,
    /// Image height in pixels.
    pub height: NonZeroU32,
    /// Samples per pixel (default 1).
    #[serde(default = "one")]
    pub samples: NonZeroU32,
    /// Reflections and refractions allowed along a path (default 5).
    #[serde(default = "five")]
    pub bounces: u32,
    /// Seed of the random generators (default 0).
    #[serde(default)]
    pub seed: u64,
    /// Display gamma (absent: linear output).
    pub gamma: Option<Positive>,
    /// Whether shadow rays are traced towards a point light (default false).
    #[serde(default)]
    pub shadows: bool,
    /// The course's fixed offset `epsilon` of a shadow ray's origin along the normal
    /// (session 2; absent: the offset that follows the hit point's rounding error).
    pub shadow_offset: Option<NonNegative>,
    /// Whether diffuse surfaces reflect indirect light (session 3; default false).
    #[serde(default)]
    pub indirect: bool,
    /// Whether a sphere light is sampled directly (session 4; default false).
    #[serde(default)]
    pub light_sampling: bool,
    /// Survival probability of Russian roulette past the bounce limit (session 4;
    /// absent: paths stop at the limit).
    pub russian_roulette: Option<Probability>,
    /// How meshes are searched for the nearest hit (session 5; default none).
    #[serde(default)]
    pub acceleration: AccelerationSpec,
    /// Which ray-triangle test meshes use (session 5; default watertight).
    pub triangle_test: Option<TriangleTestSpec>,
}

fn one() -> NonZeroU32 {
    NonZeroU32::MIN
}

fn five() -> u32 {
    5
}

/// `[camera]`: the eye.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraSpec {
    /// Where the eye is.
    pub position: Point,
    /// Vertical field of view in degrees.
    pub fov: Degrees,
    /// Standard deviation of the Gaussian jitter of camera rays, in pixels
    /// (session 3; absent: rays through pixel centres).
    pub antialiasing: Option<Positive>,
    /// A thin lens (session 4; absent: a pinhole).
    pub lens: Option<LensSpec>,
    /// The point the camera looks at (session 7; absent: down `-z`).
    pub look_at: Option<Point>,
    /// Which way is up when aiming (session 7; default `[0, 1, 0]`).
    pub up: Option<Point>,
    /// Angle in degrees by which the eye is raised around `look_at`, keeping its
    /// distance, to look down on the scene (session 7; default 0).
    pub plunge: Option<Finite>,
}

/// `lens = { aperture = ..., focus = ... }`: a thin lens.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LensSpec {
    /// Radius of the lens.
    pub aperture: Positive,
    /// Distance from the eye to the sharp plane.
    pub focus: Positive,
}

/// `[light]`: a point light, or with a radius a sphere light.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightSpec {
    /// Where the light is (the centre of a sphere light).
    pub position: Point,
    /// Its intensity `I`: the total power it emits.
    pub intensity: NonNegative,
    /// Radius of a sphere light (session 4; absent: a point light).
    pub radius: Option<Positive>,
}

/// One `[[spheres]]` entry.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SphereSpec {
    /// Centre of the sphere.
    pub centre: Point,
    /// Radius, greater than 0.
    pub radius: Positive,
    /// What it is made of.
    pub material: Material,
    /// Radiance it emits (default none).
    pub emission: Option<Rgb>,
}
