//! The scene file format (TOML): what a stage declares, checked and turned into a
//! [`Scene`]. Unknown keys are refused, so a misspelt setting never goes unnoticed.

use std::num::NonZeroU32;
use std::path::Path;

use serde::Deserialize;

use crate::camera::pinhole::Camera;
use crate::camera::pinhole::{Lens, Orientation, PixelFilter};
use crate::geometry::sphere::Sphere;
use crate::integrator::termination::Termination;
use crate::lights::light::{Light, PointLight};
use crate::materials::material::Material;
use crate::maths::numbers::Colour;
use crate::maths::numbers::Real;
use crate::scene::objects::{Scene, Settings};
use crate::scene_file::error::{SceneError, one_line};
use crate::scene_file::features::{SESSION, feature_name};
use crate::scene_file::values::{
    Albedo, Degrees, Finite, NonNegative, Point, Positive, Probability, Rgb,
};

/// The largest image, in pixels, a scene may ask for (8192 x 8192): beyond it the
/// film alone would take gigabytes.
pub const MAX_PIXELS: u64 = 8192 * 8192;

/// A whole scene file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
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

/// One `[[meshes]]` entry: an OBJ file placed in the scene,
/// `p' = rotation (scale p) + translation`.
#[derive(Debug, Deserialize)]
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

/// `acceleration = "none"`, `"bbox"`, `"bvh"` or `"fast"`: how meshes are searched.
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
    /// A hierarchy built with the surface area heuristic and laid out for speed
    /// (after session 6; leaves of at most `leaf_size` triangles).
    Fast,
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
#[derive(Debug, Deserialize)]
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
    /// Most triangles in a leaf of the `"fast"` hierarchy (default 8).
    pub leaf_size: Option<std::num::NonZeroU16>,
}

fn one() -> NonZeroU32 {
    NonZeroU32::MIN
}

fn five() -> u32 {
    5
}

/// `[camera]`: the eye.
#[derive(Debug, Deserialize)]
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
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LensSpec {
    /// Radius of the lens.
    pub aperture: Positive,
    /// Distance from the eye to the sharp plane.
    pub focus: Positive,
}

/// `[light]`: a point light, or with a radius a sphere light.
#[derive(Debug, Deserialize)]
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
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SphereSpec {
    /// Centre of the sphere.
    pub centre: Point,
    /// Radius, greater than 0.
    pub radius: Positive,
    /// What it is made of.
    pub material: MaterialSpec,
    /// Radiance it emits (default none).
    pub emission: Option<Rgb>,
}

/// A material as written in a scene file: `{ diffuse = [r, g, b] }`, `"mirror"` or
/// `{ glass = 1.5 }`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "kebab-case", deny_unknown_fields)]
pub enum MaterialSpec {
    /// Lambertian with this albedo (session 1).
    Diffuse(Albedo),
    /// Perfect mirror (session 2).
    Mirror,
    /// Glass with this refractive index (session 2).
    Glass(Positive),
    /// Glass with Fresnel reflection (session 4).
    FresnelGlass(Positive),
}

impl MaterialSpec {
    /// The course session that teaches this material, and its name.
    fn session(self) -> (u32, &'static str) {
        match self {
            Self::Diffuse(_) => (1, "a diffuse material"),
            Self::Mirror => (2, "a mirror material"),
            Self::Glass(_) => (2, "a glass material"),
            Self::FresnelGlass(_) => (4, "a Fresnel glass material"),
        }
    }

