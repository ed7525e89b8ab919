//! The checker's answer: whether a student's image is the stage's, the figures
//! behind the verdict, where it differs and the likely mistake.

use image::{Rgb, RgbImage};

use crate::check::compare::{
    Linear, Outcome, brightness_ratio, compare_blocks, compare_pixels, compare_pixels_near_edges,
    displayed,
};
use crate::check::expected::{Expected, Source};
use crate::check::mistakes::{Candidates, MISTAKES, Mistake, best_explanation};
use crate::check::regions::object_names;
use crate::scene_file::SceneError;

/// Whether an image is a stage's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// It is, within the tolerance and the noise.
    Matches,
    /// It is not.
    Differs,
}

/// What the checker found.
#[derive(Clone, Debug)]
pub struct Report {
    /// The verdict.
    pub verdict: Verdict,
    /// Per channel, the student's brightness over the stage's.
    pub ratio: [f64; 3],
    /// The comparison, pixel by pixel or block by block.
    pub outcome: Outcome,
    /// Where it differs: each object and each half of the image, with the share of
    /// its pixels (or blocks) that differ, the largest first; only those that differ.
    pub regions: Vec<(String, f64)>,
    /// For a Monte Carlo stage: the student's noise variance over a render's at the
    /// course's samples, and those samples.
    pub noise: Option<(f64, u32)>,
    /// The mistake that explains the difference, if one does.
    pub hint: Option<&'static Mistake>,
}

/// Checks the student's `image` (8 bits per channel; `lossy` for a JPEG, whose
/// compression moves pixels by a few levels) against the stage of `source`.
pub fn check(source: &Source, image: &RgbImage, lossy: bool) -> Result<Report, SceneError> {
    let expected = source.expected()?;
    let gamma = expected.scene.settings.gamma;
    let film = expected.film();
    let linear = Linear::from_rgb8(image, gamma);
    let reference = Linear::from_film(&film, gamma);
    let mut outcome = if expected.deterministic {
        let expected = displayed(&film, gamma);
        match lossy {
            true => compare_pixels_near_edges(image, &expected, 20, 1),
            false => compare_pixels(image, &expected, 3),
        }
    } else {
        compare_blocks(&linear, &reference, gamma)
    };
    let noise = noise(&expected, &linear);
    if outcome.image_differs
        && let Some((ratio, samples)) = noise
        && ratio > 1.5
    {
        outcome = at_students_samples(source, &linear, (ratio, samples), gamma)?;
    }
    let candidates = Candidates {
        source,
        expected: &expected,
        film: film.clone(),
        student: image,
    };
    let moved = expected.deterministic && !lossy && moved_a_pixel(&candidates, &outcome, gamma);
    let verdict = if outcome.image_differs || moved {
        Verdict::Differs
    } else {
        Verdict::Matches
    };
    let hint = match verdict {
        Verdict::Differs if moved => MISTAKES.iter().find(|m| m.id == "shifted-a-pixel"),
        Verdict::Differs => best_explanation(&candidates, outcome.share())?,
        Verdict::Matches => None,
    };
    Ok(Report {
        verdict,
        ratio: brightness_ratio(&linear, &reference, gamma),
        regions: regions(&expected, &outcome),
        noise,
        outcome,
        hint,
    })
}

/// Whether a deterministic image that passes thanks to the allowance at the edges
/// is rather the reference moved by one pixel, as a pixel loop off by one makes it:
/// more than 0.5% of its pixels (edges included) differ from the reference, and
/// four times fewer from the moved one.
fn moved_a_pixel(candidates: &Candidates, outcome: &Outcome, gamma: crate::maths::Real) -> bool {
    let count = |o: &Outcome| o.differs.iter().filter(|d| **d).count();
    let here = count(outcome);
    if outcome.image_differs || here as f64 <= 0.005 * outcome.differs.len() as f64 {
        return false;
    }
    let moved = displayed(&candidates.shifted(), gamma);
    4 * count(&compare_pixels(candidates.student, &moved, 3)) < here
}

