//! What the checker says: a report as the lines `raycourse check` prints, which the
//! book's check page shows too, in English or in French.

use crate::check::language::Language;
use crate::check::report::{Report, Verdict};
use crate::scene_file::Stage;

impl Report {
    /// The report on a student's image of `stage` in words: the verdict and the share
    /// of pixels (or blocks) that differ, the brightness ratio per channel, where it
    /// differs, for a Monte Carlo stage the noise against the course's, and the hint.
    pub fn lines(&self, stage: &Stage, language: Language) -> Vec<String> {
        let say = |english, french| language.pick(english, french);
        let unit = if self.outcome.cell == 1 {
            say("pixels", "des pixels")
        } else {
            say("blocks of 8 x 8 pixels", "des blocs de 8 × 8 pixels")
        };
        let share = language.number(100.0 * self.outcome.share(), 1);
        let name = stage.name;
        let mut lines = vec![match (self.verdict, language) {
            (Verdict::Matches, Language::English) => {
                format!("{name}: matches ({share}% of {unit} differ, within what is allowed)")
            }
            (Verdict::Matches, Language::French) => format!(
                "{name}\u{a0}: correspond ({share}\u{a0}% {unit} diffèrent, dans la tolérance)"
            ),
            (Verdict::Differs, Language::English) => {
                format!("{name}: differs ({share}% of {unit} differ)")
            }
            (Verdict::Differs, Language::French) => {
                format!("{name}\u{a0}: diffère ({share}\u{a0}% {unit} diffèrent)")
            }
        }];
        let [r, g, b] = self.ratio.map(|x| language.number(x, 2));
        lines.push(match language {
            Language::English => {
                format!("  brightness against the reference: red x{r}, green x{g}, blue x{b}")
            }
            Language::French => format!(
                "  luminosité par rapport à la référence\u{a0}: rouge ×\u{a0}{r}, vert ×\u{a0}{g}, bleu ×\u{a0}{b}"
            ),
        });
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
            .map(|(name, s)| {
                let share = language.number(100.0 * s, 0);
                match language {
                    Language::English => format!("{name} ({share}%)"),
                    Language::French => format!("{} ({share}\u{a0}%)", french_place(name)),
                }
            })
            .collect();
        let label = language.pick("  where: ", "  où\u{a0}: ");
        Some(format!("{label}{}", places.join(", ")))
    }

    /// For a matching Monte Carlo image, its noise against a render at the course's
    /// samples, and the samples it seems to have.
    fn noise_line(&self, language: Language) -> Option<String> {
        let (ratio, samples) = self.noise.filter(|_| self.verdict == Verdict::Matches)?;
        let equivalent = language.number((f64::from(samples) / ratio.max(1e-9)).min(1e6), 0);
        let ratio = language.number(ratio, 2);
        Some(match language {
            Language::English => format!(
                "  noise: {ratio} times the variance of a render at the course's {samples} samples per pixel (as from about {equivalent} samples)"
            ),
            Language::French => format!(
                "  bruit\u{a0}: {ratio} fois la variance d'un rendu aux {samples} échantillons par pixel du cours (comme avec environ {equivalent} échantillons)"
            ),
        })
    }

    /// The hint: the classic mistake that explains the difference, or where to look
    /// when none does.
    fn hint_line(&self, stage: &Stage, language: Language) -> Option<String> {
        let command = format!(
            "raycourse s{} {} --out reference.png",
            stage.session, stage.name
        );
        match (self.hint, language) {
            (Some(mistake), _) => {
                let [name, hint] = mistake.words(language);
                let label = language.pick("hint", "indice");
                let colon = language.pick(":", "\u{a0}:");
                Some(format!("  {label} ({name}){colon} {hint}"))
            }
            (None, _) if self.verdict == Verdict::Matches => None,
            (None, Language::English) => Some(format!(
                "  hint: no classic mistake explains the difference; compare with `{command}`"
            )),
            (None, Language::French) => Some(format!(
                "  indice\u{a0}: aucune erreur classique n'explique la différence\u{a0}; comparez avec `{command}`"
            )),
        }
    }
}

/// A place of the image, as `regions` names it in English, in French.
fn french_place(name: &str) -> &str {
    match name {
        "the background" => "le fond",
        "the light" => "la source",
        "the mesh" => "le maillage",
        "the sphere" => "la sphère",
        "the floor" => "le sol",
        "the ceiling" => "le plafond",
        "the left wall" => "le mur de gauche",
        "the right wall" => "le mur de droite",
        "the back wall" => "le mur du fond",
        "the wall behind the camera" => "le mur derrière la caméra",
        "a wall" => "un mur",
        "the top half" => "la moitié haute",
        "the bottom half" => "la moitié basse",
        other => other,
    }
}
