//! Where the files a scene file names (OBJ meshes, their MTL files, textures) are
//! read from: the disk for the command line, bytes held in memory for a web page,
//! which has no files.

use std::collections::BTreeMap;
use std::io;
use std::path::{Component, Path, PathBuf};

/// A source of the files a scene file names, by path. `Sync`, so that a reference to
/// one can go with a render onto its threads.
pub trait Files: Sync {
    /// The bytes of the file at `path`.
    fn read(&self, path: &Path) -> io::Result<Vec<u8>>;
}

/// The files on disk.
#[derive(Clone, Copy, Debug, Default)]
pub struct Disk;

impl Files for Disk {
    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        std::fs::read(path)
    }
}

/// Files held in memory, found by path once `.` and `..` are resolved by name
/// (`sessions/s5/../../assets/spot/spot.obj` is `assets/spot/spot.obj`): what a web
/// page compiled in or fetched.
#[derive(Clone, Debug, Default)]
pub struct InMemory {
    files: BTreeMap<PathBuf, Vec<u8>>,
}

impl InMemory {
    /// Holds `bytes` as the file at `path`.
    pub fn insert(&mut self, path: impl AsRef<Path>, bytes: Vec<u8>) {
        self.files.insert(resolve(path.as_ref()), bytes);
    }
}

impl Files for InMemory {
    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        self.files.get(&resolve(path)).cloned().ok_or_else(|| {
            io::Error::new(io::ErrorKind::NotFound, "no such file among those given")
        })
    }
}

/// `path` with its `.` components dropped and each `..` removing the name before it,
/// without asking the file system (so links are not followed).
fn resolve(path: &Path) -> PathBuf {
    let mut resolved = PathBuf::new();
    for component in path.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir if resolved.file_name().is_some() => {
                resolved.pop();
            }
            other => resolved.push(other),
        }
    }
    resolved
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn in_memory_files_are_found_through_dots() {
        let mut files = InMemory::default();
        files.insert("assets/spot/spot.obj", b"v 0 0 0".to_vec());
        let found = files.read(Path::new("sessions/s5/../../assets/./spot/spot.obj"));
        assert_eq!(found.unwrap(), b"v 0 0 0");
        let missing = files.read(Path::new("assets/spot/other.obj")).unwrap_err();
        assert_eq!(missing.kind(), io::ErrorKind::NotFound);
    }

    #[test]
    fn leading_parents_are_kept() {
        assert_eq!(resolve(Path::new("../a/./b/../c")), Path::new("../a/c"));
        assert_eq!(resolve(Path::new("/x/y/../../z")), Path::new("/z"));
    }
}
