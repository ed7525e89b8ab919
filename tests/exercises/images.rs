//! Each stage rendered small by the code under test and compared with its reference
//! image in `references/`, as `check` compares a student's image: within a few
//! display levels per pixel for a stage of one sample per pixel, within the noise,
//! block by block, for a Monte Carlo stage. Any right implementation passes: the
//! textbook formula or the robust one, any order of drawing random numbers.
//!
//! The references are this crate's renders: the deterministic stages as 8-bit PNGs,
//! the Monte Carlo ones with many more samples and another seed, as 16-bit PNGs of
//! the displayed value (256 steps per display level), so that reading them back
//! loses nothing the comparison could see.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use image::{ImageBuffer, Rgb, RgbImage};
use raycourse::check::compare::{
    Linear, brightness_ratio, compare_blocks, compare_pixels, displayed,
};
use raycourse::maths::{Real, to_double};
use raycourse::scene::Settings;
use raycourse::{Film, Overrides, Stage, render, stages};

use crate::known::Outcome;
use crate::say;
use crate::words::{decimal, separator};

/// The width and height of the Monte Carlo images compared, in pixels: five
/// blocks of 8 x 8 pixels across and three down, odd and not square, so that a
/// rule that holds only for even or square images shows.
const NOISY_SIZE: (u32, u32) = (41, 25);

/// The width and height of the deterministic images compared: odd and not square,
/// and large enough that a shaded sphere changes by fewer display levels from one
/// pixel to the next than `check` counts as an edge (where any difference is
/// allowed), and that a glass sphere's wrong exit shows in more pixels than its
/// edges.
const EXACT_SIZE: (u32, u32) = (201, 151);

/// How many times more samples a Monte Carlo reference has than the render under
/// test, which takes the course's: fewer would miss the rare paths that find a
/// small light (a stage's fireflies), and its mean with them.
const REFERENCE_FACTOR: u32 = 8;

/// The seed of the references: not the course's, so that their noise is not the
/// render's own.
const REFERENCE_SEED: u64 = 1;

/// The display levels a pixel of a deterministic stage may differ by (as `check`).
const TOLERANCE: u8 = 3;

/// The stage's line in the checklist: `s2_stage_glass`.
pub fn check_name(stage: &Stage) -> String {
    format!("s{}_stage_{}", stage.session, stage.name.replace('-', "_"))
}

/// The stage's samples per pixel at the course's settings: more than one for a
/// Monte Carlo stage, which draws random numbers.
fn course_samples(stage: &Stage) -> u32 {
    stage
        .scene(&Overrides::default())
        .expect("the stages' scene files are valid")
        .settings
        .samples
}

/// The stage rendered small (`noisy`: the size of Monte Carlo stages), with
/// `samples` per pixel and `seed`, and its settings.
fn film(stage: &Stage, noisy: bool, samples: u32, seed: Option<u64>) -> (Film, Settings) {
    let scene = stage
        .scene(&overrides(noisy, samples, seed))
        .expect("the stages' scene files are valid");
    (render(&scene).film, scene.settings)
}

/// The settings a stage line changes: the size (`noisy`: of Monte Carlo stages),
/// the samples per pixel and the seed.
fn overrides(noisy: bool, samples: u32, seed: Option<u64>) -> Overrides {
    let (width, height) = if noisy { NOISY_SIZE } else { EXACT_SIZE };
    crate::trace::overrides(width, height, samples, seed)
}

fn reference_path(stage: &Stage) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/exercises/references")
        .join(format!("{}.png", stage.name))
}

/// Renders the stage with the code under test and compares it with its reference;
/// the render is written to the test's target folder for a look when it differs.
pub fn check(stage: &Stage) -> Outcome {
    let samples = course_samples(stage);
    let noisy = samples > 1;
    let (film, settings) = film(stage, noisy, samples, None);
    let gamma = settings.gamma;
    let reference = reference_path(stage);
    let yours = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{}.png", stage.name));
    let found = if noisy {
        compare_noisy(&film, &read_16(&reference, gamma)?, &settings)
    } else {
        compare_exact(&displayed(&film, gamma), &read_8(&reference)?, gamma)
    };
    found.map_err(|why| {
        let traced = crate::trace::trace(stage, &overrides(noisy, samples, None), &film.pixels)
            .map(|found| then(&found))
            .unwrap_or_default();
        let saved = displayed(&film, gamma).save(&yours).is_ok();
        let place = if saved {
            say!("images-yours-is", yours = yours.display())
        } else {
            String::new()
        };
        say!(
            "images-the-stage-at-x-differs-from",
            stage_name = stage.name,
            film_width = film.width,
            film_height = film.height,
            reference = reference.display(),
            place = place,
            why = why,
            traced = traced
        )
    })
}

