//! The course's answer on generated inputs. Each exercise whose answer is a function
//! of its inputs is compared, beyond its worked answers, with the course's own
//! function (the crate `course`: in a student's exercise crate, the course's answers
//! in `tests/course/`; in the course's crate, the crate itself) on a few hundred
//! inputs that reach the awkward cases on purpose: odd and non-square images, the
//! border pixels, scales from `1e-4` to `1e4`, objects `1e8` away, rays from inside,
//! grazing or lying in a face, `-0`, ties, non-square textures, cameras aimed off the
//! origin, degenerate triangles.
//!
//! The inputs come from proptest with a fixed seed, so that every run tries the
//! same ones; a failure is shrunk to the simplest input that still fails and
//! printed in the book's notation, with both answers and the rule of the chapter
//! the difference breaks (each exercise's diagnoses).

mod s1;
#[cfg(feature = "s2")]
mod s2;
#[cfg(feature = "s3")]
mod s3;
#[cfg(feature = "s4")]
mod s4;
#[cfg(feature = "s5")]
mod s5;
#[cfg(feature = "s6")]
mod s6;
#[cfg(feature = "s7")]
mod s7;
#[cfg(feature = "s3")]
mod sampling;

pub use s1::*;
#[cfg(feature = "s2")]
pub use s2::*;
#[cfg(feature = "s3")]
pub use s3::*;
#[cfg(feature = "s4")]
pub use s4::*;
#[cfg(feature = "s5")]
pub use s5::*;
#[cfg(feature = "s6")]
pub use s6::*;
#[cfg(feature = "s7")]
pub use s7::*;

use proptest::strategy::{BoxedStrategy, Strategy};
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};
use raycourse::maths::{Real, Vec3};

use crate::known::Outcome;
use crate::say;
use crate::words::{decimal, separator};

/// The environment variable that leaves the generated inputs out, so that only the
/// worked answers run: how `.ci/exercises` proves that a mistake passes them all
/// and only the generated inputs catch it.
const KNOWN_ONLY: &str = "RAYCOURSE_KNOWN_ONLY";

/// How many inputs each exercise is tried on.
const CASES: u32 = 400;

/// The seed of every run: the same inputs each time, on every machine.
const SEED: [u8; 32] = *b"raycourse: the course's answers.";

/// Runs `compare` on `CASES` inputs drawn from `inputs`; on a difference, proptest
/// shrinks the input to the simplest that still differs and the outcome is that
/// case's message, after `what` (the exercise's function).
pub fn on_generated<S: Strategy + 'static>(
    what: &str,
    inputs: S,
    compare: impl Fn(S::Value) -> Result<(), String>,
) -> Outcome {
    on_generated_cases(what, CASES, inputs, compare)
}

/// [`on_generated`] on `cases` inputs: fewer for the checks whose every input
/// costs thousands of samples.
pub fn on_generated_cases<S: Strategy + 'static>(
    what: &str,
    cases: u32,
    inputs: S,
    compare: impl Fn(S::Value) -> Result<(), String>,
) -> Outcome {
    run_cases(what, cases, inputs.boxed(), &compare)
}

/// [`on_generated_cases`] on a boxed strategy and a comparison behind a reference:
/// proptest's runner is compiled once for each type of input rather than once for
/// each check, which keeps the checklist quick to build.
fn run_cases<T: std::fmt::Debug>(
    what: &str,
    cases: u32,
    inputs: BoxedStrategy<T>,
    compare: &dyn Fn(T) -> Result<(), String>,
) -> Outcome {
    if std::env::var_os(KNOWN_ONLY).is_some() {
        return Ok(());
    }
    let config = Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: 4096,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &SEED));
    match runner.run(&inputs, |input| compare(input).map_err(TestCaseError::fail)) {
        Ok(()) => Ok(()),
        Err(TestError::Fail(why, _)) => Err(say!(
            "generated-common-on-a-generated-input-the-simplest",
            why_message = why.message(),
            what = what
        )),
        Err(TestError::Abort(why)) => Err(why.message().to_owned()),
    }
}

/// Runs `check`, a sampler's test on generated numbers, unless only the worked
/// answers are to run; a failure is prefixed with `what` (the exercise's function).
#[cfg(feature = "s3")]
pub fn on_draws(what: &str, check: impl FnOnce() -> Result<(), String>) -> Outcome {
    if std::env::var_os(KNOWN_ONLY).is_some() {
        return Ok(());
    }
    check().map_err(|why| {
        say!(
            "generated-common-on-generated-numbers",
            what = what,
            why = why
        )
    })
}

/// A number with up to six significant digits, as the book writes it (`0.5`, `-3`,
/// `1.5e-4`), with the language's decimal mark; `-0` kept, since a sign can matter.
pub fn n(x: Real) -> String {
    let text = if x == 0.0 {
        if x.is_sign_negative() {
            "-0".into()
        } else {
            "0".into()
        }
    } else if !x.is_finite() {
        format!("{x}")
    } else if (1e-3..1e6).contains(&x.abs()) {
        significant(x, 6)
    } else {
        let text = format!("{x:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    };
    decimal(text)
}

/// Two numbers written with the fewest significant digits, six or more, that tell
/// them apart (`2.03166e7` and `2.03166e7` become `20316612.95` and `20316613.04`),
/// or as [`n`] writes them when nothing does.
pub fn apart(a: Real, b: Real) -> (String, String) {
    for digits in 6..=17 {
        let (x, y) = (significant(a, digits), significant(b, digits));
        if x != y {
            return (decimal(x), decimal(y));
        }
    }
    (n(a), n(b))
}

/// `x` with `digits` significant digits, trailing zeros dropped.
fn significant(x: Real, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let decimals = (digits as i32 - 1 - x.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// A vector in the book's notation, with six significant digits a component.
pub fn v(x: Vec3) -> String {
    let s = separator();
    format!("({}{s}{}{s}{})", n(x.x), n(x.y), n(x.z))
}

/// Whether `gave` is within `tolerance` of `expected`, relative to `scale`.
pub fn near(gave: Real, expected: Real, scale: Real, tolerance: Real) -> bool {
    (gave - expected).abs() <= tolerance * scale.abs().max(Real::MIN_POSITIVE)
}

/// Whether two vectors agree within `tolerance`, relative to the longer.
pub fn near_vec(gave: Vec3, expected: Vec3, tolerance: Real) -> bool {
    let scale = gave.length().max(expected.length());
    (gave - expected).length() <= tolerance * scale.max(Real::MIN_POSITIVE)
}

/// A tolerance of `k` roundings of the build's numbers: `k * 2^-52` in double
/// precision, `k * 2^-23` in single.
pub fn ulps(k: Real) -> Real {
    k * Real::EPSILON
}

/// A message `yours gave G, the course's gives E`, then why, when a diagnosis found it.
pub fn differs(case: &str, gave: &str, expected: &str, why: Option<String>) -> String {
    let why = why
        .map(|w| say!("generated-common-message", w = w))
        .unwrap_or_default();
    say!(
        "generated-common-yours-gave-the-course-s-gives",
        case = case,
        gave = gave,
        expected = expected,
        why = why
    )
}
