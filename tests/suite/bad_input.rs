//! The bad-input corpus in `tests/bad-input/sN/`, a folder for each session whose
//! keys the files use: every scene file there is wrong in one way, named by its
//! first line (`# expect: ...`, a part of the error message). Each must fail with
//! one line on stderr naming the file and what is wrong, exit code 2, and no change
//! to an existing output image. A build runs the folders of its sessions.

use std::ffi::OsStr;
use std::path::{Path, PathBuf};

use crate::common::{run, text};
use raycourse::scene_file::SESSION;

/// A bad scene file: its name, its folder and what its error must say.
struct Case {
    name: String,
    folder: PathBuf,
    expect: String,
}

/// The scene files of the folders `s1` to `sN` of `dir`, for this build's sessions.
fn corpus(dir: &Path) -> Vec<Case> {
    let mut cases = vec![];
    for session in 1..=SESSION {
        let folder = dir.join(format!("s{session}"));
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for path in entries.map(|e| e.unwrap().path()) {
            if path.extension().is_none_or(|e| e != "toml") {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            let expect = text
                .lines()
                .find_map(|l| l.strip_prefix("# expect: "))
                .expect("every case says what it expects");
            cases.push(Case {
                name: path.file_name().unwrap().to_string_lossy().into_owned(),
                folder: folder.clone(),
                expect: expect.to_owned(),
            });
        }
    }
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
    for case in &cases {
        let output = run(
            &[
                OsStr::new("render"),
                case.name.as_ref(),
                "--quiet".as_ref(),
                "--out".as_ref(),
                image.as_os_str(),
            ],
            &case.folder,
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
    eprintln!("{ran} bad inputs of this build's sessions were refused");
}