/// The comparison of a noisier image than the course's, whose noise variance is
/// `ratio` times that of `samples` per pixel, with two renders at the samples it
/// seems to have, each clipped to full white as the student's is: a noisy pixel
/// that clips loses light, and an unbiased render at those samples loses as much.
/// The estimate of the samples is rough where pixels clip, so half and twice as
/// many are tried too: the image passes if it fits one of them.
fn at_students_samples(
    source: &Source,
    student: &Linear,
    (ratio, samples): (f64, u32),
    gamma: crate::maths::Real,
) -> Result<Outcome, SceneError> {
    let estimate = (f64::from(samples) / ratio).max(1.0);
    let mut tries =
        [estimate, estimate / 2.0, estimate * 2.0].map(|s| (s.round() as u32).clamp(1, samples));
    tries.sort_unstable();
    let mut last = None;
    for fewer in tries {
        let films = source.halves(fewer)?;
        let reference =
            Linear::from_film(&films[0], gamma).mean(&Linear::from_film(&films[1], gamma));
        let outcome = compare_blocks(student, &reference, gamma);
        if !outcome.image_differs {
            return Ok(outcome);
        }
        last = Some(outcome);
    }
    Ok(last.expect("three tries"))
}

/// The regions that differ, with their share of differing cells, largest first.
fn regions(expected: &Expected, outcome: &Outcome) -> Vec<(String, f64)> {
    let names = object_names(&expected.scene);
    let camera = expected.scene.camera;
    let mut tally: Vec<(String, usize, usize)> = vec![];
    for (k, differs) in outcome.differs.iter().enumerate() {
        let (cx, cy) = (k as u32 % outcome.columns, k as u32 / outcome.columns);
        let (x, y) = (
            cx * outcome.cell + outcome.cell / 2,
            cy * outcome.cell + outcome.cell / 2,
        );
        let half = if y < camera.height / 2 {
            "top-half"
        } else {
            "bottom-half"
        };
        for name in [names[(y * camera.width + x) as usize], half] {
            match tally.iter_mut().find(|t| t.0 == name) {
                Some(t) => {
                    t.1 += 1;
                    t.2 += usize::from(*differs);
                }
                None => tally.push((name.to_owned(), 1, usize::from(*differs))),
            }
        }
    }
    let mut shares: Vec<(String, f64)> = tally
        .into_iter()
        .filter(|t| t.2 > 0)
        .map(|(name, all, differing)| (name, differing as f64 / all as f64))
        .collect();
    shares.sort_by(|a, b| b.1.total_cmp(&a.1));
    shares
}

/// For a Monte Carlo stage, the student's noise variance over the course's, and the
/// course's samples: the pixels' spread about the reference, less the reference's own
/// share, which the difference of its two halves measures. Only the pixels whose
/// reference is neither black nor clipped to full white tell: the others are the
/// same in every render, or show only whether a sample found the light.
fn noise(expected: &Expected, student: &Linear) -> Option<(f64, u32)> {
    let [a, b] = &expected.films[..] else {
        return None;
    };
    let gamma = expected.scene.settings.gamma;
    let (a, b) = (Linear::from_film(a, gamma), Linear::from_film(b, gamma));
    let white = 255f64.powf(crate::maths::to_double(gamma)) * 0.999;
    let (mut own, mut course) = (0.0, 0.0);
    for ((s, a), b) in student.values.iter().zip(&a.values).zip(&b.values) {
        let mean = (a + b) / 2.0;
        if mean > 0.0 && mean < white {
            own += (s - mean).powi(2) - (a - b).powi(2) / 4.0;
            course += (a - b).powi(2) / 4.0;
        }
    }
    (course > 0.0).then(|| (own.max(0.0) / course, expected.scene.settings.samples))
}

impl Report {
    /// A picture of the differences: the student's image dimmed, with each
    /// differing pixel or block painted red.
    pub fn difference_image(&self, image: &RgbImage) -> RgbImage {
        let o = &self.outcome;
        RgbImage::from_fn(image.width(), image.height(), |x, y| {
            let cell = (y / o.cell) * o.columns + x / o.cell;
            if o.differs.get(cell as usize).copied().unwrap_or(false) {
                Rgb([230, 30, 30])
            } else {
                Rgb(image.get_pixel(x, y).0.map(|v| v / 3))
            }
        })
    }
}
