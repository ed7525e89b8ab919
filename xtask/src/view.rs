//! A session view: the crate as it stands after session N, written to a folder.

use std::fs;
use std::path::{Path, PathBuf};

use crate::manifest::view_manifest;
use crate::prune::prune;

/// The first line of a view's README: how a folder is known to hold a view that may
/// be written over.
const README_FIRST_LINE: &str = "# raycourse after session";

/// Writes the view of `session` of the crate at `root` into `out`, which must be
/// empty, absent, or an earlier view (replaced).
pub fn write_view(root: &Path, session: u32, out: &Path) -> Result<(), String> {
    prepare(out)?;
    let manifest = view_manifest(&read(&root.join("Cargo.toml"))?, session)?;
    write(&out.join("Cargo.toml"), &manifest)?;
    for file in ["Cargo.lock", "build.rs"] {
        copy(&root.join(file), &out.join(file))?;
    }
    write(&out.join(".gitignore"), "/target\n/out\n")?;
    for main in ["lib.rs", "main.rs"] {
        module_tree(&root.join("src").join(main), root, out, session)?;
    }
    for n in 1..=session {
        copy_folder(
            &root.join(format!("sessions/s{n}")),
            &out.join(format!("sessions/s{n}")),
        )?;
    }
    copy_folder(&root.join("messages"), &out.join("messages"))?;
    copy_assets(root, out, session)?;
    copy_tests(root, out, session)?;
    write(&out.join("README.md"), &readme(session))
}

/// Makes `out` ready: absent or empty is fine; an earlier view is removed.
fn prepare(out: &Path) -> Result<(), String> {
    if out.exists()
        && fs::read_dir(out)
            .map_err(|e| e.to_string())?
            .next()
            .is_some()
    {
        let readme = fs::read_to_string(out.join("README.md")).unwrap_or_default();
        if !readme.starts_with(README_FIRST_LINE) {
            return Err(format!(
                "{}: the folder is not empty and holds no session view; choose another",
                out.display()
            ));
        }
        for entry in fs::read_dir(out).map_err(|e| e.to_string())? {
            let path = entry.map_err(|e| e.to_string())?.path();
            if path.file_name().is_some_and(|n| n == "target") {
                continue;
            }
            let removed = if path.is_dir() {
                fs::remove_dir_all(&path)
            } else {
                fs::remove_file(&path)
            };
            removed.map_err(|e| format!("{}: {e}", path.display()))?;
        }
    }
    fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))
}

/// Prunes the module file `file` and, through its kept `mod` declarations, every
/// module below it, writing them under `out` at the same places as under `root`.
fn module_tree(file: &Path, root: &Path, out: &Path, session: u32) -> Result<(), String> {
    let relative = file.strip_prefix(root).map_err(|e| e.to_string())?;
    let Some(pruned) = prune_file(file, &out.join(relative), session)? else {
        return Ok(());
    };
    let stem = file.file_stem().unwrap_or_default();
    let folder = match stem.to_str() {
        Some("lib" | "main" | "mod") => file.parent().unwrap().to_owned(),
        _ => file.with_extension(""),
    };
    for module in pruned {
        let flat = folder.join(format!("{module}.rs"));
        let nested = folder.join(&module).join("mod.rs");
        let child = if flat.exists() { flat } else { nested };
        module_tree(&child, root, out, session)?;
    }
    Ok(())
}

/// Prunes `from` into `to`; the modules it declares, or `None` when the whole file
/// belongs to a later session (nothing is written).
fn prune_file(from: &Path, to: &Path, session: u32) -> Result<Option<Vec<String>>, String> {
    let pruned = prune(&read(from)?, session).map_err(|e| format!("{}: {e}", from.display()))?;
    let Some(pruned) = pruned else {
        return Ok(None);
    };
    write(to, &pruned.text)?;
    Ok(Some(pruned.modules))
}

/// Copies the assets the view's scenes and tests use: the folders that
/// `assets/sessions.toml` gives to sessions up to `session` (the meshes with their
/// textures, from session 5).
fn copy_assets(root: &Path, out: &Path, session: u32) -> Result<(), String> {
    copy(
        &root.join("assets/README.md"),
        &out.join("assets/README.md"),
    )?;
    let map = root.join("assets/sessions.toml");
    let text = std::fs::read_to_string(&map).map_err(|e| format!("{}: {e}", map.display()))?;
    let folders: toml_edit::DocumentMut = text
        .parse()
        .map_err(|e| format!("{}: {e}", map.display()))?;
    for (folder, from) in folders.iter() {
        let from = from
            .as_integer()
            .ok_or_else(|| format!("{}: `{folder}` should be a session number", map.display()))?;
        if i64::from(session) >= from {
            copy_folder(
                &root.join("assets").join(folder),
                &out.join("assets").join(folder),
            )?;
        }
    }
    Ok(())
}

