//! Meshes: what the loader reads from the two assets, that the bounding box and the
//! BVH find exactly the hit that brute force finds, and clear errors for bad files.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use raycourse::geometry::Ray;
use raycourse::maths::{Mat3, Real, Vec3, pixel_rng, uniform};
use raycourse::{Overrides, parse_scene};
use std::sync::Arc;

use raycourse::meshes::{Mesh, MeshHit, ObjData, Placement, read_obj};
use rayon::prelude::*;

fn asset(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets")
        .join(path)
}

fn distinct_positions(data: &ObjData) -> usize {
    let keys: HashSet<_> = data
        .positions
        .iter()
        .map(|p| p.to_array().map(Real::to_bits))
        .collect();
    keys.len()
}

#[test]
fn spot_loads_with_normals_uvs_and_its_texture() {
    let data = read_obj(&asset("spot/spot.obj")).unwrap();
    assert_eq!(data.triangles.len(), 5856);
    assert_eq!(distinct_positions(&data), 2930, "the file's `v` lines");
    // One index per corner: a position is repeated for each distinct (v, vt, vn).
    assert_eq!(data.positions.len(), 3225);
    assert_eq!(data.normals.len(), data.positions.len());
    assert_eq!(data.uvs.len(), data.positions.len());
    assert_eq!(data.diffuse_texture, Some(asset("spot/spot_texture.png")));
}

#[test]
fn ogre_loads_with_normals_and_uvs_but_no_material() {
    let data = read_obj(&asset("ogre/ogre.obj")).unwrap();
    assert_eq!(data.triangles.len(), 39856);
    assert_eq!(distinct_positions(&data), 19985);
    assert_eq!(data.positions.len(), 19985);
    assert_eq!(data.normals.len(), 19985);
    assert_eq!(data.uvs.len(), 19985);
    assert_eq!(data.diffuse_texture, None, "ogre.obj has no mtllib");
}

/// The mesh of `data` where the file puts it.
fn unplaced(data: &ObjData) -> Mesh {
    let placement = Placement {
        scale: 1.0,
        rotation: Mat3::IDENTITY,
        translation: Vec3::ZERO,
    };
    Mesh::new(data, &placement)
}

/// `count` seeded rays: four in five from a sphere around the mesh towards random
/// points of its box, one in five leaving a random point of a triangle in a random
/// direction from just above it, as a bounce does (the single-precision pre-test of
/// the fast BVH must not drop the triangles such a ray starts near).
fn rays_at(mesh: &Mesh, count: u64) -> Vec<Ray> {
    let centre = mesh.bounds.centre();
    let size = mesh.bounds.max - mesh.bounds.min;
    let radius = size.length();
    (0..count)
        .map(|i| {
            let mut rng = pixel_rng(99, i);
            let mut u = || uniform(&mut rng);
            let z: Real = 2.0 * u() - 1.0;
            let phi = 2.0 * raycourse::maths::PI * u();
            let r = (1.0 - z * z).sqrt();
            let direction = Vec3::new(r * phi.cos(), r * phi.sin(), z);
            if i % 5 == 4 {
                let triangle = (u() * mesh.triangles.len() as Real) as u32;
                let [a, b, c] = mesh.corners(triangle.min(mesh.triangles.len() as u32 - 1));
                let (s, t) = (u().sqrt(), u());
                let point = a * (1.0 - s) + b * (s * (1.0 - t)) + c * (s * t);
                let normal = (b - a).cross(c - a).normalize();
                return Ray::new(point + normal * (1e-4 * radius), direction);
            }
            let origin = centre + radius * direction;
            let target = mesh.bounds.min + size * Vec3::new(u(), u(), u());
            Ray::new(origin, target - origin)
        })
        .collect()
}

fn hits(mesh: &Mesh, rays: &[Ray]) -> Vec<Option<MeshHit>> {
    rays.par_iter()
        .map(|ray| mesh.intersect(ray, Real::INFINITY))
        .collect()
}

/// How many of `rays` the mesh's any-hit test answers otherwise than `nearest`,
/// their nearest hits, say.
#[cfg(feature = "beyond")]
fn any_hit_disagreements(mesh: &Mesh, rays: &[Ray], nearest: &[Option<MeshHit>]) -> usize {
    (rays.iter().zip(nearest))
        .filter(|(ray, hit)| mesh.occluded(ray, Real::INFINITY) != hit.is_some())
        .count()
}

