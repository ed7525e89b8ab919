//! The `raycourse` command as a student runs it.

use std::path::Path;

use crate::common::{run, text};
use raycourse::stages;

#[test]
fn list_shows_exactly_the_stages_of_this_build() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["list"], dir.path());
    assert!(out.status.success());
    let stdout = text(&out.stdout);
    let listed: Vec<&str> = stdout
        .lines()
        .skip(1)
        .map(|l| l.split_whitespace().nth(2).unwrap())
        .collect();
    let expected: Vec<&str> = stages().map(|s| s.name).collect();
    assert_eq!(listed, expected);
    assert!(
        stdout
            .lines()
            .skip(1)
            .all(|l| l.contains("512x512") || l.contains("128x128"))
    );
}

/// The help begins with what the program is, not with the render options' own
/// description, and says what it does without a command.
#[test]
fn the_help_says_what_the_program_does() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["--help"], dir.path());
    assert!(out.status.success());
    let stdout = text(&out.stdout);
    let first = stdout.lines().next().unwrap();
    assert!(
        first.starts_with("Ray tracing, one course session at a time."),
        "{first}"
    );
    assert!(
        first.contains("With no command, renders the last stage"),
        "{first}"
    );
}

/// `animate` writes a GIF by default, and its help says so rather than the render
/// options' PNG.
#[cfg(feature = "s7")]
#[test]
fn animate_s_help_gives_its_gif() {
    let dir = tempfile::tempdir().unwrap();
    let help = text(&run(&["animate", "--help"], dir.path()).stdout);
    assert!(
        help.contains("Output GIF (default: out/<stage>.gif)"),
        "{help}"
    );
    assert!(!help.contains("Output PNG"), "{help}");
}

#[test]
fn session_one_has_its_three_stages() {
    assert_eq!(
        raycourse::scene_file::stage_names(1),
        ["white-disk", "shading", "spheres"]
    );
}

#[cfg(feature = "s2")]
#[test]
fn session_two_has_its_four_stages() {
    assert_eq!(
        raycourse::scene_file::stage_names(2),
        ["gamma", "shadows", "mirror", "glass"]
    );
}

#[test]
fn a_stage_renders_to_the_requested_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(
        &[
            "s1",
            "white-disk",
            "--width",
            "32",
            "--height",
            "24",
            "--out",
            "disk.png",
            "-q",
        ],
        dir.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(stdout.starts_with("white-disk: 32x24, 1 spp"), "{stdout}");
    assert!(
        stdout.contains("Mrays/s") && stdout.contains("768 rays"),
        "{stdout}"
    );
    let image = image::open(dir.path().join("disk.png")).unwrap().to_rgb8();
    assert_eq!(image.dimensions(), (32, 24));
    assert_eq!(image.get_pixel(16, 12).0, [255, 255, 255]);
    assert_eq!(image.get_pixel(0, 0).0, [0, 0, 0]);
}

#[test]
fn an_unknown_stage_lists_the_valid_ones() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["s1", "glass"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("invalid value 'glass'")
            && stderr.contains("[possible values: white-disk, shading, spheres]"),
        "{stderr}"
    );
}

#[test]
fn a_bad_scene_fails_cleanly_and_leaves_the_output_alone() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("bad.toml");
    std::fs::write(&scene, "[render]\nwidth = 0\nheight = 4\n").unwrap();
    let previous = dir.path().join("keep.png");
    std::fs::write(&previous, b"an earlier image").unwrap();
    let out = run(&["render", "bad.toml", "--out", "keep.png"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        "error: bad.toml:2:9: key `render.width`: invalid value: integer `0`, expected a \
         nonzero u32\n"
    );
    assert_eq!(std::fs::read(&previous).unwrap(), b"an earlier image");
    assert!(!dir.path().join("out").exists(), "no output written");
}

