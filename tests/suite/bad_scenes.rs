//! Scene files with mistakes: each gives one line naming the file, the key (and
//! line where TOML knows it) and what was expected.

use std::path::Path;

use raycourse::scene_file::SESSION;
use raycourse::scene_file::features::comes_with;
use raycourse::{Overrides, SceneError, load_scene, parse_scene};

const GOOD: &str = r#"
[render]
width = 64
height = 48

[camera]
position = [0, 0, 55]
fov = 60

[light]
position = [-10, 20, 40]
intensity = 2e7

[[spheres]]
centre = [0, 0, 0]
radius = 10
material = { diffuse = [1, 1, 1] }
"#;

/// The error for `GOOD` with the line starting with `key =` replaced by `line`.
fn error_with(key: &str, line: &str) -> String {
    let text: String = GOOD
        .lines()
        .map(|l| if l.starts_with(key) { line } else { l })
        .collect::<Vec<_>>()
        .join("\n");
    assert_ne!(text.trim(), GOOD.trim(), "the case changes the file");
    let err = parse_scene(&text, Path::new("room.toml"), &Overrides::default())
        .expect_err("the scene is invalid");
    let message = err.to_string();
    assert!(!message.contains('\n'), "one line: {message}");
    message
}

#[test]
fn the_good_scene_loads() {
    let scene = parse_scene(GOOD, Path::new("room.toml"), &Overrides::default()).unwrap();
    assert_eq!((scene.camera.width, scene.camera.height), (64, 48));
    assert_eq!(scene.spheres.len(), 1);
    assert_eq!(scene.settings.bounces, 5, "default bounce limit");
}

#[test]
fn unknown_key() {
    assert_eq!(
        error_with("radius", "radis = 10"),
        "room.toml:16:1: key `spheres[0].radis`: unknown field `radis`, expected one of \
         `centre`, `radius`, `material`, `emission`"
    );
}

#[test]
fn wrong_type() {
    assert_eq!(
        error_with("width", "width = \"wide\""),
        "room.toml:3:9: key `render.width`: invalid type: string \"wide\", expected a nonzero u32"
    );
}

#[test]
fn negative_radius() {
    assert_eq!(
        error_with("radius", "radius = -10"),
        "room.toml:16:10: key `spheres[0].radius`: expected a number greater than 0, found -10"
    );
}

#[test]
fn zero_radius() {
    assert_eq!(
        error_with("radius", "radius = 0"),
        "room.toml:16:10: key `spheres[0].radius`: expected a number greater than 0, found 0"
    );
}

#[test]
fn nan_number() {
    assert_eq!(
        error_with("intensity", "intensity = nan"),
        "room.toml:12:13: key `light.intensity`: expected a finite number, found NaN"
    );
}

#[test]
fn infinite_coordinate() {
    assert_eq!(
        error_with("centre", "centre = [0, inf, 0]"),
        "room.toml:15:10: key `spheres[0].centre`: expected a finite number, found inf"
    );
}

#[test]
fn zero_width_and_height() {
    assert_eq!(
        error_with("width", "width = 0"),
        "room.toml:3:9: key `render.width`: invalid value: integer `0`, expected a nonzero u32"
    );
    assert_eq!(
        error_with("height", "height = 0"),
        "room.toml:4:10: key `render.height`: invalid value: integer `0`, expected a nonzero u32"
    );
}

#[test]
fn albedo_above_one() {
    assert_eq!(
        error_with("material", "material = { diffuse = [1, 2, 1] }"),
        "room.toml:17:12: key `spheres[0].material.diffuse`: expected an albedo between 0 and 1, \
         found 2"
    );
}

/// An unknown material is answered with the materials this build knows.
#[test]
fn unknown_material() {
    let known = match SESSION {
        1 => "expected `diffuse`",
        2 | 3 => "expected one of `diffuse`, `mirror`, `glass`",
        _ => "expected one of `diffuse`, `mirror`, `glass`, `fresnel-glass`",
    };
    assert_eq!(
        error_with("material", "material = \"chrome\""),
        format!("room.toml:17:12: key `spheres[0].material`: unknown variant `chrome`, {known}")
    );
}

#[test]
fn missing_key() {
    assert_eq!(
        error_with("fov", "# no field of view"),
        "room.toml:6:1: key `camera`: missing field `fov`"
    );
}

#[test]
fn syntax_error() {
    assert_eq!(
        error_with("width", "width = = 3"),
        "room.toml:3:9: extra `=`, expected nothing"
    );
}

#[test]
fn image_too_large() {
    assert_eq!(
        error_with("width", "width = 10000000"),
        "room.toml: key `render.width`: 10000000 x 48 is 480000000 pixels; at most 67108864 \
         are allowed"
    );
}

#[test]
fn missing_file() {
    let err = load_scene(Path::new("no/such/scene.toml"), &Overrides::default()).unwrap_err();
    assert!(matches!(err, SceneError::Read { .. }));
    assert_eq!(
        err.to_string(),
        "no/such/scene.toml: cannot read the scene file: No such file or directory (os error 2)"
    );
}

