//! The diagnoses, proved: each mistake of this catalogue, written as a student
//! might, is run through its exercise's generated check, which must fail and name
//! the rule the mistake breaks. The course's crate runs them as the checklist's
//! last lines (`mistakes_sN`); a student's exercise crate, whose `course` is a crate
//! of its own, does not.

mod s1;
#[cfg(feature = "s2")]
mod s2;
#[cfg(feature = "s6")]
mod s6;
#[cfg(feature = "s7")]
mod s7;

use crate::known::Outcome;
use crate::say;

/// A mistake: its exercise, what it gets wrong, the generated check with the
/// mistaken function in place of the student's, and what the failure must say (in
/// English and in French).
pub struct Mistake {
    /// The exercise, such as `s1.1`.
    pub exercise: &'static str,
    /// The mistake, in a few words.
    pub what: &'static str,
    /// The generated check run on the mistaken function.
    pub run: fn() -> Outcome,
    /// Words the failure's message must hold: `[english, french]`.
    pub names: [&'static str; 2],
}

/// The catalogue of session `session`, in the course's order.
pub fn catalogue(session: u32) -> &'static [Mistake] {
    match session {
        1 => s1::MISTAKES,
        #[cfg(feature = "s2")]
        2 => s2::MISTAKES,
        #[cfg(feature = "s6")]
        6 => s6::MISTAKES,
        #[cfg(feature = "s7")]
        7 => s7::MISTAKES,
        _ => &[],
    }
}

/// The checklist's line for the mistakes of session `session`: each must fail its
/// generated check and name its rule.
pub fn check_session(session: u32) -> Outcome {
    for mistake in catalogue(session) {
        let [english, french] = mistake.names;
        let words = if crate::words::french() {
            french
        } else {
            english
        };
        match (mistake.run)() {
            Ok(()) => {
                return Err(say!(
                    "the mistake \"{}\" of exercise {} passes its generated check",
                    "l'erreur «\u{a0}{}\u{a0}» de l'exercice {} passe sa vérification générée",
                    mistake.what,
                    mistake.exercise
                ));
            }
            Err(why) if !why.contains(words) => {
                return Err(say!(
                    "the mistake \"{}\" of exercise {} fails without naming its rule (\"{words}\"): {why}",
                    "l'erreur «\u{a0}{}\u{a0}» de l'exercice {} échoue sans nommer sa règle («\u{a0}{words}\u{a0}»)\u{a0}: {why}",
                    mistake.what,
                    mistake.exercise
                ));
            }
            Err(_) => {}
        }
    }
    Ok(())
}