#[test]
fn a_missing_scene_file_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["render", "nowhere.toml"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).starts_with("error: nowhere.toml: cannot read the scene file:"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn a_scene_file_renders_into_out() {
    let dir = tempfile::tempdir().unwrap();
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("sessions/s1/shading.toml");
    std::fs::copy(source, dir.path().join("lit.toml")).unwrap();
    let out = run(
        &[
            "render", "lit.toml", "--width", "16", "--height", "16", "--quiet",
        ],
        dir.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let image = image::open(dir.path().join("out/lit.png")).unwrap();
    assert_eq!((image.width(), image.height()), (16, 16));
}

#[test]
fn no_arguments_renders_the_last_stage_of_the_build() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(
        &["--width", "16", "--height", "8", "--spp", "2"],
        dir.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let last = stages().last().unwrap().name;
    assert!(text(&out.stdout).starts_with(&format!("{last}: 16x8, ")));
    let image = image::open(dir.path().join(format!("out/{last}.png"))).unwrap();
    assert_eq!((image.width(), image.height()), (16, 8));
}

/// A `.rays` file (RAYFORMAT.md) of `kind` holding `records`.
#[cfg(feature = "beyond")]
fn ray_file(kind: u32, records: &[[f32; 8]]) -> Vec<u8> {
    let mut bytes = b"RAYS".to_vec();
    bytes.extend(1u32.to_le_bytes());
    bytes.extend(kind.to_le_bytes());
    bytes.extend((records.len() as u64).to_le_bytes());
    bytes.extend(records.iter().flatten().flat_map(|v| v.to_le_bytes()));
    bytes
}

#[cfg(feature = "beyond")]
#[test]
fn rays_prints_the_checksums_of_each_set() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("quad.obj"),
        "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n",
    )
    .unwrap();
    let inf = f32::INFINITY;
    let closest = [
        [0.2, 0.3, 2.0, 0.0, 0.0, -1.0, 0.0, inf],
        [5.0, 0.0, 2.0, 0.0, 0.0, -1.0, 0.0, inf],
        [0.0, 0.0, -0.5, 0.0, 0.0, 1.0, 0.0, inf],
    ];
    let shadow = [
        [0.0, 0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 2.0],
        [0.0, 0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.5],
    ];
    std::fs::write(dir.path().join("closest.rays"), ray_file(0, &closest)).unwrap();
    std::fs::write(dir.path().join("shadow.rays"), ray_file(1, &shadow)).unwrap();
    let out = run(
        &[
            "rays",
            "quad.obj",
            "closest.rays",
            "shadow.rays",
            "--passes",
            "1",
            "--threads",
            "1,2",
        ],
        dir.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    for threads in [1, 2] {
        let closest = format!("raycourse closest threads={threads} ");
        let line = stdout.lines().find(|l| l.starts_with(&closest)).unwrap();
        assert!(line.contains("hits=2 tsum=2.500000 rays=3"), "{line}");
        let shadow = format!("raycourse shadow threads={threads} ");
        let line = stdout.lines().find(|l| l.starts_with(&shadow)).unwrap();
        assert!(line.contains("occluded=1 rays=2"), "{line}");
    }
    std::fs::write(dir.path().join("short.rays"), &ray_file(0, &closest)[..40]).unwrap();
    let out = run(&["rays", "quad.obj", "short.rays"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("short.rays: 40 bytes"));
}

/// The CSV of a study with two variants whose error halves as the samples double.
#[cfg(feature = "plots")]
fn two_variant_study(
    folder: &Path,
    errors: impl Fn(u32) -> [raycourse::maths::Real; 2],
) -> std::path::PathBuf {
    use raycourse::maths::Real;
    use raycourse::studies::convergence::{ImageError, Rung};
    let mut text = format!("{}\n", Rung::CSV_HEADER);
    for samples in [1, 2, 4, 8] {
        for (variant, rmse) in ["a", "b"].iter().zip(errors(samples)) {
            let rung = Rung {
                variant: variant.to_string(),
                samples,
                seconds: samples as Real * 0.01,
                error: ImageError { rmse, rel_mse: 0.0 },
            };
            text += &format!("{}\n", rung.csv());
        }
    }
    let path = folder.join("study.csv");
    std::fs::write(&path, text).unwrap();
    path
}

/// `plot` draws a PNG of its size with one colour of line per variant, and labels.
#[cfg(feature = "plots")]
#[test]
fn plots_are_pngs_of_the_plot_size_with_two_colours_of_lines() {
    use plotters::style::{Color, Palette, Palette99};
    let dir = tempfile::tempdir().unwrap();
    use raycourse::maths::Real;
    let csv = two_variant_study(dir.path(), |n| [1.0 / n as Real, 2.0 / n as Real]);
    let out = run(
        &["plot", csv.to_str().unwrap(), "--out", "plot.png"],
        dir.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let image = image::open(dir.path().join("plot.png")).unwrap().to_rgb8();
    assert_eq!(image.dimensions(), (1200, 500));
    for i in 0..2 {
        let c = Palette99::pick(i).to_rgba();
        let count = image.pixels().filter(|p| p.0 == [c.0, c.1, c.2]).count();
        assert!(count > 500, "variant {i}: {count} pixels of its colour");
    }
    let black = image.pixels().filter(|p| p.0 == [0, 0, 0]).count();
    assert!(
        black > 1000,
        "{black} black pixels: labels and frames drawn"
    );
}

/// Exact images have no logarithm of their error: nothing to plot, said, and no file.
#[cfg(feature = "plots")]
#[test]
fn exact_images_have_no_plot() {
    let dir = tempfile::tempdir().unwrap();
    let csv = two_variant_study(dir.path(), |_| [0.0, 0.0]);
    let out = run(
        &["plot", csv.to_str().unwrap(), "--out", "plot.png"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(text(&out.stderr).contains("nothing to plot"));
    assert!(!dir.path().join("plot.png").exists());
}

#[test]
fn too_many_threads_are_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["s1", "shading", "--threads", "100000", "-q"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr).trim(),
        "error: --threads 100000: at most 1024 (one per core is the fastest)"
    );
    assert!(!dir.path().join("out").exists(), "nothing written");
}

/// `--out` writes through a symbolic link, and refuses what is not a regular file
/// (a pipe, a device, a folder) rather than replace it.
#[cfg(unix)]
#[test]
fn out_writes_through_a_link_and_refuses_what_is_not_a_file() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let render = |out: &str| {
        run(
            &[
                "s1", "shading", "--width", "8", "--height", "8", "--out", out, "-q",
            ],
            dir.path(),
        )
    };
    std::fs::write(dir.path().join("real.png"), b"old").unwrap();
    std::os::unix::fs::symlink("real.png", dir.path().join("link.png")).unwrap();
    assert!(render("link.png").status.success());
    let link = std::fs::symlink_metadata(dir.path().join("link.png")).unwrap();
    assert!(link.file_type().is_symlink(), "the link is kept");
    let image = image::open(dir.path().join("real.png")).unwrap();
    assert_eq!((image.width(), image.height()), (8, 8));
    let fifo = dir.path().join("pipe");
    assert!(
        std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    std::fs::create_dir(dir.path().join("folder.png")).unwrap();
    for (out, kind) in [
        ("pipe", "pipe"),
        ("/dev/null", "device"),
        ("folder.png", "folder"),
    ] {
        let refused = render(out);
        assert_eq!(refused.status.code(), Some(2), "{kind}");
        let said = text(&refused.stderr);
        assert!(said.contains("not a regular file"), "{kind}: {said}");
        assert_eq!(said.lines().count(), 1, "{kind}: {said}");
    }
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
}

/// A reader that closes the output at once (`raycourse list | head -0`) ends the
/// command quietly: exit code 0 and no panic on stderr.
#[test]
fn a_closed_output_ends_the_command_quietly() {
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_raycourse"))
        .arg("list")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{:?}", out.status);
    assert_eq!(text(&out.stderr), "", "nothing on stderr");
}
