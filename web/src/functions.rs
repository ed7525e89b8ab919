//! Which of the course's functions a scene's render runs, as the book names them:
//! what a demo lists under its image, so that a reader knows which listings made it.

use raycourse::Scene;
use raycourse::camera::{Lens, PixelFilter};
use raycourse::fast::paths::paths_at_once;
use raycourse::geometry::TriangleTest;
use raycourse::lights::Light;
use raycourse::materials::Material;
use raycourse::meshes::MeshAlbedo;
use raycourse::scene::beyond::Beyond;

/// The course functions that rendering `scene` with the settings `beyond` runs,
/// from the pixel loop to the light: each listed once, in the order a ray first
/// meets them. Where the fast engine follows four paths at a time, none of them
/// runs: its row function is named instead.
pub fn ran(scene: &Scene, beyond: &Beyond) -> Vec<&'static str> {
    if beyond.fast && paths_at_once::applies(scene) {
        return vec!["paths_at_once::row"];
    }
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
    let mut seen = std::collections::HashSet::new();
    names.retain(|name| seen.insert(*name));
    names
}

/// The camera's functions: each sample's ray (`sample_ray`, the course's pixel loop
/// from session 3 on), its jitter, its lens, its aim.
fn camera(scene: &Scene) -> Vec<&'static str> {
    let camera = &scene.camera;
    let mut names = vec!["Camera::sample_ray", "Camera::pixel_direction"];
    names.extend(["PixelFilter::offset", "Lens::refocus", "Camera::place"]);
    if camera.filter != PixelFilter::Centre {
        names.push("sample_gaussian");
    }
    if matches!(camera.lens, Lens::Thin(_)) {
        names.extend(["ThinLens::refocus", "sample_disk"]);
    }
    if camera.orientation != Default::default() {
        names.push("Orientation::to_world");
    }
    names
}

/// The meshes' functions: the search its scene file chose, the triangle test, and
/// the hit record with smooth normals and textures where a mesh has them. The fast
/// engine's brute force tests its triangles on lanes, not with the course's test.
fn meshes(scene: &Scene) -> Vec<&'static str> {
    let Some(first) = scene.meshes.first() else {
        return vec![];
    };
    let mut names = vec!["Scene::nearest_mesh", "Mesh::intersect"];
    names.extend(match first.search.name() {
        "brute force, fast" | "bounding box, fast" => {
            ["FastBruteForce::nearest", "TriangleLanes::hits"]
        }
        name => [search_function(name), triangle_test(first.triangle_test)],
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

/// The `nearest` of the course's search called `name`, or of the fast hierarchy.
fn search_function(name: &str) -> &'static str {
    match name {
        "brute force" => "BruteForce::nearest",
        "bounding box" => "BoundingBox::nearest",
        "fast" => "FastBvh::nearest",
        _ => "Bvh::nearest",
    }
}

/// The course's triangle test `test`, as the list names it.
fn triangle_test(test: TriangleTest) -> &'static str {
    match test {
        TriangleTest::MollerTrumbore => "intersect_triangle (Möller-Trumbore)",
        TriangleTest::Watertight => "intersect_triangle (watertight)",
    }
}

/// What the materials and the light bring: Lambert and shadows, mirrors and glass,
/// indirect light and its bounces (with Russian roulette where the scene asks for
/// it), the sphere light and its sampling.
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
            names.push("Tracer::bounce");
            names.push(match settings.russian_roulette {
                Some(_) => "Tracer::next_bounce (Russian roulette)",
                None => "Tracer::next_bounce",
            });
        }
    }
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
    names
}

#[cfg(test)]
mod tests {
    use super::*;
    use raycourse::Overrides;

    fn listed(name: &str) -> Vec<&'static str> {
        let stage = raycourse::stages().find(|s| s.name == name).unwrap();
        let files = crate::assets::stage_files();
        ran(
            &stage.scene_from(&Overrides::default(), files).unwrap(),
            &Beyond::default(),
        )
    }

    #[test]
    fn the_list_follows_the_scene_and_names_each_function_once() {
        let camera = listed("camera");
        for name in [
            "Camera::sample_ray",
            "sample_gaussian",
            "Orientation::to_world",
        ] {
            assert!(camera.contains(&name), "{name} in {camera:?}");
        }
        assert!(camera.contains(&"Texture::colour") && camera.contains(&"Bvh::nearest"));
        assert!(
            !camera.contains(&"Camera::ray"),
            "from session 3, rays are sample_ray's"
        );
        let glass = listed("glass");
        assert!(glass.contains(&"refract") && !glass.contains(&"Tracer::mirror"));
        assert!(!glass.contains(&"ThinLens::refocus") && !glass.contains(&"Mesh::intersect"));
        for list in [camera, glass, listed("depth-of-field")] {
            let mut unique = list.clone();
            unique.sort();
            unique.dedup();
            assert_eq!(unique.len(), list.len(), "{list:?}");
        }
    }

    #[test]
    fn the_fast_engine_names_its_own_row_or_its_hierarchy() {
        let fast = |name: &str| {
            let edits = r#"{"render.fast": true}"#;
            let (scene, beyond) = crate::demo::scene(name, edits, 16, 16, 0).unwrap();
            ran(&scene, &beyond)
        };
        assert_eq!(fast("indirect"), ["paths_at_once::row"]);
        let glass = fast("glass");
        assert!(glass.contains(&"refract"), "the course's code: {glass:?}");
    }

    #[test]
    fn the_fast_engine_names_its_searches_of_a_mesh() {
        let searches = |name: &str, edits: &str| {
            let (scene, _) = crate::demo::scene(name, edits, 16, 16, 0).unwrap();
            meshes(&scene)[2..4].to_vec()
        };
        let fast = r#"{"render.fast": true}"#;
        for stage in ["mesh", "mesh-bbox"] {
            assert_eq!(
                searches(stage, fast),
                ["FastBruteForce::nearest", "TriangleLanes::hits"]
            );
        }
        assert_eq!(
            searches("mesh", "{}"),
            [
                "BruteForce::nearest",
                "intersect_triangle (Möller-Trumbore)"
            ]
        );
        assert_eq!(searches("bvh", fast)[0], "FastBvh::nearest");
    }
}
