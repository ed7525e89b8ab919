//! PNG encoding with fixed settings, and writing that never leaves half a file.

use std::io::Write;
use std::path::Path;

use image::ImageEncoder;
use image::codecs::png::{CompressionType, FilterType, PngEncoder};

use crate::film::Film;
use crate::math::Real;

/// The film as PNG bytes. The encoder settings are fixed so the same film always
/// gives the same bytes: the snapshot tests compare them byte for byte.
pub fn encode_png(film: &Film, gamma: Real) -> Vec<u8> {
    let mut bytes = Vec::new();
    PngEncoder::new_with_quality(&mut bytes, CompressionType::Default, FilterType::Adaptive)
        .write_image(
            &film.to_rgb8(gamma),
            film.width,
            film.height,
            image::ExtendedColorType::Rgb8,
        )
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
    let mut file = tempfile::NamedTempFile::new_in(dir)?;
    file.write_all(bytes)?;
    file.as_file().sync_all()?;
    file.persist(path).map_err(|e| e.error)?;
    Ok(())
}
