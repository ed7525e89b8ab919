//! The comparison of a student's image with what a stage should give.
//!
//! Deterministic stages (one sample per pixel, no randomness) are compared pixel by
//! pixel: a few display levels of difference are allowed everywhere, more on the
//! silhouettes and other edges, where one student's rounding puts a pixel on the
//! other side. Monte Carlo stages are noisy, and so is the student's image, with
//! another seed and maybe another number of samples: they are compared in blocks of
//! `BLOCK` x `BLOCK` pixels. In each block and channel, the mean difference of
//! linear radiance is tested against its standard error, estimated from the spread
//! of the pixel differences themselves: an unbiased render with any seed passes.

use image::RgbImage;

use crate::maths::Real;
use crate::render::Film;
use crate::render::film::display;

/// Side of a block of pixels, for Monte Carlo stages.
pub const BLOCK: u32 = 8;

/// How many standard errors a block's mean difference may reach: with 12,288
/// block-channel tests for a 512 x 512 image, a Gaussian mean difference passes 4.5
/// standard errors about once in 150 images.
pub const Z: f64 = 4.5;

/// The relative difference a block's mean may have besides the noise: the display's
/// rounding and clipping of noisy pixels bias a mean by a little.
pub const RELATIVE: f64 = 0.03;

/// The share of blocks that may fail before an image differs: a few blocks straddle
/// a light whose fireflies no estimate of the noise captures.
pub const BLOCK_BUDGET: f64 = 0.01;

/// A picture in linear radiance, as the checker compares it: for the student's
/// image, each 8-bit value `v` read back as `v^gamma`, and 255 (clipped) kept as
/// clipped.
#[derive(Clone, Debug, PartialEq)]
pub struct Linear {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Three channels per pixel, row-major from the top.
    pub values: Vec<f64>,
}

impl Linear {
    /// The mean of two pictures of the same size, pixel by pixel.
    pub fn mean(&self, other: &Linear) -> Linear {
        Linear {
            values: self
                .values
                .iter()
                .zip(&other.values)
                .map(|(a, b)| (a + b) / 2.0)
                .collect(),
            ..self.clone()
        }
    }

    /// The student's 8-bit image read back to linear radiance through the stage's
    /// display `gamma`.
    pub fn from_rgb8(image: &RgbImage, gamma: Real) -> Linear {
        Linear {
            width: image.width(),
            height: image.height(),
            values: image
                .as_raw()
                .iter()
                .map(|&v| f64::from(v).powf(crate::maths::to_double(gamma)))
                .collect(),
        }
    }

    /// A film's radiance, clipped where the display shows full white.
    pub fn from_film(film: &Film, gamma: Real) -> Linear {
        let white = 255f64.powf(crate::maths::to_double(gamma));
        Linear {
            width: film.width,
            height: film.height,
            values: film
                .pixels
                .iter()
                .flat_map(|p| p.to_array())
                .map(|v| crate::maths::to_double(v).clamp(0.0, white))
                .collect(),
        }
    }
}

/// What a comparison found.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// Per pixel (deterministic stages) or per block (Monte Carlo ones), row-major:
    /// whether it differs.
    pub differs: Vec<bool>,
    /// Pixels per cell of `differs` along each side: 1 or [`BLOCK`].
    pub cell: u32,
    /// Cells along the width.
    pub columns: u32,
    /// Whether the whole image differs: more differing cells than allowed.
    pub image_differs: bool,
}

impl Outcome {
    /// The share of cells that differ.
    pub fn share(&self) -> f64 {
        self.differs.iter().filter(|d| **d).count() as f64 / self.differs.len().max(1) as f64
    }
}

/// Compares a deterministic stage's 8-bit image with the `expected` one: a pixel
/// differs when a channel is off by more than `tolerance` levels. Pixels on an edge
/// of the expected image (a neighbour more than 24 levels away) may all differ;
/// elsewhere, at most 0.2% of the pixels.
pub fn compare_pixels(student: &RgbImage, expected: &RgbImage, tolerance: u8) -> Outcome {
    compare_pixels_near_edges(student, expected, tolerance, 0)
}

