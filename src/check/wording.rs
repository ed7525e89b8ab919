//! What the checker says: a report as the lines `raycourse check` prints, which the
//! book's check page shows too, in the reader's language. The sentences are the
//! catalogue's (`messages/*/check.ftl`); this chooses which, with what figures.

use crate::check::report::{Report, Verdict};
use crate::messages::language::Language;
use crate::messages::say;
use crate::scene_file::Stage;

impl Report {
    /// The report on a student's image of `stage` in words: the verdict and the share
    /// of pixels (or blocks) that differ, the brightness ratio per channel, where it
    /// differs, for a Monte Carlo stage the noise against the course's, and the hint.
    pub fn lines(&self, stage: &Stage, language: Language) -> Vec<String> {
        let verdict = match self.verdict {
            Verdict::Matches => "check-matches",
            Verdict::Differs => "check-differs",
        };
        let share = 100.0 * self.outcome.share();
        let [red, green, blue] = self.ratio;
        let mut lines = vec![
            say(
                language,
                verdict,
                &[
                    ("stage", stage.name.into()),
                    ("share", share.into()),
                    ("cell", self.outcome.cell.into()),
                ],
            ),
            say(
                language,
                "check-brightness",
                &[
                    ("red", red.into()),
                    ("green", green.into()),
                    ("blue", blue.into()),
                ],
            ),
        ];
        lines.extend(self.where_line(language));
        lines.extend(self.noise_line(language));
        lines.extend(self.hint_line(stage, language));
        lines
    }

    /// For a differing image, the objects and halves of the image where it differs,
    /// with the share of each that differs.
    fn where_line(&self, language: Language) -> Option<String> {
        if self.verdict != Verdict::Differs {
            return None;
        }
        let places: Vec<String> = self
            .regions
            .iter()
            .take(5)
            .map(|(place, share)| {
                let place = say(language, &format!("place-{place}"), &[]);
                let share = 100.0 * share;
                say(
                    language,
                    "check-place",
                    &[("place", place.into()), ("share", share.into())],
                )
            })
            .collect();
        let places = places.join(&say(language, "check-place-separator", &[]));
        Some(say(language, "check-where", &[("places", places.into())]))
    }

    /// For a matching Monte Carlo image, its noise against a render at the course's
    /// samples, and the samples it seems to have.
    fn noise_line(&self, language: Language) -> Option<String> {
        let (ratio, samples) = self.noise.filter(|_| self.verdict == Verdict::Matches)?;
        let equivalent = (f64::from(samples) / ratio.max(1e-9)).min(1e6);
        let arguments = [
            ("ratio", ratio.into()),
            ("samples", samples.into()),
            ("equivalent", equivalent.into()),
        ];
        Some(say(language, "check-noise", &arguments))
    }

    /// The hint: the classic mistake that explains the difference, or where to look
    /// when none does.
    fn hint_line(&self, stage: &Stage, language: Language) -> Option<String> {
        match self.hint {
            Some(mistake) => {
                let [name, hint] = mistake.words(language);
                let arguments = [("name", name.into()), ("hint", hint.into())];
                Some(say(language, "check-hint", &arguments))
            }
            None if self.verdict == Verdict::Matches => None,
            None => {
                let command = format!(
                    "raycourse s{} {} --out reference.png",
                    stage.session, stage.name
                );
                Some(say(
                    language,
                    "check-no-hint",
                    &[("command", command.into())],
                ))
            }
        }
    }
}
