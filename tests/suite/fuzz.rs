//! Property tests in the spirit of a fuzzer: whatever bytes a scene file or an OBJ
//! file holds, loading it returns a scene or an error, and never panics. The inputs
//! are random edits of valid files (deleted, repeated or replaced characters,
//! numbers swapped for extreme ones), which reach far deeper into the parsers than
//! random bytes do. `cargo test` tries a few thousand; `FUZZ_CASES=1000000 cargo test
//! --test suite fuzz` runs a longer campaign (the test profile is optimised and keeps
//! the overflow checks, which `--release` would turn off).

use std::path::Path;

use proptest::prelude::*;
use raycourse::{Overrides, parse_scene};

/// The scene file whose edits are tried: the last stage of the build, which uses
/// the most keys.
fn scene() -> &'static str {
    raycourse::stages()
        .last()
        .expect("every build has stages")
        .source
}

/// Cases per property: `FUZZ_CASES`, or `default`.
fn cases(default: u32) -> ProptestConfig {
    let cases = std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok());
    ProptestConfig::with_cases(cases.unwrap_or(default))
}

/// Extreme replacements for a number.
const NUMBERS: &[&str] = &[
    "0",
    "-0",
    "-1",
    "nan",
    "inf",
    "-inf",
    "1e308",
    "1e-320",
    "4294967296",
    "18446744073709551616",
    "\"x\"",
    "[]",
    "{}",
    "true",
];

/// A random edit of `text`: at `at` (a fraction of its length), one of: delete a
/// span, repeat a span, insert a character, or replace the number there.
fn edit(text: &str, at: f64, len: usize, kind: u8, byte: u8, number: usize) -> String {
    let chars: Vec<char> = text.chars().collect();
    let i = ((at * chars.len() as f64) as usize).min(chars.len());
    let j = (i + len).min(chars.len());
    let (head, tail) = (&chars[..i], &chars[i..]);
    let mut out: String = head.iter().collect();
    match kind % 4 {
        0 => out.extend(&chars[j..]),
        1 => {
            out.extend(&chars[i..j]);
            out.extend(tail);
        }
        2 => {
            out.push(char::from(byte));
            out.extend(tail);
        }
        _ => {
            let digits = tail
                .iter()
                .take_while(|c| c.is_ascii_digit() || **c == '.')
                .count();
            out.push_str(NUMBERS[number % NUMBERS.len()]);
            out.extend(&tail[digits..]);
        }
    }
    out
}

proptest! {
    #![proptest_config(cases(3000))]

    #[test]
    fn edited_scene_files_never_panic(
        edits in prop::collection::vec((0.0..1.0f64, 0..40usize, any::<u8>(), any::<u8>(), any::<usize>()), 1..6)
    ) {
        let mut text = scene().to_owned();
        for (at, len, kind, byte, number) in edits {
            text = edit(&text, at, len, kind, byte, number);
        }
        let _ = parse_scene(&text, Path::new("fuzz.toml"), &Overrides::default());
    }
}

#[cfg(feature = "s5")]
mod obj {
    use super::*;
    use raycourse::meshes::read_obj;

    const OBJ: &str = "mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\n\
                       vt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 2/2/1 4/1/1 3/3/1\n\
                       f -1 -2 -3\ns off\ng part\nf 1 2 3 4\n";

    proptest! {
        #![proptest_config(cases(2000))]

        #[test]
        fn edited_obj_files_never_panic(
            edits in prop::collection::vec((0.0..1.0f64, 0..20usize, any::<u8>(), any::<u8>(), any::<usize>()), 1..5)
        ) {
            let mut text = OBJ.to_owned();
            for (at, len, kind, byte, number) in edits {
                text = edit(&text, at, len, kind, byte, number);
            }
            let dir = tempfile::tempdir().unwrap();
            let path = dir.path().join("fuzz.obj");
            std::fs::write(&path, &text).unwrap();
            if let Ok(data) = read_obj(&path) {
                let count = data.positions.len() as u32;
                prop_assert!(data.triangles.iter().flatten().all(|&i| i < count));
            }
        }
    }
}