/// As [`compare_pixels`], with the edges widened by `reach` pixels on every side:
/// a JPEG's compression smears colour over blocks of pixels (its colour is stored at
/// half the resolution), so a right image saved as a JPEG differs by more than its
/// tolerance up to a pixel beyond each edge.
pub fn compare_pixels_near_edges(
    student: &RgbImage,
    expected: &RgbImage,
    tolerance: u8,
    reach: u32,
) -> Outcome {
    let (w, h) = student.dimensions();
    let differs: Vec<bool> = student
        .pixels()
        .zip(expected.pixels())
        .map(|(s, e)| s.0.iter().zip(e.0).any(|(a, b)| a.abs_diff(b) > tolerance))
        .collect();
    let edges = widened(&edges(expected), (w, h), reach);
    let off_edges = (0..(w * h) as usize)
        .filter(|&i| differs[i] && !edges[i])
        .count();
    Outcome {
        image_differs: off_edges as f64 > 0.002 * f64::from(w * h),
        differs,
        cell: 1,
        columns: w,
    }
}

/// Per pixel, row-major: whether a neighbour of the pixel in `image` is more than 24
/// levels away in a channel.
fn edges(image: &RgbImage) -> Vec<bool> {
    let (w, h) = image.dimensions();
    let edge = |x: u32, y: u32| {
        let centre = image.get_pixel(x, y).0;
        (x.saturating_sub(1)..(x + 2).min(w))
            .flat_map(|i| (y.saturating_sub(1)..(y + 2).min(h)).map(move |j| (i, j)))
            .any(|(i, j)| {
                image
                    .get_pixel(i, j)
                    .0
                    .iter()
                    .zip(centre)
                    .any(|(a, b)| a.abs_diff(b) > 24)
            })
    };
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| edge(x, y))
        .collect()
}

/// `mask` (of a `w` x `h` image) with every set pixel grown by `reach` pixels.
fn widened(mask: &[bool], (w, h): (u32, u32), reach: u32) -> Vec<bool> {
    if reach == 0 {
        return mask.to_vec();
    }
    let at = |x: u32, y: u32| mask[(y * w + x) as usize];
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            (x.saturating_sub(reach)..(x + reach + 1).min(w))
                .any(|i| (y.saturating_sub(reach)..(y + reach + 1).min(h)).any(|j| at(i, j)))
        })
        .collect()
}

/// Compares a Monte Carlo stage's image, read back to linear radiance, with the
/// `expected` radiance, block by block: in each block and channel the mean
/// difference `m` of the pixels, their standard deviation `s` (so the standard
/// error `s / sqrt(n)`), and the allowance `Z s / sqrt(n) + q + RELATIVE e`, with `q`
/// the mean half step of the display's rounding at the expected values and `e` their
/// mean. The block differs when `|m|` exceeds it in a channel; the image, when more
/// than `BLOCK_BUDGET` of the blocks (and at least two) do.
pub fn compare_blocks(student: &Linear, expected: &Linear, gamma: Real) -> Outcome {
    let (columns, rows) = (student.width / BLOCK, student.height / BLOCK);
    let mut differs = Vec::with_capacity((columns * rows) as usize);
    for by in 0..rows {
        for bx in 0..columns {
            differs.push((0..3).any(|c| block_differs(student, expected, (bx, by, c), gamma)));
        }
    }
    let failing = differs.iter().filter(|d| **d).count();
    Outcome {
        image_differs: failing >= 2 && failing as f64 > BLOCK_BUDGET * differs.len() as f64,
        differs,
        cell: BLOCK,
        columns,
    }
}

/// Whether channel `c` of block `(bx, by)` differs (see [`compare_blocks`]).
fn block_differs(
    student: &Linear,
    expected: &Linear,
    (bx, by, c): (u32, u32, usize),
    gamma: Real,
) -> bool {
    let gamma = crate::maths::to_double(gamma);
    let mut differences = Vec::with_capacity((BLOCK * BLOCK) as usize);
    let (mut expected_sum, mut rounding) = (0.0, 0.0);
    for y in by * BLOCK..(by + 1) * BLOCK {
        for x in bx * BLOCK..(bx + 1) * BLOCK {
            let i = 3 * (y * student.width + x) as usize + c;
            let e = expected.values[i];
            differences.push(student.values[i] - e);
            expected_sum += e;
            let v = e.powf(1.0 / gamma);
            rounding += ((v + 0.5).powf(gamma) - (v - 0.5).max(0.0).powf(gamma)) / 2.0;
        }
    }
    let n = differences.len() as f64;
    let mean = differences.iter().sum::<f64>() / n;
    let variance = differences.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let allowance = Z * (variance / n).sqrt() + rounding / n + RELATIVE * expected_sum / n;
    mean.abs() > allowance
}

