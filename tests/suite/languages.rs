//! The commands in the reader's language: `--lang fr`, or a French environment,
//! gives `probe`'s path, a render's closing line and a scene file's errors in
//! French; English otherwise, as it always read.

use crate::common::{run, run_in_locale, text};

/// The no-break space that French sets before `:` and `;`.
const NBSP: char = '\u{a0}';

#[test]
fn probe_speaks_french_when_asked_and_english_otherwise() {
    let dir = tempfile::tempdir().unwrap();
    let french = run(
        &["probe", "glass", "128", "100", "--lang", "fr"],
        dir.path(),
    );
    assert!(french.status.success(), "{}", text(&french.stderr));
    let french = text(&french.stdout);
    assert!(
        french.starts_with("pixel (x 128, y 100), échantillon 0 sur 1"),
        "{french}"
    );
    assert!(
        french.contains(&format!("niveau 0{NBSP}: le rayon de la caméra")),
        "{french}"
    );
    assert!(
        french.contains("  rayon    O = (0,0000\u{a0}; 0,0000\u{a0}; 55,0000)"),
        "{french}"
    );
    assert!(french.contains("moyenne de 1 échantillon ("), "{french}");
    assert!(french.contains("-> gamma 2,2 ->"), "{french}");
    let end = format!("fin      pas d'éclairage indirect dans cette scène{NBSP}: le chemin");
    assert!(french.contains(&end), "{french}");
    let from_locale = run_in_locale(&["probe", "glass", "128", "100"], dir.path(), "fr_FR.UTF-8");
    assert_eq!(text(&from_locale.stdout), french);
    let english = text(&run(&["probe", "glass", "128", "100"], dir.path()).stdout);
    assert!(
        english.starts_with("pixel (x 128, y 100), sample 0 of 1 (from 0)"),
        "{english}"
    );
    assert!(english.contains("level 0: the camera ray"), "{english}");
    assert!(
        english.contains("  ray      O = (0.0000, 0.0000, 55.0000)"),
        "{english}"
    );
    assert!(english.contains("mean of 1 sample ("), "{english}");
}

#[test]
fn a_bad_scene_file_is_refused_in_french_naming_its_file_line_and_key() {
    let dir = tempfile::tempdir().unwrap();
    let scene = "[camera]\nposition = [0, 0, 0]\nfov = 60\n\n[render]\nwidht = 32\n";
    std::fs::write(dir.path().join("room.toml"), scene).unwrap();
    let french = run(&["render", "room.toml", "--lang", "fr"], dir.path());
    assert_eq!(french.status.code(), Some(2));
    let stderr = text(&french.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    let expected = format!(
        "erreur{NBSP}: room.toml:6:1: clé `render.widht`{NBSP}: champ inconnu `widht`, attendu l'un de `width`"
    );
    assert!(stderr.starts_with(&expected), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    let english = text(&run(&["render", "room.toml"], dir.path()).stderr);
    let expected =
        "error: room.toml:6:1: key `render.widht`: unknown field `widht`, expected one of `width`";
    assert!(english.starts_with(expected), "{english}");
}

#[test]
fn a_rule_of_the_scene_file_is_said_in_french() {
    let dir = tempfile::tempdir().unwrap();
    let size = ["--width", "10000", "--height", "10000", "--lang", "fr"];
    let out = run(&[&["s1", "white-disk"][..], &size].concat(), dir.path());
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(stderr.contains(&format!("clé `render.width`{NBSP}: 10000{NBSP}×{NBSP}10000 font 100\u{202f}000\u{202f}000 pixels")), "{stderr}");
}

#[test]
fn a_french_render_closes_with_a_french_line() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["s1", "white-disk", "--width", "32", "--height", "24"];
    let options = ["--out", "disk.png", "-q", "--lang", "fr"];
    let out = run(&[&args[..], &options].concat(), dir.path());
    assert!(out.status.success(), "{}", text(&out.stderr));
    let line = text(&out.stdout);
    let start = format!("white-disk{NBSP}: 32{NBSP}×{NBSP}24, 1 échantillon par pixel, ");
    assert!(line.starts_with(&start), "{line}");
    assert!(
        line.contains(" 768 rayons, ") && line.contains(&format!("{NBSP}Mrayons/s, ")),
        "{line}"
    );
    assert!(line.trim_end().ends_with("-> disk.png"), "{line}");
    let seconds = line.split(", ").find(|p| p.ends_with(&format!("{NBSP}s")));
    let seconds = seconds.unwrap_or_else(|| panic!("no seconds: {line}"));
    assert!(seconds.contains(','), "a decimal comma: {line}");
}

/// The English closing line is the one the README quotes, word for word: only
/// the time, the speed and the threads change from one run to the next.
#[test]
fn an_english_render_closes_with_the_readme_s_line() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["s1", "white-disk", "--width", "32", "--height", "24"];
    let out = run(
        &[&args[..], &["--out", "disk.png", "-q"]].concat(),
        dir.path(),
    );
    let line = text(&out.stdout);
    let parts: Vec<&str> = line.trim_end().split(", ").collect();
    let [settings, spp, bounces, seconds, rays, speed, threads] = parts[..] else {
        panic!("seven parts: {line}");
    };
    assert_eq!(
        [settings, spp, bounces],
        ["white-disk: 32x24", "1 spp", "5 bounces"]
    );
    assert_eq!(rays, "768 rays");
    let number = |text: &str, unit: &str| {
        let figure = text
            .strip_suffix(unit)
            .unwrap_or_else(|| panic!("{text}: {line}"));
        assert!(figure.parse::<f64>().is_ok(), "{text}: {line}");
        figure.split_once('.').map_or(0, |(_, d)| d.len())
    };
    assert_eq!(number(seconds, " s"), 3);
    assert_eq!(number(speed, " Mrays/s"), 2);
    let threads = threads.strip_suffix(" threads -> disk.png").expect(&line);
    assert!(threads.parse::<u32>().is_ok(), "{line}");
}