/// Brute force, bounding box and (from session 6) BVH find the same triangle at the
/// same distance for every ray, and so do the fast engine's hierarchies beyond the
/// course.
fn searches_agree(obj: &str, count: u64) {
    let data = read_obj(&asset(obj)).unwrap();
    let mut mesh = unplaced(&data);
    let rays = rays_at(&mesh, count);
    let brute = hits(&mesh, &rays);
    let hit_count = brute.iter().flatten().count();
    assert!(
        hit_count as u64 > count / 4,
        "{hit_count} rays hit: the test is not vacuous"
    );
    mesh.search = Arc::new(raycourse::acceleration::BoundingBox);
    assert!(
        hits(&mesh, &rays) == brute,
        "bounding box differs from brute force"
    );
    #[cfg(feature = "s6")]
    {
        mesh.search = Arc::new(raycourse::acceleration::Bvh::build(&mesh));
        let bvh = hits(&mesh, &rays);
        let differing = bvh.iter().zip(&brute).filter(|(a, b)| a != b).count();
        assert_eq!(differing, 0, "BVH differs from brute force");
    }
    #[cfg(feature = "beyond")]
    {
        mesh.search = Arc::new(raycourse::fast::hierarchy::sah::build(&mesh, 8, 1));
        let sah = hits(&mesh, &rays);
        let differing = sah.iter().zip(&brute).filter(|(a, b)| a != b).count();
        assert_eq!(differing, 0, "SAH BVH differs from brute force");
        use raycourse::fast::lanes::Lanes;
        let lanes = [1, 4, 8, 16].map(|leaf| (leaf, Lanes::fastest()));
        for (leaf, lanes) in lanes.into_iter().chain([(8, Lanes::Portable)]) {
            let fast = raycourse::fast::FastBvh::build(&mesh, leaf).with_lanes(lanes);
            mesh.search = Arc::new(fast);
            let fast = hits(&mesh, &rays);
            let differing = fast.iter().zip(&brute).filter(|(a, b)| a != b).count();
            assert_eq!(
                differing, 0,
                "fast BVH (leaves of {leaf}, {lanes:?}) differs from brute force"
            );
            assert_eq!(
                any_hit_disagreements(&mesh, &rays, &brute),
                0,
                "fast BVH's any-hit test differs from the closest hit"
            );
        }
    }
}

#[test]
fn searches_agree_on_spot() {
    searches_agree("spot/spot.obj", 100_000);
}

/// The ogre has seven times Spot's triangles (39,856): brute force over 25,000 rays
/// costs about what Spot's 100,000 cost, and a fifth of them still leave its surface
/// as bounces do.
#[test]
fn searches_agree_on_the_ogre() {
    searches_agree("ogre/ogre.obj", 25_000);
}

/// With the course's triangle test, which the fast BVH's single-precision pre-test
/// does not serve, the fast BVH still finds brute force's hits; and so do session
/// 5's searches on lanes, with and without the bounding box, on either kind of
/// lanes, their any-hit test too.
#[cfg(feature = "beyond")]
#[test]
fn the_fast_searches_agree_with_the_course_triangle_test() {
    use raycourse::fast::lanes::Lanes;
    let data = read_obj(&asset("spot/spot.obj")).unwrap();
    let mut mesh = unplaced(&data);
    mesh.triangle_test = raycourse::geometry::TriangleTest::MollerTrumbore;
    let rays = rays_at(&mesh, 10_000);
    let brute = hits(&mesh, &rays);
    assert!(
        brute.iter().flatten().count() > 2_500,
        "the test is not vacuous"
    );
    mesh.search = Arc::new(raycourse::fast::FastBvh::build(&mesh, 8));
    assert!(
        hits(&mesh, &rays) == brute,
        "fast BVH differs from brute force"
    );
    for (boxed, lanes) in [
        (false, Lanes::fastest()),
        (true, Lanes::fastest()),
        (false, Lanes::Portable),
    ] {
        let fast = raycourse::fast::FastBruteForce::build(&mesh, boxed).unwrap();
        mesh.search = Arc::new(fast.with_lanes(lanes));
        let name = format!("{} on {lanes:?}", mesh.search.name());
        assert!(
            hits(&mesh, &rays) == brute,
            "{name} differs from brute force"
        );
        assert_eq!(
            any_hit_disagreements(&mesh, &rays, &brute),
            0,
            "{name}'s any-hit test differs from the closest hit"
        );
    }
}

