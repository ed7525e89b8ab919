//! `raycourse converge` and `raycourse plot`: the error of Monte Carlo renders
//! against a reference, measured as a student runs it. Both arrive with session 3,
//! when rendering becomes a trade between time and noise.

use std::path::Path;

use crate::common::{run, text};
use raycourse::maths::Real;
use raycourse::studies::convergence::fitted_slope;
use raycourse::studies::convergence::{Rung, read_rungs};

/// Runs a study in `dir` and returns its rows, after checking that the reference
/// file it names on its first line is there.
fn study(dir: &Path, args: &[&str]) -> Vec<Rung> {
    let mut all = vec!["converge", "-q", "--fast", "--out", "study"];
    all.extend(args);
    let out = run(&all, dir);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let printed = text(&out.stdout);
    let reference = printed.split(['(', ')']).nth(1).unwrap_or_default();
    assert!(
        reference.ends_with(".ref") && dir.join(reference).is_file(),
        "{printed}"
    );
    read_rungs(&std::fs::read_to_string(dir.join("study.csv")).unwrap()).unwrap()
}

#[cfg(feature = "s4")]
fn rows<'r>(rungs: &'r [Rung], variant: &str) -> Vec<&'r Rung> {
    rungs.iter().filter(|r| r.variant == variant).collect()
}

#[test]
fn indirect_error_falls_as_one_over_root_n_and_the_reference_is_cached() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "indirect",
        "--width",
        "32",
        "--height",
        "32",
        "--max-spp",
        "64",
        "--reference-spp",
        "2048",
    ];
    let rungs = study(dir.path(), &args);
    let samples: Vec<u32> = rungs.iter().map(|r| r.samples).collect();
    assert_eq!(samples, [1, 2, 4, 8, 16, 32, 64]);
    let points: Vec<(Real, Real)> = rungs
        .iter()
        .map(|r| (r.samples as Real, r.error.rmse))
        .collect();
    let slope = fitted_slope(&points).unwrap();
    assert!((slope + 0.5).abs() < 0.1, "slope {slope}");
    assert!(rungs.iter().all(|r| r.error.rel_mse > 0.0));
    let png = std::fs::read(dir.path().join("study.png")).unwrap();
    assert_eq!(image::load_from_memory(&png).unwrap().width(), 1200);
    // A second study finds the reference in the cache: the same errors, bit for
    // bit, since the ladder's renders do not depend on the thread count either.
    let cached: Vec<_> = std::fs::read_dir(dir.path().join("out/reference"))
        .unwrap()
        .collect();
    assert_eq!(cached.len(), 1);
    let again = study(dir.path(), &args);
    let errors = |r: &[Rung]| r.iter().map(|r| r.error).collect::<Vec<_>>();
    assert_eq!(errors(&again), errors(&rungs));
}

#[cfg(feature = "s4")]
#[test]
fn light_sampling_is_far_more_efficient_than_waiting_to_hit_the_light() {
    let dir = tempfile::tempdir().unwrap();
    let rungs = study(
        dir.path(),
        &[
            "light-sampling",
            "--compare",
            "light-sampling",
            "--width",
            "32",
            "--height",
            "32",
            "--max-spp",
            "32",
            "--reference-spp",
            "1024",
        ],
    );
    let naive = rows(&rungs, "naive");
    let sampled = rows(&rungs, "light sampling");
    assert_eq!((naive.len(), sampled.len()), (6, 6));
    for (n, s) in naive.iter().zip(&sampled) {
        assert!(
            n.error.rmse > 5.0 * s.error.rmse,
            "{} spp: {} vs {}",
            n.samples,
            n.error.rmse,
            s.error.rmse
        );
    }
    // Efficiency at equal work, 1 / (MSE x rays traced): counted, not timed, so that
    // a busy machine cannot decide the comparison.
    let work =
        |rung: &Rung| rung.error.rmse.powi(2) * rays_traced(&rung.variant, rung.samples) as Real;
    let gain = work(naive[5]) / work(sampled[5]);
    assert!(gain > 10.0, "efficiency gain {gain}");
}