/// A deterministic stage: pixel by pixel, edges allowed, then the hints.
fn compare_exact(yours: &RgbImage, reference: &RgbImage, gamma: Real) -> Outcome {
    let outcome = compare_pixels(yours, reference, TOLERANCE);
    if !outcome.image_differs {
        return Ok(());
    }
    let (worst, at) = worst_pixel(yours, reference);
    let mut why = say!(
        "images-of-pixels-differ-by-more-than",
        d_count = outcome.differs.iter().filter(|d| **d).count(),
        outcome_differs = outcome.differs.len(),
        at = at.0,
        at2 = at.1,
        TOLERANCE = TOLERANCE,
        worst = worst
    );
    if let Some(hint) = flip_hint(yours, reference).or_else(|| gamma_hint(yours, reference, gamma))
    {
        why += &then(&hint);
    } else if let Some(hint) = brightness_hint(
        &Linear::from_rgb8(yours, gamma),
        &Linear::from_rgb8(reference, gamma),
        gamma,
        Drawn {
            bounces: false,
            light_samples: false,
        },
    ) {
        why += &then(&hint);
    }
    Err(why)
}

/// A Monte Carlo stage: block by block against the noise, then the hints.
fn compare_noisy(yours: &Film, reference: &Linear, settings: &Settings) -> Outcome {
    let gamma = settings.gamma;
    let linear = Linear::from_film(yours, gamma);
    let outcome = compare_blocks(&linear, reference, gamma);
    if !outcome.image_differs {
        return Ok(());
    }
    let mut why = say!(
        "images-of-blocks-of-8-x-8",
        d_count = outcome.differs.iter().filter(|d| **d).count(),
        outcome_differs = outcome.differs.len()
    );
    let shown = displayed(yours, gamma);
    let reference_shown = to_rgb8(reference, gamma);
    if let Some(hint) = flip_hint(&shown, &reference_shown)
        .or_else(|| brightness_hint(&linear, reference, gamma, Drawn::of(settings)))
    {
        why += &then(&hint);
    }
    Err(why)
}

/// `; hint`, a hint after what differs, in the checklist's language.
fn then(hint: &str) -> String {
    say!("images-message", hint = hint)
}

/// The largest difference of a channel, and where.
fn worst_pixel(yours: &RgbImage, reference: &RgbImage) -> (u8, (u32, u32)) {
    let mut worst = (0, (0, 0));
    for (x, y, p) in yours.enumerate_pixels() {
        let q = reference.get_pixel(x, y);
        let d = (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0);
        if d > worst.0 {
            worst = (d, (x, y));
        }
    }
    worst
}

/// The mistake an upside-down or mirrored image shows.
fn flip_hint(yours: &RgbImage, reference: &RgbImage) -> Option<String> {
    let upside_down = image::imageops::flip_vertical(yours);
    let mirrored = image::imageops::flip_horizontal(yours);
    if !compare_pixels(&upside_down, reference, 2 * TOLERANCE).image_differs {
        Some(say!("images-it-is-the-reference-upside-down"))
    } else if !compare_pixels(&mirrored, reference, 2 * TOLERANCE).image_differs {
        Some(say!("images-it-is-the-reference-mirrored-left"))
    } else {
        None
    }
}

/// The mistake an image without its gamma, or with it twice, shows.
fn gamma_hint(yours: &RgbImage, reference: &RgbImage, gamma: Real) -> Option<String> {
    if gamma == 1.0 {
        return None;
    }
    let remap = |power: f64| {
        let mut image = reference.clone();
        for v in image.iter_mut() {
            let linear = f64::from(*v).powf(to_double(gamma));
            *v = linear.powf(power).round().min(255.0) as u8;
        }
        image
    };
    let g = to_double(gamma);
    if !compare_pixels(yours, &remap(1.0), 2 * TOLERANCE).image_differs {
        let gamma = decimal(gamma.to_string());
        Some(say!(
            "images-it-shows-the-radiance-without-the",
            gamma = gamma
        ))
    } else if !compare_pixels(yours, &remap(1.0 / (g * g)), 2 * TOLERANCE).image_differs {
        Some(say!("images-the-display-s-gamma-is-applied"))
    } else {
        None
    }
}

/// What a stage draws at random, which decides the hints its brightness may get.
#[derive(Clone, Copy)]
struct Drawn {
    /// Bounce directions (indirect light).
    bounces: bool,
    /// Directions towards a sphere light (light sampling).
    light_samples: bool,
}

impl Drawn {
    /// What a stage with `settings` draws.
    fn of(settings: &Settings) -> Drawn {
        Drawn {
            bounces: settings.indirect,
            light_samples: settings.light_sampling,
        }
    }
}

