//! The bad-input corpus in `tests/bad-input/`: every scene file there is wrong in one
//! way, named by its first line (`# expect: ...`, a part of the error message) and,
//! for later sessions' keys, its second (`# session: N`). Each must fail with one line
//! on stderr naming the file and what is wrong, exit code 2, and no change to an
//! existing output image.

use std::ffi::OsStr;
use std::path::Path;

use crate::common::{run, text};
use raycourse::scene_file::SESSION;

struct Case {
    name: String,
    expect: String,
    session: u32,
}

fn corpus(dir: &Path) -> Vec<Case> {
    let mut cases: Vec<Case> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|path| {
            let text = std::fs::read_to_string(&path).unwrap();
            let header = |key: &str| {
                text.lines()
                    .find_map(|l| l.strip_prefix(&format!("# {key}: ")))
                    .map(str::to_owned)
            };
            Case {
                name: path.file_name().unwrap().to_string_lossy().into_owned(),
                expect: header("expect").expect("every case says what it expects"),
                session: header("session").map_or(1, |s| s.parse().unwrap()),
            }
        })
        .collect();
    cases.sort_by(|a, b| a.name.cmp(&b.name));
    cases
}

#[test]
fn every_bad_input_fails_cleanly_and_writes_nothing() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad-input");
    let out = tempfile::tempdir().unwrap();
    let image = out.path().join("keep.png");
    std::fs::write(&image, b"an earlier image").unwrap();
    let cases = corpus(&dir);
    assert!(cases.len() >= 30, "{} cases", cases.len());
    let mut ran = 0;
    for case in cases.iter().filter(|c| c.session <= SESSION) {
        let output = run(
            &[
                OsStr::new("render"),
                case.name.as_ref(),
                "--quiet".as_ref(),
                "--out".as_ref(),
                image.as_os_str(),
            ],
            &dir,
        );
        let stderr = text(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{}: {stderr}", case.name);
        assert_eq!(
            stderr.lines().count(),
            1,
            "{}: one line: {stderr}",
            case.name
        );
        assert!(stderr.starts_with("error: "), "{}: {stderr}", case.name);
        assert!(
            stderr.contains(&case.name),
            "{}: names the file: {stderr}",
            case.name
        );
        assert!(
            stderr.contains(&case.expect),
            "{}: expected `{}` in: {stderr}",
            case.name,
            case.expect
        );
        assert_eq!(
            std::fs::read(&image).unwrap(),
            b"an earlier image",
            "{}",
            case.name
        );
        ran += 1;
    }
    eprintln!(
        "{ran} of {} bad inputs apply to this build and were refused",
        cases.len()
    );
    if SESSION == 7 {
        assert_eq!(ran, cases.len());
    }
}