#[test]
fn later_session_materials_name_their_feature() {
    let text = GOOD.replace("{ diffuse = [1, 1, 1] }", "\"mirror\"");
    let result = parse_scene(&text, Path::new("room.toml"), &Overrides::default());
    if SESSION >= 2 {
        assert!(result.is_ok());
    } else {
        assert_eq!(
            result.unwrap_err().to_string(),
            format!(
                "room.toml: key `spheres[0].material`: a mirror material {}",
                comes_with(2)
            )
        );
    }
}

#[test]
fn later_session_settings_name_their_feature() {
    let text = GOOD.replace("height = 48", "height = 48\nshadows = true");
    let result = parse_scene(&text, Path::new("room.toml"), &Overrides::default());
    if SESSION >= 2 {
        assert!(result.unwrap().settings.shadows);
    } else {
        assert_eq!(
            result.unwrap_err().to_string(),
            format!(
                "room.toml: key `render.shadows`: shadow rays {}",
                comes_with(2)
            )
        );
    }
}

#[test]
fn light_sampling_needs_a_sphere_light() {
    let text = GOOD.replace("height = 48", "height = 48\nlight_sampling = true");
    let err = parse_scene(&text, Path::new("room.toml"), &Overrides::default()).unwrap_err();
    let expected = if SESSION >= 4 {
        "room.toml: key `render.light_sampling`: light sampling needs a sphere light: give \
         [light] a radius"
            .to_owned()
    } else {
        format!(
            "room.toml: key `render.light_sampling`: light sampling {}",
            comes_with(4)
        )
    };
    assert_eq!(err.to_string(), expected);
}

#[test]
fn a_sphere_light_needs_session_four_and_no_shadow_rays() {
    let text = GOOD.replace("intensity = 2e7", "intensity = 2e7\nradius = 5");
    let result = parse_scene(&text, Path::new("room.toml"), &Overrides::default());
    if SESSION >= 4 {
        assert_eq!(
            result.unwrap().spheres.len(),
            2,
            "the light's body is a sphere"
        );
        let text = text.replace("height = 48", "height = 48\nshadows = true");
        let err = parse_scene(&text, Path::new("room.toml"), &Overrides::default()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "room.toml: key `render.shadows`: shadow rays are for a point light; a sphere \
             light's shadows come from light_sampling or indirect rays"
        );
    } else {
        assert_eq!(
            result.unwrap_err().to_string(),
            format!(
                "room.toml: key `light.radius`: a sphere light {}",
                comes_with(4)
            )
        );
    }
}

#[test]
fn antialiasing_needs_session_three() {
    let text = GOOD.replace("fov = 60", "fov = 60\nantialiasing = 0.5");
    let result = parse_scene(&text, Path::new("room.toml"), &Overrides::default());
    if SESSION >= 3 {
        assert!(result.is_ok());
    } else {
        assert_eq!(
            result.unwrap_err().to_string(),
            format!(
                "room.toml: key `camera.antialiasing`: antialiasing {}",
                comes_with(3)
            )
        );
    }
}

#[test]
fn russian_roulette_survival_is_a_probability() {
    let text = GOOD.replace("height = 48", "height = 48\nrussian_roulette = 1.5");
    let err = parse_scene(&text, Path::new("room.toml"), &Overrides::default()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "room.toml:5:20: key `render.russian_roulette`: expected a probability above 0 and at \
         most 1, found 1.5"
    );
}

#[cfg(feature = "beyond")]
#[test]
fn samplers_are_named_and_noise_is_positive() {
    use raycourse::scene_file::beyond::{BeyondOverrides, parse_with_beyond};
    let error = |line: &str, beyond: &BeyondOverrides| {
        let text = GOOD.replace("height = 48", &format!("height = 48\n{line}"));
        let path = Path::new("room.toml");
        parse_with_beyond(&text, path, &Overrides::default(), beyond, &raycourse::Disk).map(|_| ())
    };
    let halton = error("sampler = \"halton\"", &BeyondOverrides::default()).unwrap_err();
    assert_eq!(
        halton.to_string(),
        "room.toml:5:11: key `render.sampler`: unknown variant `halton`, expected one of \
         `independent`, `stratified`, `sobol`"
    );
    let negative = error("noise = -0.1", &BeyondOverrides::default()).unwrap_err();
    assert!(
        negative
            .to_string()
            .starts_with("room.toml:5:9: key `render.noise`: expected a number greater than 0"),
        "{negative}"
    );
    let from_the_command_line = BeyondOverrides {
        noise: Some(0.0),
        ..BeyondOverrides::default()
    };
    assert!(
        error("", &from_the_command_line)
            .unwrap_err()
            .to_string()
            .starts_with("room.toml: key `render.noise`: expected a number greater than 0"),
    );
    assert!(error("sampler = \"sobol\"", &BeyondOverrides::default()).is_ok());
}