/// A scene in a temporary folder with one mesh entry and the given files.
fn scene_error(mesh_keys: &str, files: &[(&str, &[u8])]) -> String {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in files {
        std::fs::write(dir.path().join(name), bytes).unwrap();
    }
    let text = format!(
        "[render]\nwidth = 8\nheight = 8\n[camera]\nposition = [0, 0, 5]\nfov = 60\n\
         [[meshes]]\n{mesh_keys}\n"
    );
    let path = dir.path().join("scene.toml");
    let err = parse_scene(&text, &path, &Overrides::default()).unwrap_err();
    err.to_string()
        .replace(&dir.path().display().to_string(), "DIR")
}

const TRIANGLE: &[u8] = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";

#[test]
fn a_missing_obj_file_is_named() {
    assert_eq!(
        scene_error("obj = \"nowhere.obj\"", &[]),
        "DIR/nowhere.obj: cannot load the mesh: No such file or directory (os error 2) (referred to by \
         DIR/scene.toml)"
    );
}

#[test]
fn an_out_of_range_index_is_refused() {
    assert_eq!(
        scene_error(
            "obj = \"bad.obj\"",
            &[("bad.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")]
        ),
        "DIR/bad.obj: cannot load the mesh: line 4: vertex index 7 is out of range \
         (3 read so far) (referred to by DIR/scene.toml)"
    );
}

#[test]
fn a_file_without_triangles_is_refused() {
    assert_eq!(
        scene_error("obj = \"empty.obj\"", &[("empty.obj", b"v 0 0 0\n")]),
        "DIR/empty.obj: cannot load the mesh: no triangles (referred to by DIR/scene.toml)"
    );
}

#[cfg(feature = "s7")]
#[test]
fn a_missing_or_broken_texture_is_named() {
    assert_eq!(
        scene_error(
            "obj = \"t.obj\"\ntexture = \"missing.png\"",
            &[("t.obj", TRIANGLE)]
        ),
        "DIR/missing.png: cannot read the texture: No such file or directory (os error 2) \
         (referred to by DIR/scene.toml)"
    );
    let err = scene_error(
        "obj = \"t.obj\"\ntexture = \"fake.png\"",
        &[("t.obj", TRIANGLE), ("fake.png", b"not a picture")],
    );
    assert!(
        err.starts_with("DIR/fake.png: cannot read the texture: "),
        "{err}"
    );
}

#[cfg(not(feature = "s7"))]
#[test]
fn textures_need_session_seven() {
    assert_eq!(
        scene_error("obj = \"t.obj\"\ntextured = true", &[("t.obj", TRIANGLE)]),
        format!(
            "DIR/scene.toml: key `meshes[0].textured`: textures {}",
            raycourse::scene_file::features::comes_with(7)
        )
    );
}

#[cfg(feature = "s6")]
#[test]
fn missing_normals_fall_back_to_the_geometric_normal() {
    let data = read_obj_text(TRIANGLE);
    assert!(data.normals.is_empty());
    let mesh = unplaced(&data);
    let ray = Ray::new(Vec3::new(0.2, 0.2, 1.0), -Vec3::Z);
    let hit = mesh.intersect(&ray, Real::INFINITY).unwrap();
    let weights = [1.0 / 3.0; 3];
    assert_eq!(mesh.smooth_normal(hit.triangle, weights, Vec3::Z), Vec3::Z);
    let record = mesh.hit_record(&ray, hit, 0);
    assert_eq!(record.normal, Vec3::Z);
}

#[cfg(feature = "s6")]
fn read_obj_text(text: &[u8]) -> ObjData {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("m.obj");
    std::fs::write(&path, text).unwrap();
    read_obj(&path).unwrap()
}

