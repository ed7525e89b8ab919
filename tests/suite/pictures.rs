//! What the stages show, checked on numbers rather than on snapshots: the disk's
//! size, the light's direction, the shadow, the mirror's reflection.

use raycourse::maths::Real;
use raycourse::{Film, Overrides, Scene, find_stage, render};

fn scene(session: u32, name: &str, size: u32) -> Scene {
    let overrides = Overrides::sized(size, size, 0);
    find_stage(session, name)
        .expect("stage of this build")
        .scene(&overrides)
        .unwrap()
}

fn film(scene: &Scene) -> Film {
    render(scene).film
}

fn luminance(film: &Film, row: u32, column: u32) -> Real {
    let c = film.pixels[(row * film.width + column) as usize];
    (c.x + c.y + c.z) / 3.0
}

#[test]
fn white_disk_covers_the_sphere_s_angular_size() {
    // From 55 units, a sphere of radius 10 subtends a half-angle asin(10/55); on a
    // 512-pixel image spanning 60 degrees, its disk has a radius of
    // 256 tan(asin(10/55)) / tan(30 deg) pixels and covers pi r^2 pixels.
    let s = scene(1, "white-disk", 512);
    let f = film(&s);
    let white = f.pixels.iter().filter(|c| c.x == 255.0).count() as Real;
    let black = f.pixels.iter().filter(|c| c.x == 0.0).count() as Real;
    assert_eq!(white + black, (512 * 512) as Real, "only white and black");
    let half_angle = (10.0 as Real / 55.0).asin();
    let r = 256.0 * half_angle.tan() / (30.0 as Real).to_radians().tan();
    let expected = raycourse::maths::PI * r * r;
    assert!(
        (white - expected).abs() < 2.0 * raycourse::maths::PI * r,
        "{white} white pixels, expected about {expected}"
    );
}

#[test]
fn shading_is_brightest_towards_the_light() {
    // The light is up and to the left: the upper-left of the disk is lit, the
    // lower-right is dark.
    let f = film(&scene(1, "shading", 128));
    let upper_left = luminance(&f, 50, 50);
    let lower_right = luminance(&f, 76, 76);
    assert!(
        upper_left > 4.0 * lower_right,
        "{upper_left} vs {lower_right}"
    );
    assert_eq!(luminance(&f, 2, 2), 0.0, "black background");
}

#[test]
fn spheres_stage_sees_the_room() {
    let f = film(&scene(1, "spheres", 128));
    let bottom = f.pixels[(127 * 128 + 64) as usize];
    assert!(
        bottom.z > 0.0 && bottom.x == 0.0 && bottom.y == 0.0,
        "blue floor: {bottom}"
    );
    assert!(f.pixels.iter().all(|c| c.max_element() > 0.0 || c.z == 0.0));
}

#[cfg(feature = "s2")]
#[test]
fn shadows_darken_the_floor_below_the_sphere() {
    // Find the floor pixels straight below the sphere's contact point on the side
    // away from the light: lit without shadows, black with.
    let lit = film(&scene(2, "gamma", 128));
    let shadowed = film(&scene(2, "shadows", 128));
    let darkened = lit
        .pixels
        .iter()
        .zip(&shadowed.pixels)
        .filter(|(a, b)| a.z > 0.0 && b.z == 0.0)
        .count();
    assert!(darkened > 50, "{darkened} floor pixels fell into shadow");
    let brightened = lit
        .pixels
        .iter()
        .zip(&shadowed.pixels)
        .filter(|(a, b)| b.max_element() > a.max_element())
        .count();
    assert_eq!(brightened, 0, "a shadow ray never adds light");
}

/// The `shadows` stage at 128 x 128 with `shadow_offset = epsilon` in its file.
#[cfg(feature = "s2")]
fn shadows_offset_by(epsilon: &str) -> Film {
    let stage = find_stage(2, "shadows").unwrap();
    let text = stage.source.replace(
        "shadows = true",
        &format!("shadows = true\nshadow_offset = {epsilon}"),
    );
    let overrides = Overrides::sized(128, 128, 0);
    film(&raycourse::parse_scene(&text, &stage.file(), &overrides).unwrap())
}

#[cfg(feature = "s2")]
#[test]
fn a_zero_shadow_offset_shows_acne_and_a_small_one_does_not() {
    // At epsilon = 0 a shadow ray starts on its own surface, which it meets again
    // at t of about 0 for about half the points, by rounding: black speckles on
    // lit surfaces. A small epsilon clears the rounding error: the same image as
    // the crate's offset but on a few shadow-edge pixels.
    let robust = film(&scene(2, "shadows", 128));
    let lit = robust
        .pixels
        .iter()
        .filter(|c| c.max_element() > 0.0)
        .count();
    let blackened = |film: &Film| {
        let pairs = robust.pixels.iter().zip(&film.pixels);
        pairs
            .filter(|(a, b)| a.max_element() > 0.0 && b.max_element() == 0.0)
            .count()
    };
    let acne = blackened(&shadows_offset_by("0"));
    assert!(
        acne * 5 > lit,
        "{acne} of {lit} lit pixels turned black at epsilon 0"
    );
    let small = blackened(&shadows_offset_by("0.001"));
    assert!(
        small * 200 < lit,
        "{small} of {lit} lit pixels turned black at epsilon 0.001"
    );
}

#[cfg(feature = "s2")]
#[test]
fn mirror_centre_reflects_the_wall_behind_the_camera() {
    // The central ray meets the mirror head-on and comes straight back, past the
    // eye, to the yellow wall at z = 60.
    let f = film(&scene(2, "mirror", 128));
    let c = f.pixels[(64 * 128 + 64) as usize];
    assert!(c.x > 0.0 && c.y > 0.0 && c.z == 0.0, "yellow: {c}");
}

#[cfg(feature = "s2")]
#[test]
fn glass_centre_looks_straight_through() {
    // At normal incidence a ray passes undeviated and sees the cyan back wall, as
    // bright as without the sphere up to the sphere's own shadow-free path.
    let glass = film(&scene(2, "glass", 128));
    let c = glass.pixels[(64 * 128 + 64) as usize];
    assert!(c.x == 0.0 && c.y > 0.0 && c.z > 0.0, "cyan: {c}");
}