/// The 8-bit image a film displays as, with the display `gamma`.
pub fn displayed(film: &Film, gamma: Real) -> RgbImage {
    let rgb = film
        .pixels
        .iter()
        .flat_map(|p| p.to_array().map(|v| display(v, gamma)))
        .collect();
    RgbImage::from_raw(film.width, film.height, rgb).expect("a film has width x height pixels")
}

/// Whether `other`, a render of the scene of `film` by another engine (the fast one),
/// shows the same picture, as `check` judges one: the same 8-bit image, or else
/// `check`'s "matches", pixel by pixel for a stage of one sample per pixel and block
/// by block against the noise for a Monte Carlo one. The fast engine's numbers may
/// differ from the course's in the last bits, so at a size where a rare pixel lies on
/// a display level's edge its byte may too.
pub fn same_picture(film: &Film, other: &Film, gamma: Real, samples: u32) -> bool {
    let (expected, shown) = (displayed(film, gamma), displayed(other, gamma));
    if expected == shown {
        return true;
    }
    let outcome = if samples == 1 {
        compare_pixels(&shown, &expected, 3)
    } else {
        let shown = Linear::from_rgb8(&shown, gamma);
        compare_blocks(&shown, &Linear::from_film(film, gamma), gamma)
    };
    !outcome.image_differs
}

/// Per channel, the student's total radiance over the expected total, over the
/// pixels the reference does not clip: 1 for a right image, about 3.14 for a
/// forgotten `1 / pi` (less where the student's pixels clip).
pub fn brightness_ratio(student: &Linear, expected: &Linear, gamma: Real) -> [f64; 3] {
    let white = 255f64.powf(crate::maths::to_double(gamma)) * 0.999;
    let mut sums = [[0.0; 2]; 3];
    for (i, (s, e)) in student.values.iter().zip(&expected.values).enumerate() {
        if *e < white {
            sums[i % 3][0] += s;
            sums[i % 3][1] += e;
        }
    }
    sums.map(|[s, e]| if e > 0.0 { s / e } else { 1.0 })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maths::Colour;

    /// A 40 x 30 film of a smooth gradient that displays, with gamma 2.2, as levels
    /// from 0 to 240, a few levels apart from pixel to pixel.
    fn gradient() -> Film {
        let (width, height) = (40, 30);
        let pixels = (0..width * height)
            .map(|i| {
                let (x, y) = ((i % width) as Real, (i / width) as Real);
                Colour::new(6.0 * x, 8.0 * y, 3.0 * (x + y)).map(|level| level.powf(2.2))
            })
            .collect();
        Film {
            width,
            height,
            pixels,
        }
    }

    #[test]
    fn a_render_a_few_roundings_away_shows_the_same_picture_and_a_dimmer_one_does_not() {
        let film = gradient();
        let nudged = Film {
            pixels: film
                .pixels
                .iter()
                .map(|c| *c * (1.0 + 8.0 * Real::EPSILON))
                .collect(),
            ..film.clone()
        };
        let dimmer = Film {
            pixels: film.pixels.iter().map(|c| *c * 0.75).collect(),
            ..film.clone()
        };
        for samples in [1, 100] {
            assert!(same_picture(&film, &nudged, 2.2, samples), "{samples}");
            assert!(!same_picture(&film, &dimmer, 2.2, samples), "{samples}");
        }
        let mut spotted = film.clone();
        spotted.pixels[600] = Colour::ONE;
        assert!(same_picture(&film, &spotted, 2.2, 1), "0.2% may differ");
        spotted.pixels[600..608].fill(Colour::ONE);
        assert!(!same_picture(&film, &spotted, 2.2, 1), "8 pixels of 1200");
    }
}
