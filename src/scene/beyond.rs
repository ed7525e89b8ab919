//! Settings beyond the course (session 3 on): how a pixel's samples are placed, how
//! many it takes, and whether the fast engine renders. Without them every stage runs
//! the course's code; the code that uses them stands apart from it (`src/samplers/`
//! and `src/fast/`).

use crate::maths::Real;

/// How the random numbers of a pixel's samples are chosen (`[render] sampler`:
/// `"independent"`, `"stratified"` or `"sobol"`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Sampler {
    /// Each number drawn independently of all others: the course's choice.
    #[default]
    Independent,
    /// Each decision's range cut into as many equal strata as the pixel has
    /// samples, one sample in each, at a random place inside it.
    Stratified,
    /// Owen-scrambled Sobol points: spread evenly at every scale at once.
    Sobol,
}

/// What a render uses beyond the course: `[render] sampler`, `noise` and `fast`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Beyond {
    /// How the random numbers of the samples are chosen.
    pub sampler: Sampler,
    /// Adaptive sampling: a pixel takes samples until the estimated relative
    /// standard error of its mean falls below `noise`, up to four times the scene's
    /// count; `None`: every pixel takes the scene's count.
    pub noise: Option<Real>,
    /// Whether the fast engine renders (`--fast`): the same bytes as the course's
    /// functions, in less time.
    pub fast: bool,
}

impl Beyond {
    /// What a render with these settings uses beyond the course, in words, if
    /// anything: another sampler, adaptive sampling, the fast engine.
    pub fn beyond_the_course(&self) -> Option<String> {
        let mut what = vec![];
        if self.sampler != Sampler::Independent {
            what.push(format!("the sampler {:?}", self.sampler));
        }
        if let Some(noise) = self.noise {
            what.push(format!("adaptive sampling (noise {noise})"));
        }
        if self.fast {
            what.push("the fast engine (--fast)".into());
        }
        (!what.is_empty()).then(|| what.join(" and "))
    }
}