    /// The material of the renderer, or `None` if this build lacks it.
    fn build(self) -> Option<Material> {
        #[allow(unreachable_patterns, reason = "all arms exist from session 2 on")]
        match self {
            Self::Diffuse(Albedo(albedo)) => Some(Material::Diffuse { albedo }),
            #[cfg(feature = "s2")]
            Self::Mirror => Some(Material::Mirror),
            #[cfg(feature = "s2")]
            Self::Glass(Positive(index)) => Some(Material::Glass { index }),
            #[cfg(feature = "s4")]
            Self::FresnelGlass(Positive(index)) => Some(Material::FresnelGlass { index }),
            _ => None,
        }
    }
}

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
    fn apply(&self, file: &mut SceneFile) -> Result<(), String> {
        if let Some(p) = self.plunge {
            file.camera.plunge = Some(Finite::try_from(p)?);
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

/// Reads and checks the scene file at `path`, with `overrides` applied.
pub fn load_scene(path: &Path, overrides: &Overrides) -> Result<Scene, SceneError> {
    let source = std::fs::read_to_string(path).map_err(|source| SceneError::Read {
        path: path.to_owned(),
        source,
    })?;
    parse_scene(&source, path, overrides)
}

/// Parses and checks scene-file text, with `overrides` applied; `path` names it in
/// error messages.
pub fn parse_scene(source: &str, path: &Path, overrides: &Overrides) -> Result<Scene, SceneError> {
    let invalid = |span: Option<std::ops::Range<usize>>, key: String, message: &str| {
        let (line, column) = line_and_column(source, span.map_or(0, |s| s.start));
        SceneError::Invalid {
            path: path.to_owned(),
            line,
            column,
            key,
            message: one_line(message),
        }
    };
    let deserializer = toml::Deserializer::parse(source)
        .map_err(|e| invalid(e.span(), String::new(), e.message()))?;
    let mut file: SceneFile = serde_path_to_error::deserialize(deserializer).map_err(|e| {
        let key = e.path().to_string();
        let inner = e.into_inner();
        invalid(inner.span(), key, inner.message())
    })?;
    overrides
        .apply(&mut file)
        .map_err(|message| SceneError::Inconsistent {
            path: path.to_owned(),
            key: "camera.plunge".into(),
            message,
        })?;
    file.into_scene(path)
}

/// The error for a scene key that needs a later session's feature.
pub fn missing_feature(path: &Path, key: &str, session: u32, what: &str) -> SceneError {
    SceneError::NeedsFeature {
        path: path.to_owned(),
        key: key.to_owned(),
        what: what.to_owned(),
        feature: feature_name(session),
    }
}

/// `Ok` if this build has `session`, else the error naming its feature.
pub fn require(path: &Path, key: &str, session: u32, what: &str) -> Result<(), SceneError> {
    if session <= SESSION {
        Ok(())
    } else {
        Err(missing_feature(path, key, session, what))
    }
}

/// 1-based line and column of byte `offset` in `source`.
fn line_and_column(source: &str, offset: usize) -> (usize, usize) {
    let before = &source[..offset.min(source.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

impl SceneFile {
    /// The scene this file describes, once every value is known to be usable in this
    /// build.
    pub fn into_scene(self, path: &Path) -> Result<Scene, SceneError> {
        let missing =
            |key: &str, session: u32, what: &str| missing_feature(path, key, session, what);
        let needs = |key: &str, session: u32, what: &str| require(path, key, session, what);
        if !self.meshes.is_empty() {
            needs("meshes", 5, "triangle meshes")?;
        }
        if self.render.acceleration != AccelerationSpec::None {
            needs("render.acceleration", 5, "an acceleration structure")?;
        }
        if self.render.triangle_test.is_some() {
            needs("render.triangle_test", 5, "triangle meshes")?;
        }
        if matches!(
            self.render.acceleration,
            AccelerationSpec::Bvh | AccelerationSpec::Fast
        ) {
            needs("render.acceleration", 6, "a bounding volume hierarchy")?;
        }
        if self.render.leaf_size.is_some() && self.render.acceleration != AccelerationSpec::Fast {
            return Err(SceneError::Inconsistent {
                path: path.to_owned(),
                key: "render.leaf_size".into(),
                message: "only the \"fast\" acceleration has a leaf size".into(),
            });
        }
        let camera = &self.camera;
        if camera.look_at.is_some() || camera.up.is_some() || camera.plunge.is_some() {
            needs("camera.look_at", 7, "an aimed camera")?;
        }
        if camera.look_at.is_none() && (camera.up.is_some() || camera.plunge.is_some()) {
            return Err(SceneError::Inconsistent {
                path: path.to_owned(),
                key: "camera.look_at".into(),
                message: "`up` and `plunge` aim the camera: give it a `look_at` point".into(),
            });
        }
        let r = &self.render;
        let pixels = u64::from(r.width.get()) * u64::from(r.height.get());
        if pixels > MAX_PIXELS {
            return Err(SceneError::Inconsistent {
                path: path.to_owned(),
                key: "render.width".into(),
                message: format!(
                    "{} x {} is {pixels} pixels; at most {MAX_PIXELS} are allowed",
                    r.width, r.height
                ),
            });
        }
        if r.gamma.is_some() {
            needs("render.gamma", 2, "gamma correction")?;
        }
        if r.shadows {
            needs("render.shadows", 2, "shadow rays")?;
            if self.light.as_ref().is_some_and(|l| l.radius.is_some()) {
                return Err(SceneError::Inconsistent {
                    path: path.to_owned(),
                    key: "render.shadows".into(),
                    message: "shadow rays are for a point light; a sphere light's shadows \
                              come from light_sampling or indirect rays"
                        .into(),
                });
            }
        }
        if r.indirect {
            needs("render.indirect", 3, "indirect lighting")?;
        }
        if r.light_sampling {
            needs("render.light_sampling", 4, "light sampling")?;
            if self.light.as_ref().is_none_or(|l| l.radius.is_none()) {
                return Err(SceneError::Inconsistent {
                    path: path.to_owned(),
                    key: "render.light_sampling".into(),
                    message: "light sampling needs a sphere light: give [light] a radius".into(),
                });
            }
        }
        let mut spheres = Vec::with_capacity(self.spheres.len() + 1);
        for (i, s) in self.spheres.iter().enumerate() {
            let (session, what) = s.material.session();
            let material = s
                .material
                .build()
                .ok_or_else(|| missing(&format!("spheres[{i}].material"), session, what))?;
            spheres.push(Sphere {
                centre: s.centre.0,
                radius: s.radius.0,
                material,
                emission: s.emission.map_or(Colour::ZERO, |e| e.0),
            });
        }
        #[allow(unreachable_patterns, reason = "every arm exists from session 4 on")]
        let light = match self.light {
            None => None,
            Some(LightSpec {
                position,
                intensity,
                radius: None,
            }) => Some(Light::Point(PointLight {
                position: position.0,
                intensity: intensity.0,
            })),
            #[cfg(feature = "s4")]
            Some(LightSpec {
                position,
                intensity,
                radius: Some(Positive(radius)),
            }) => {
                let light = crate::lights::sphere_light::SphereLight::new(
                    position.0,
                    radius,
                    intensity.0,
                    spheres.len(),
                );
                spheres.push(light.body());
                Some(Light::Sphere(light))
            }
            Some(_) => return Err(missing("light.radius", 4, "a sphere light")),
        };
        #[allow(unreachable_patterns, reason = "every arm exists from session 3 on")]
        let filter = match self.camera.antialiasing {
            None => PixelFilter::Centre,
            #[cfg(feature = "s3")]
            Some(Positive(sigma)) => PixelFilter::Gaussian { sigma },
            Some(_) => return Err(missing("camera.antialiasing", 3, "antialiasing")),
        };
        #[allow(unreachable_patterns, reason = "every arm exists from session 4 on")]
        let lens = match self.camera.lens {
            None => Lens::Pinhole,
            #[cfg(feature = "s4")]
            Some(LensSpec { aperture, focus }) => Lens::Thin(crate::camera::lens::ThinLens {
                aperture: aperture.0,
                focus: focus.0,
            }),
            Some(_) => return Err(missing("camera.lens", 4, "a thin lens")),
        };
        #[allow(unreachable_patterns, reason = "every arm exists from session 4 on")]
        let termination = match r.russian_roulette {
            None => Termination::BounceLimit,
            #[cfg(feature = "s4")]
            Some(Probability(survival)) => Termination::RussianRoulette { survival },
            Some(_) => return Err(missing("render.russian_roulette", 4, "Russian roulette")),
        };
        #[allow(unreachable_patterns, reason = "every arm exists from session 7 on")]
        let (position, orientation) = match self.camera.look_at {
            None => (self.camera.position.0, Orientation::Fixed),
            #[cfg(feature = "s7")]
            Some(target) => crate::camera::aim::aim(
                self.camera.position.0,
                target.0,
                self.camera
                    .up
                    .map_or(crate::maths::numbers::Vec3::Y, |u| u.0),
                self.camera.plunge.map_or(0.0, |p| p.0),
            )
            .ok_or_else(|| SceneError::Inconsistent {
                path: path.to_owned(),
                key: "camera.up".into(),
                message: "the camera must not look along `up` or at its own position".into(),
            })?,
            Some(_) => return Err(missing("camera.look_at", 7, "an aimed camera")),
        };
        Ok(Scene {
            #[cfg(feature = "s5")]
            meshes: crate::scene_file::meshes::build_meshes(
                &self.meshes,
                r.acceleration,
                r.leaf_size.map_or(8, |l| l.get()),
                r.triangle_test.unwrap_or_default(),
                path,
            )?,
            camera: Camera {
                position,
                fov: self.camera.fov.0.to_radians(),
                width: r.width.get(),
                height: r.height.get(),
                filter,
                lens,
                orientation,
            },
            spheres,
            light,
            settings: Settings {
                samples: r.samples.get(),
                bounces: r.bounces,
                seed: r.seed,
                gamma: r.gamma.map_or(1.0, |g| g.0),
                shadows: r.shadows,
                indirect: r.indirect,
                light_sampling: r.light_sampling,
                termination,
            },
        })
    }
}