#[test]
fn probe_refuses_a_pixel_outside_the_image_in_french() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["probe", "glass", "9999", "0", "--lang", "fr"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    let expected = format!("erreur{NBSP}: le pixel (9999, 0) est hors de l'image, qui fait 512");
    assert!(stderr.starts_with(&expected), "{stderr}");
    let english = text(&run(&["probe", "glass", "9999", "0"], dir.path()).stderr);
    assert!(
        english.starts_with("error: pixel (9999, 0) is outside the image, which is 512x512"),
        "{english}"
    );
}

#[test]
fn an_image_of_what_the_renderer_sees_closes_in_french() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["s1", "white-disk", "--width", "16", "--height", "16", "-q"];
    let french = run(
        &[&args[..], &["--aov", "depth", "--lang", "fr"]].concat(),
        dir.path(),
    );
    assert!(french.status.success(), "{}", text(&french.stderr));
    let line = text(&french.stdout);
    let start = format!("white-disk{NBSP}: image de la profondeur, de ");
    assert!(
        line.starts_with(&start) && line.contains("(violet) à"),
        "{line}"
    );
    let english = text(&run(&[&args[..], &["--aov", "depth"]].concat(), dir.path()).stdout);
    assert!(
        english.starts_with("white-disk: depth image, from "),
        "{english}"
    );
}

/// `animate` is a render command: `--lang fr` gives its closing line in French.
#[cfg(feature = "s7")]
#[test]
fn an_animation_closes_in_french() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "animate", "camera", "--frames", "2", "--width", "8", "--height", "8",
    ];
    let options = ["--spp", "1", "-q", "--lang", "fr"];
    let out = run(&[&args[..], &options].concat(), dir.path());
    assert!(out.status.success(), "{}", text(&out.stderr));
    let line = text(&out.stdout);
    let start = format!("camera{NBSP}: 2 images, plongée de 0 à 30{NBSP}degrés, ");
    assert!(line.starts_with(&start), "{line}");
}

/// What a render command refuses before it renders is said in French too.
#[test]
fn too_many_threads_are_refused_in_french() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["s1", "shading", "--threads", "100000", "-q", "--lang", "fr"];
    let out = run(&args, dir.path());
    assert_eq!(out.status.code(), Some(2));
    let expected = format!(
        "erreur{NBSP}: --threads 100000{NBSP}: 1024 au plus (un par cœur est le plus rapide)\n"
    );
    assert_eq!(text(&out.stderr), expected);
}
