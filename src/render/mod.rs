//! The renderer: every pixel's radiance on the film, rows shared among threads, and
//! the film written out as a PNG.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`rows`] | 1 | the render loop: rows shared among threads |
//! | `pixel` | 1, 2 | one pixel: the radiance of the ray through its centre |
//! | [`samples`] | 3 | one pixel: the mean of many random samples |
//! | [`film`] | 1 | linear radiance per pixel, and its 8-bit display values |
//! | [`png`] | 1 | PNG files with fixed settings, written atomically |
//! | [`cache`] | 1 | films rendered once and kept on disk, such as `check`'s references |

pub mod cache;
pub mod film;
pub mod png;
pub mod rows;

#[cfg(not(feature = "s3"))]
pub mod pixel;

#[cfg(feature = "s3")]
pub mod samples;

pub use film::Film;
pub use png::{encode_png, write_atomically};
pub use rows::{Render, render, render_reporting, render_rows};