/// Copies the tests that apply to the view: the snapshot test, the suite's and the
/// exercises' modules pruned (a module of a later session left out), the bad inputs
/// of sessions 1..N, the snapshots and reference images of their stages.
fn copy_tests(root: &Path, out: &Path, session: u32) -> Result<(), String> {
    let tests = root.join("tests");
    for file in rust_files(&tests)? {
        module_tree(&file, root, out, session)?;
    }
    module_tree(&tests.join("suite/main.rs"), root, out, session)?;
    for n in 1..=session {
        let folder = tests.join(format!("bad-input/s{n}"));
        if folder.is_dir() {
            copy_folder(&folder, &out.join(format!("tests/bad-input/s{n}")))?;
        }
    }
    let stages: Vec<String> = (1..=session)
        .flat_map(|n| rust_like(&root.join(format!("sessions/s{n}")), "toml"))
        .collect();
    module_tree(&tests.join("exercises/main.rs"), root, out, session)?;
    for stage in stages {
        for suffix in [".snap", ".snap.png"] {
            let name = format!("stages__{stage}{suffix}");
            copy(
                &tests.join("snapshots").join(&name),
                &out.join("tests/snapshots").join(&name),
            )?;
        }
        let reference = format!("exercises/references/{stage}.png");
        copy(&tests.join(&reference), &out.join("tests").join(&reference))?;
    }
    Ok(())
}

/// The `.rs` files directly in `folder`, sorted.
fn rust_files(folder: &Path) -> Result<Vec<PathBuf>, String> {
    let mut files: Vec<PathBuf> = fs::read_dir(folder)
        .map_err(|e| format!("{}: {e}", folder.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .collect();
    files.sort();
    Ok(files)
}

/// The `.rs` files under `folder`, at any depth, sorted.
pub fn rust_files_under(folder: &Path) -> Result<Vec<PathBuf>, String> {
    let mut files = rust_files(folder)?;
    for entry in fs::read_dir(folder).map_err(|e| format!("{}: {e}", folder.display()))? {
        let path = entry.map_err(|e| e.to_string())?.path();
        if path.is_dir() {
            files.extend(rust_files_under(&path)?);
        }
    }
    Ok(files)
}

/// The stems of the files with extension `extension` directly in `folder`.
fn rust_like(folder: &Path, extension: &str) -> Vec<String> {
    let entries = fs::read_dir(folder).into_iter().flatten().flatten();
    entries
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == extension))
        .map(|p| {
            p.file_stem()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned()
        })
        .collect()
}

/// The view's README: what it is and how to go on.
fn readme(session: u32) -> String {
    let next = session + 1;
    let last = crate::cfg::last_session();
    let go_on = if session < last {
        format!(
            "## Going on to session {next}\n\n\
             Build session {next} here: add its files, its stages' scene files in \
             `sessions/s{next}/`, and the tests that pin them. The course's crate holds \
             the finished session: `cargo xtask view s{next} DIR` in it writes the crate \
             as it stands after session {next}, to compare with your own.\n"
        )
    } else {
        "This is the whole course.\n".to_owned()
    };
    format!(
        "{README_FIRST_LINE} {session}\n\n\
         This crate is `raycourse` as it stands after session {session} of the course: \
         the code, scene files, assets, tests and snapshots of sessions 1 to {session}, \
         and nothing of the later ones. It was written by `cargo xtask view s{session}` \
         from the course's crate, which holds every session behind the Cargo features \
         `s1` to `s{last}`; here there are no session features.\n\n\
         ```sh\n\
         cargo run --release -- list          # the stages of sessions 1 to {session}\n\
         cargo run --release -- s{session} <stage>        # render one\n\
         cargo test                           # every stage pinned by its snapshot\n\
         cargo doc --open                     # this session's crate, documented\n\
         ```\n\n\
         Each stage renders byte for byte as the course's crate built with \
         `--features s{session}`.\n\n{go_on}"
    )
}

/// The text of `path`.
fn read(path: &Path) -> Result<String, String> {
    fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// Writes `text` to `path`, making its folder.
fn write(path: &Path, text: &str) -> Result<(), String> {
    if let Some(folder) = path.parent() {
        fs::create_dir_all(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    }
    fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Copies the file `from` to `to`, making its folder.
pub fn copy(from: &Path, to: &Path) -> Result<(), String> {
    if let Some(folder) = to.parent() {
        fs::create_dir_all(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    }
    fs::copy(from, to)
        .map(drop)
        .map_err(|e| format!("{}: {e}", from.display()))
}

/// Copies the folder `from` into `to`, recursively.
pub fn copy_folder(from: &Path, to: &Path) -> Result<(), String> {
    for entry in fs::read_dir(from).map_err(|e| format!("{}: {e}", from.display()))? {
        let path = entry.map_err(|e| e.to_string())?.path();
        let target = to.join(path.file_name().unwrap());
        if path.is_dir() {
            copy_folder(&path, &target)?;
        } else {
            copy(&path, &target)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `.rs` and `.toml` files under `folder`, with their text.
    fn texts(folder: &Path) -> Vec<(PathBuf, String)> {
        let mut found = vec![];
        for path in fs::read_dir(folder).unwrap().map(|e| e.unwrap().path()) {
            if path.is_dir() {
                found.extend(texts(&path));
            } else if path.extension().is_some_and(|e| e == "rs" || e == "toml") {
                found.push((path.clone(), fs::read_to_string(&path).unwrap()));
            }
        }
        found
    }

    #[test]
    fn no_view_keeps_a_session_gate_or_what_goes_beyond_the_course() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let out = std::env::temp_dir().join(format!("raycourse-views-{}", std::process::id()));
        for session in 1..=crate::cfg::last_session() {
            let view = out.join(format!("s{session}"));
            write_view(root, session, &view).unwrap();
            for (path, text) in texts(&view) {
                for gate in ["feature = \"s", "feature = \"beyond\"", "mod fast;"] {
                    assert!(!text.contains(gate), "{}: {gate}", path.display());
                }
            }
            assert!(!view.join("src/fast").exists() && !view.join("assets/fonts").exists());
        }
        fs::remove_dir_all(&out).unwrap();
    }
}
