//! The diagnoses, proved: each mistake of this catalogue, written as a student
//! might, is run through its exercise's generated check, which must fail and name
//! the rule the mistake breaks. The course's crate runs them as the checklist's
//! last lines (`mistakes_sN`); a student's exercise crate, whose `course` is a crate
//! of its own, does not. Beside them, right answers written otherwise than the
//! course's (another frame, another map of the square, no widened exit), which the
//! same checks must pass: they hold the tolerances to what the chapters allow.

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

use crate::known::Outcome;
use crate::say;

/// A mistake: its exercise, what it gets wrong, the generated check with the
/// mistaken function in place of the student's, and the rule its failure must name.
pub struct Mistake {
    /// The exercise, such as `s1.1`.
    pub exercise: &'static str,
    /// The mistake, in a few words.
    pub what: &'static str,
    /// The generated check run on the mistaken function.
    pub run: fn() -> Outcome,
    /// The catalogue's message (`messages/<code>/checklist.ftl`, `rule-...`) whose
    /// words the failure's message must hold, in the checklist's language.
    pub rule: &'static str,
}

/// A right answer written otherwise than the course's: its exercise, how it
/// differs, and its generated check, which it must pass.
pub struct Right {
    /// The exercise, such as `s3.2`.
    pub exercise: &'static str,
    /// How it differs from the course's answer, in a few words.
    pub what: &'static str,
    /// The generated check run on it.
    pub run: fn() -> Outcome,
}

/// The catalogue of session `session`, in the course's order.
pub fn catalogue(session: u32) -> &'static [Mistake] {
    match session {
        1 => s1::MISTAKES,
        #[cfg(feature = "s2")]
        2 => s2::MISTAKES,
        #[cfg(feature = "s3")]
        3 => s3::MISTAKES,
        #[cfg(feature = "s4")]
        4 => s4::MISTAKES,
        #[cfg(feature = "s5")]
        5 => s5::MISTAKES,
        #[cfg(feature = "s6")]
        6 => s6::MISTAKES,
        #[cfg(feature = "s7")]
        7 => s7::MISTAKES,
        _ => &[],
    }
}

/// The right answers of session `session` written otherwise than the course's.
pub fn right_answers(session: u32) -> &'static [Right] {
    match session {
        1 => s1::RIGHT,
        #[cfg(feature = "s2")]
        2 => s2::RIGHT,
        #[cfg(feature = "s3")]
        3 => s3::RIGHT,
        #[cfg(feature = "s4")]
        4 => s4::RIGHT,
        #[cfg(feature = "s5")]
        5 => s5::RIGHT,
        _ => &[],
    }
}

/// The checklist's line for the mistakes of session `session`: each must fail its
/// generated check and name its rule, and each right answer written otherwise
/// must pass it.
pub fn check_session(session: u32) -> Outcome {
    for right in right_answers(session) {
        (right.run)().map_err(|why| {
            say!(
                "mistakes-common-the-right-answer-of-exercise-fails",
                right_what = right.what,
                right_exercise = right.exercise,
                why = why
            )
        })?;
    }
    for mistake in catalogue(session) {
        let words = crate::words::message(mistake.rule, &[]);
        match (mistake.run)() {
            Ok(()) => {
                return Err(say!(
                    "mistakes-common-the-mistake-of-exercise-passes-its",
                    mistake_what = mistake.what,
                    mistake_exercise = mistake.exercise
                ));
            }
            Err(why) if !why.contains(&words) => {
                return Err(say!(
                    "mistakes-common-the-mistake-of-exercise-fails-without",
                    mistake_what = mistake.what,
                    mistake_exercise = mistake.exercise,
                    words = words,
                    why = why
                ));
            }
            Err(_) => {}
        }
    }
    Ok(())
}