/// The rays that the comparison `light-sampling`'s variant `label` traces at 32 x
/// 32 pixels and `samples` per pixel.
#[cfg(feature = "s4")]
fn rays_traced(label: &str, samples: u32) -> u64 {
    let (variants, _) = raycourse::studies::variant::comparison("light-sampling").unwrap();
    let variant = variants.iter().find(|v| v.label == label).unwrap();
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("sessions/s4/light-sampling.toml");
    let source = variant
        .apply(&std::fs::read_to_string(&path).unwrap())
        .unwrap();
    let sized = raycourse::Overrides::sized(32, 32, samples);
    let scene = raycourse::parse_scene(&source, &path, &sized).unwrap();
    raycourse::render(&scene).rays
}

#[cfg(feature = "s6")]
#[test]
fn acceleration_changes_the_time_and_never_the_image() {
    let dir = tempfile::tempdir().unwrap();
    let rungs = study(
        dir.path(),
        &[
            "bvh",
            "--compare",
            "acceleration",
            "--width",
            "12",
            "--height",
            "12",
            "--max-spp",
            "2",
            "--reference-spp",
            "4",
        ],
    );
    let brute = rows(&rungs, "brute force");
    for variant in ["bounding box", "BVH", "fast BVH"] {
        let errors: Vec<_> = rows(&rungs, variant).iter().map(|r| r.error).collect();
        let expected: Vec<_> = brute.iter().map(|r| r.error).collect();
        assert_eq!(errors, expected, "{variant}");
    }
}

#[test]
fn a_deterministic_stage_has_no_error_and_no_plot() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(
        &[
            "converge",
            "white-disk",
            "-q",
            "--width",
            "16",
            "--height",
            "16",
            "--max-spp",
            "4",
            "--reference-spp",
            "8",
        ],
        dir.path(),
    );
    assert!(out.status.success());
    assert!(text(&out.stdout).contains("nothing to plot"));
    let csv = std::fs::read_to_string(dir.path().join("out/converge/white-disk.csv")).unwrap();
    let rungs = read_rungs(&csv).unwrap();
    assert_eq!(rungs.len(), 3);
    assert!(rungs.iter().all(|r| r.error.rmse == 0.0));
    assert!(!dir.path().join("out/converge/white-disk.png").exists());
}

#[test]
fn bad_variants_and_files_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(
        &["converge", "white-disk", "--variant", "x:render.bogus=1"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("render.bogus"), "{stderr}");
    let out = run(&["converge", "nowhere"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("`nowhere` is neither a stage"));
    std::fs::write(dir.path().join("bad.csv"), "variant,samples\n").unwrap();
    let out = run(&["plot", "bad.csv", "--out", "plot.png"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr).trim(),
        format!(
            "error: bad.csv: line 1: expected the header `{}`",
            Rung::CSV_HEADER
        )
    );
    assert!(!dir.path().join("plot.png").exists());
}

#[test]
fn plot_merges_studies() {
    let dir = tempfile::tempdir().unwrap();
    for (name, scale) in [("a", 1.0), ("b", 2.0)] {
        let mut csv = format!("{}\n", Rung::CSV_HEADER);
        for n in [1, 2, 4] {
            csv += &format!("{name},{n},{},{},0.1,0\n", n as f64 * 0.1, scale / n as f64);
        }
        std::fs::write(dir.path().join(format!("{name}.csv")), csv).unwrap();
    }
    let out = run(&["plot", "a.csv", "b.csv", "--out", "ab.png"], dir.path());
    assert!(out.status.success());
    assert_eq!(text(&out.stdout).trim(), "6 rows -> ab.png");
    assert!(dir.path().join("ab.png").exists());
}
