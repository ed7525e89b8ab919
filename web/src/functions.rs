//! Which of the course's functions a scene's render runs, as the book names them:
//! what a demo lists under its image, so that a reader knows which listings made it.

use raycourse::Scene;
use raycourse::camera::{Lens, PixelFilter};
use raycourse::lights::Light;
use raycourse::materials::Material;
use raycourse::meshes::MeshAlbedo;

/// The course functions that rendering `scene` runs, from the pixel loop to the
/// light: each listed once, in the order a ray meets them.
pub fn ran(scene: &Scene) -> Vec<&'static str> {
    let mut names = vec!["render_row", "pixel"];
    names.extend(camera(scene));
    names.extend(["Tracer::radiance", "Tracer::reflected", "Scene::intersect"]);
    names.extend([
        "Scene::nearest_sphere",
        "Sphere::intersect",
        "Sphere::hit_at",
    ]);
    names.extend(meshes(scene));
    names.extend(materials(scene));
    names
}

/// The camera's functions: the pinhole, its jitter, its lens, its aim.
fn camera(scene: &Scene) -> Vec<&'static str> {
    let camera = &scene.camera;
    let mut names = vec!["Camera::ray", "Camera::pixel_direction"];
    if camera.filter != PixelFilter::Centre {
        names.push("Camera::sample_ray");
    }
    if matches!(camera.lens, Lens::Thin(_)) {
        names.extend(["sample_disk", "ThinLens::refocus"]);
    }
    if camera.orientation != Default::default() {
        names.push("Orientation::to_world");
    }
    names
}

/// The meshes' functions: the search its scene file chose, the triangle test, and
/// the hit record with smooth normals and textures where a mesh has them.
fn meshes(scene: &Scene) -> Vec<&'static str> {
    let Some(first) = scene.meshes.first() else {
        return vec![];
    };
    let mut names = vec!["Scene::nearest_mesh", "Mesh::intersect"];
    names.push(match first.search.name() {
        "brute force" => "BruteForce::nearest",
        "bounding box" => "BoundingBox::nearest",
        _ => "Bvh::nearest",
    });
    names.push(match first.triangle_test {
        raycourse::geometry::TriangleTest::MollerTrumbore => "intersect_triangle (Möller-Trumbore)",
        raycourse::geometry::TriangleTest::Watertight => "intersect_triangle (watertight)",
    });
    names.push("Mesh::hit_record");
    if scene.meshes.iter().any(|m| !m.normals.is_empty()) {
        names.push("Mesh::smooth_normal");
    }
    if scene
        .meshes
        .iter()
        .any(|m| matches!(m.albedo, MeshAlbedo::Texture(_)))
    {
        names.extend(["Mesh::uv_at", "Texture::colour", "Texture::texel"]);
    }
    names
}

/// What the materials and the light bring: Lambert and shadows, mirrors and glass,
/// indirect light, the sphere light and its sampling, Russian roulette.
fn materials(scene: &Scene) -> Vec<&'static str> {
    let settings = &scene.settings;
    let has = |wanted: fn(&Material) -> bool| scene.spheres.iter().any(|s| wanted(&s.material));
    let mut names = vec![];
    if has(|m| matches!(m, Material::Mirror)) {
        names.extend(["Tracer::mirror", "reflect"]);
    }
    if has(|m| matches!(m, Material::Glass { .. })) {
        names.extend(["Tracer::glass", "refract", "reflect"]);
    }
    if has(|m| matches!(m, Material::FresnelGlass { .. })) {
        names.extend(["Tracer::fresnel_glass", "fresnel_reflectance"]);
    }
    if has(|m| matches!(m, Material::Diffuse { .. })) || !scene.meshes.is_empty() {
        names.extend(["Tracer::diffuse", "Tracer::direct_light"]);
        names.extend(lights(scene));
        if settings.indirect {
            names.extend(["Tracer::indirect_light", "Tracer::cosine_direction"]);
            names.extend(["Tracer::bounce", "Tracer::next_bounce"]);
        }
    }
    names.dedup();
    names
}

/// The light's functions: a point light's Lambert term and shadow ray, or a sphere
/// light sampled directly.
fn lights(scene: &Scene) -> Vec<&'static str> {
    let settings = &scene.settings;
    let mut names = vec![];
    match scene.light {
        Some(Light::Point(_)) => {
            names.extend(["Tracer::point_light", "PointLight::lambert"]);
            if settings.shadows {
                names.extend(["Tracer::in_shadow", "Scene::occluded"]);
            }
        }
        Some(Light::Sphere(_)) if settings.light_sampling => {
            names.extend(["Tracer::sphere_light", "Tracer::sample_light"]);
            names.extend(["SphereLight::sample", "Scene::occluded"]);
        }
        _ => {}
    }
    if settings.russian_roulette.is_some() {
        names.push("Russian roulette");
    }
    names
}