/// The mistake an image brighter or darker everywhere by a telling factor shows; a
/// hint names a density only where the stage draws with it (`drawn`).
fn brightness_hint(
    yours: &Linear,
    reference: &Linear,
    gamma: Real,
    drawn: Drawn,
) -> Option<String> {
    let ratio = brightness_ratio(yours, reference, gamma);
    let mean = ratio.iter().sum::<f64>() / 3.0;
    let near = |target: f64| (mean / target - 1.0).abs() < 0.08;
    let pi = std::f64::consts::PI;
    let hint = if near(pi) {
        say!("images-about-pi-times-too-bright-a")
    } else if near(1.0 / pi) && drawn.bounces {
        say!("images-about-pi-times-too-dark-is")
    } else if near(1.0 / pi) {
        say!("images-about-pi-times-too-dark-is-2")
    } else if drawn.light_samples && (near(2.0) || near(0.5)) {
        say!("images-about-twice-too-bright-or-too")
    } else if drawn.bounces && (near(2.0) || near(0.5)) {
        say!("images-about-twice-too-bright-or-too-2")
    } else if (mean - 1.0).abs() > 0.05 {
        let percent = format!("{:.0}", (mean - 1.0).abs() * 100.0);
        let [r, g, b] = ratio.map(|x| decimal(format!("{x:.2}")));
        let s = separator();
        return Some(if mean > 1.0 {
            say!(
                "images-brighter-than-the-reference-overall-per",
                percent = percent,
                r = r,
                g = g,
                b = b,
                s = s
            )
        } else {
            say!(
                "images-darker-than-the-reference-overall-per",
                percent = percent,
                r = r,
                g = g,
                b = b,
                s = s
            )
        });
    } else {
        return None;
    };
    let mean = decimal(format!("{mean:.2}"));
    Some(say!(
        "images-brightness-against-the-reference-x",
        hint = hint,
        mean = mean
    ))
}

/// A 16-bit reference read back to linear radiance through its stage's `gamma`:
/// `L = (v / 256)^gamma`.
fn read_16(path: &Path, gamma: Real) -> Result<Linear, String> {
    let image = image::open(path)
        .map_err(|e| unreadable(path, &e))?
        .into_rgb16();
    let gamma = to_double(gamma);
    Ok(Linear {
        width: image.width(),
        height: image.height(),
        values: image
            .as_raw()
            .iter()
            .map(|&v| (f64::from(v) / 256.0).powf(gamma))
            .collect(),
    })
}

fn read_8(path: &Path) -> Result<RgbImage, String> {
    Ok(image::open(path)
        .map_err(|e| unreadable(path, &e))?
        .into_rgb8())
}

/// A reference that cannot be read: `path: error`.
fn unreadable(path: &Path, error: &image::ImageError) -> String {
    say!("images-message-2", path = path.display(), error = error)
}

/// A linear picture as the display shows it, 8 bits.
fn to_rgb8(linear: &Linear, gamma: Real) -> RgbImage {
    let g = to_double(gamma);
    let rgb = linear
        .values
        .iter()
        .map(|v| v.max(0.0).powf(1.0 / g).round().min(255.0) as u8)
        .collect();
    RgbImage::from_raw(linear.width, linear.height, rgb).expect("width x height pixels")
}

/// A film as a 16-bit image of its displayed value: `min(255, L^(1/gamma)) * 256`.
fn to_rgb16(film: &Film, gamma: Real) -> ImageBuffer<Rgb<u16>, Vec<u16>> {
    let g = to_double(gamma);
    let values = film
        .pixels
        .iter()
        .flat_map(|p| p.to_array())
        .map(|v| {
            (to_double(v).max(0.0).powf(1.0 / g).min(255.0) * 256.0)
                .round()
                .min(65535.0) as u16
        })
        .collect();
    ImageBuffer::from_raw(film.width, film.height, values).expect("width x height pixels")
}

/// Writes every stage's reference (`cargo test --test exercises -- --write-references`).
pub fn write_references() -> ExitCode {
    for stage in stages() {
        let path = reference_path(stage);
        let samples = course_samples(stage);
        let written = if samples > 1 {
            let more = samples * REFERENCE_FACTOR;
            let (film, settings) = film(stage, true, more, Some(REFERENCE_SEED));
            to_rgb16(&film, settings.gamma).save(&path)
        } else {
            let (film, settings) = film(stage, false, 1, None);
            displayed(&film, settings.gamma).save(&path)
        };
        match written {
            Ok(()) => println!("{}", path.display()),
            Err(e) => {
                eprintln!("{}: {e}", path.display());
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}
