//! What the checker says: a report as the lines `raycourse check` prints, which the
//! book's check page shows too.

use crate::check::report::{Report, Verdict};
use crate::scene_file::Stage;

impl Report {
    /// The report on a student's image of `stage` in words: the verdict and the share
    /// of pixels (or blocks) that differ, the brightness ratio per channel, where it
    /// differs, for a Monte Carlo stage the noise against the course's, and the hint.
    pub fn lines(&self, stage: &Stage) -> Vec<String> {
        let unit = if self.outcome.cell == 1 {
            "pixels"
        } else {
            "blocks of 8 x 8 pixels"
        };
        let share = 100.0 * self.outcome.share();
        let mut lines = vec![match self.verdict {
            Verdict::Matches => format!(
                "{}: matches ({share:.1}% of {unit} differ, within what is allowed)",
                stage.name
            ),
            Verdict::Differs => format!("{}: differs ({share:.1}% of {unit} differ)", stage.name),
        }];
        let [r, g, b] = self.ratio;
        lines.push(format!(
            "  brightness against the reference: red x{r:.2}, green x{g:.2}, blue x{b:.2}"
        ));
        if self.verdict == Verdict::Differs {
            let places: Vec<String> = self
                .regions
                .iter()
                .take(5)
                .map(|(name, s)| format!("{name} ({:.0}%)", 100.0 * s))
                .collect();
            lines.push(format!("  where: {}", places.join(", ")));
        }
        lines.extend(self.noise_line());
        lines.extend(self.hint_line(stage));
        lines
    }

    /// For a matching Monte Carlo image, its noise against a render at the course's
    /// samples, and the samples it seems to have.
    fn noise_line(&self) -> Option<String> {
        let (ratio, samples) = self.noise.filter(|_| self.verdict == Verdict::Matches)?;
        let equivalent = f64::from(samples) / ratio.max(1e-9);
        Some(format!(
            "  noise: {ratio:.2} times the variance of a render at the course's {samples} samples per pixel (as from about {:.0} samples)",
            equivalent.min(1e6)
        ))
    }

    /// The hint: the classic mistake that explains the difference, or where to look
    /// when none does.
    fn hint_line(&self, stage: &Stage) -> Option<String> {
        match self.hint {
            Some(mistake) => Some(format!("  hint ({}): {}", mistake.name, mistake.hint)),
            None if self.verdict == Verdict::Differs => Some(format!(
                "  hint: no classic mistake explains the difference; compare with `raycourse s{} {} --out reference.png`",
                stage.session, stage.name
            )),
            None => None,
        }
    }
}