/// The `mesh` stage (and, from session 6, the `bvh` stage) rendered at the same
/// small settings: the searches differ only in time, so the bytes are equal.
#[test]
fn mesh_stages_render_the_same_bytes_whatever_the_search() {
    use raycourse::{encode_png, find_stage, render};

    let overrides = Overrides::sized(40, 40, 1);
    let png = |session: u32, name: &str| {
        let scene = find_stage(session, name)
            .unwrap()
            .scene(&overrides)
            .unwrap();
        encode_png(&render(&scene).film, scene.settings.gamma)
    };
    let brute = png(5, "mesh");
    assert_eq!(png(5, "mesh-bbox"), brute, "bounding box");
    #[cfg(feature = "s6")]
    {
        assert_eq!(png(6, "bvh"), brute, "BVH");
    }
    #[cfg(feature = "beyond")]
    {
        // The fast engine's hierarchy, with the BVH stage's watertight triangles.
        use raycourse::scene_file::beyond::{BeyondOverrides, stage_with_beyond};
        let stage = find_stage(6, "bvh").unwrap();
        let fast = BeyondOverrides {
            fast: true,
            ..BeyondOverrides::default()
        };
        let (scene, beyond) = stage_with_beyond(stage, &overrides, &fast).unwrap();
        assert_eq!(scene.meshes[0].search.name(), "fast");
        let fast = raycourse::engines::render(&scene, &beyond).film;
        let bvh = stage.scene(&overrides).unwrap();
        let image = |film, scene: &raycourse::Scene| encode_png(film, scene.settings.gamma);
        assert_eq!(
            image(&fast, &scene),
            image(&render(&bvh).film, &bvh),
            "fast BVH"
        );
    }
}

#[cfg(feature = "s7")]
#[test]
fn a_mesh_without_texture_coordinates_is_not_textured() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("flat.obj"),
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let text = "[render]\nwidth = 8\nheight = 8\n[camera]\nposition = [0, 0, 5]\nfov = 60\n\
                [[meshes]]\nobj = \"flat.obj\"\ntexture = \"any.png\"\nalbedo = [0.5, 0.5, 0.5]\n";
    let scene = parse_scene(text, &dir.path().join("scene.toml"), &Overrides::default()).unwrap();
    assert_eq!(
        scene.meshes[0].albedo,
        raycourse::meshes::MeshAlbedo::Constant(raycourse::maths::Colour::splat(0.5))
    );
}

/// tobj's own words would reach the user here ("read error", "color parse error",
/// or nothing at all for a face of two corners); the loader answers in the words of
/// the OBJ format, with the line.
#[test]
fn malformed_obj_files_are_told_in_the_formats_words() {
    let long = format!("v{}\nf 1 1 1\n", " 0".repeat(3_000_000));
    assert_eq!(
        scene_error("obj = \"long.obj\"", &[("long.obj", long.as_bytes())]),
        "DIR/long.obj: cannot load the mesh: line 1: a vertex has 3 coordinates, found 3000000 \
         (referred to by DIR/scene.toml)"
    );
    let two = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n";
    assert_eq!(
        scene_error("obj = \"two.obj\"", &[("two.obj", two)]),
        "DIR/two.obj: cannot load the mesh: line 4: a face has 2 corners; it needs at least 3 \
         (referred to by DIR/scene.toml)"
    );
    let binary = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR";
    assert_eq!(
        scene_error("obj = \"picture.obj\"", &[("picture.obj", binary)]),
        "DIR/picture.obj: cannot load the mesh: not a text OBJ file (referred to by \
         DIR/scene.toml)"
    );
}

/// A scene made ten times larger is the same picture but for rounding: its meshes
/// and their hierarchies are built again at the new size, the fast one included.
#[cfg(feature = "beyond")]
#[test]
fn a_scaled_scene_with_the_fast_hierarchy_renders_like_the_unscaled_one() {
    use raycourse::scene_file::beyond::{BeyondOverrides, parse_with_beyond};
    use raycourse::studies::scale::scaled;
    use raycourse::{Disk, encode_png, find_stage};

    let stage = find_stage(6, "bvh").unwrap();
    let bvh = stage.source;
    let overrides = Overrides::sized(48, 48, 1);
    let fast = BeyondOverrides {
        fast: true,
        ..BeyondOverrides::default()
    };
    let pixels = |text: &str| {
        let path = stage.file();
        let (scene, beyond) = parse_with_beyond(text, &path, &overrides, &fast, &Disk).unwrap();
        assert_eq!(scene.meshes[0].search.name(), "fast");
        let film = raycourse::engines::render(&scene, &beyond).film;
        let png = encode_png(&film, scene.settings.gamma);
        image::load_from_memory(&png).unwrap().to_rgb8().into_raw()
    };
    let small = pixels(bvh);
    let large = pixels(&scaled(bvh, 10.0, Vec3::new(3.0, -2.0, 5.0)).unwrap());
    let differing = small
        .chunks_exact(3)
        .zip(large.chunks_exact(3))
        .filter(|(a, b)| a.iter().zip(*b).any(|(x, y)| x.abs_diff(*y) > 2))
        .count();
    assert!(differing <= 48 * 48 / 50, "{differing} pixels differ");
}
