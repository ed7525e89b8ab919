//! PNG encoding with fixed settings, and writing that never leaves half a file.

use std::io::Write;
use std::path::Path;

use image::ImageEncoder;
use image::codecs::png::{CompressionType, FilterType, PngEncoder};

use crate::maths::Real;
use crate::render::Film;

/// The film as PNG bytes. The encoder settings are fixed so the same film always
/// gives the same bytes: the snapshot tests compare them byte for byte.
pub fn encode_png(film: &Film, gamma: Real) -> Vec<u8> {
    encode_rgb8(&film.to_rgb8(gamma), film.width, film.height)
}

/// `width` x `height` 8-bit RGB pixels, row-major, as PNG bytes, with the same fixed
/// settings as [`encode_png`].
pub fn encode_rgb8(rgb: &[u8], width: u32, height: u32) -> Vec<u8> {
    let mut bytes = Vec::new();
    PngEncoder::new_with_quality(&mut bytes, CompressionType::Default, FilterType::Adaptive)
        .write_image(rgb, width, height, image::ExtendedColorType::Rgb8)
        .expect("encoding a well-sized RGB buffer into memory cannot fail");
    bytes
}

/// Writes `bytes` to `path` atomically: into a temporary file beside it, then
/// renamed over it, so an interrupted run leaves the old file or none, never half
/// of a new one. Missing parent folders are created.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir)?;
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    let temporary = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let written = std::fs::File::create(&temporary).and_then(|mut file| {
        file.write_all(bytes)?;
        file.sync_all()?;
        std::fs::rename(&temporary, path)
    });
    if written.is_err() {
        // The temporary file may not exist; nothing more can be done if removal fails.
        let _ = std::fs::remove_file(&temporary);
    }
    written
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let dir = std::env::temp_dir().join(format!("raycourse-png-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let target = dir.join("image.png");
        write_atomically(&target, b"first").unwrap();
        // Renaming a file over a non-empty folder fails after the bytes are written.
        let blocked = dir.join("folder.png");
        std::fs::create_dir_all(blocked.join("inside")).unwrap();
        assert!(write_atomically(&blocked, b"second").is_err());
        assert_eq!(std::fs::read(&target).unwrap(), b"first");
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        assert!(left.iter().all(|n| !n.ends_with(".tmp")), "{left:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
