//! The probe as text, in the book's notation: one block per ray of the path, in
//! the reader's language (the catalogue's `probe.ftl`).

use crate::inspect::path::{Direct, Level, Met, Next, Probe};
use crate::maths::Real;
use crate::messages::catalogue::{Argument, decimals};
use crate::messages::language::Language;
use crate::messages::say;

impl Probe {
    /// The probe as text in `language`, a line per fact, a block per level.
    pub fn text(&self, language: Language) -> String {
        let say = |id: &str, arguments: &[(&str, Argument)]| say(language, id, arguments);
        let mut lines = vec![say(
            "probe-pixel",
            &[
                ("x", self.x.into()),
                ("y", self.y.into()),
                ("sample", self.sample.into()),
                ("samples", self.samples.into()),
            ],
        )];
        for (k, level) in self.levels.iter().enumerate() {
            let id = if k == 0 {
                "probe-camera-ray"
            } else {
                "probe-bounce"
            };
            lines.push(String::new());
            lines.push(say(id, &[("level", k.into())]));
            write_level(&mut lines, level, language);
        }
        lines.push(String::new());
        let radiance = triple(self.radiance, language);
        lines.push(say(
            "probe-sample-radiance",
            &[("radiance", radiance.into())],
        ));
        let [red, green, blue] = self.shown;
        let pixel = [
            ("samples", self.samples.into()),
            ("pixel", triple(self.pixel, language).into()),
            ("gamma", shortest(self.gamma)),
            ("red", red.into()),
            ("green", green.into()),
            ("blue", blue.into()),
        ];
        lines.push(say("probe-pixel-mean", &pixel));
        lines.join("\n") + "\n"
    }
}

/// One level's block.
fn write_level(lines: &mut Vec<String>, level: &Level, language: Language) {
    let say = |id: &str, arguments: &[(&str, Argument)]| say(language, id, arguments);
    let three = |v| Argument::from(triple(v, language));
    lines.push(say(
        "probe-ray",
        &[
            ("origin", three(level.origin)),
            ("direction", three(level.direction)),
        ],
    ));
    if let Some(hit) = &level.hit {
        write_hit(lines, hit, level, language);
    }
    if let Some(direct) = &level.direct {
        write_direct(lines, direct, language);
    }
    if let Some(next) = &level.next {
        write_next(lines, next, level.bounces_left, language);
    }
    if let Some(end) = &level.end {
        lines.push(say("probe-end", &[("end", end.say(language).into())]));
    }
    lines.push(say(
        "probe-arriving",
        &[
            ("arriving", three(level.arriving)),
            ("throughput", three(level.throughput)),
            ("adds", three(level.adds)),
        ],
    ));
}

/// What `level`'s ray met (`hit`): where, which object of which material, and
/// the light it emits.
fn write_hit(lines: &mut Vec<String>, hit: &Met, level: &Level, language: Language) {
    let say = |id: &str, arguments: &[(&str, Argument)]| say(language, id, arguments);
    let three = |v| Argument::from(triple(v, language));
    lines.push(say(
        "probe-hit",
        &[
            ("t", fixed(hit.t, 4)),
            ("point", three(hit.point)),
            ("normal", three(hit.normal)),
        ],
    ));
    let face = say(
        if hit.front_face {
            "probe-front-face"
        } else {
            "probe-back-face"
        },
        &[],
    );
    lines.push(say(
        "probe-object",
        &[
            (
                "shape",
                say(&format!("probe-shape-{}", hit.shape), &[]).into(),
            ),
            ("object", hit.object.into()),
            ("material", hit.material.as_str().into()),
            ("face", face.into()),
        ],
    ));
    let glow = match level.glow_not_counted {
        true => say("probe-glow-not-counted", &[]),
        false => String::new(),
    };
    let emitted = [("emitted", three(level.emitted)), ("glow", glow.into())];
    lines.push(say("probe-emitted", &emitted));
}

/// The light source's part.
fn write_direct(lines: &mut Vec<String>, direct: &Direct, language: Language) {
    let say = |id: &str, arguments: &[(&str, Argument)]| say(language, id, arguments);
    let light = say(
        &format!("probe-light-{}", direct.light.replace(' ', "-")),
        &[],
    );
    match &direct.shadow_ray {
        Some(ray) => {
            lines.push(say(
                "probe-shadow-ray",
                &[
                    ("light", light.into()),
                    ("origin", triple(ray.origin, language).into()),
                    ("direction", triple(ray.direction, language).into()),
                ],
            ));
            let distance = ray
                .distance
                .map_or_else(|| say("probe-no-distance", &[]).into(), |d| fixed(d, 4));
            let blocked = match (ray.blocked_by, ray.blocked_at) {
                (Some(object), Some(t)) => say(
                    "probe-blocked",
                    &[
                        ("object", object.into()),
                        ("t", scientific(t, language).into()),
                    ],
                ),
                _ => say("probe-not-blocked", &[]),
            };
            let distance = [("distance", distance), ("blocked", blocked.into())];
            lines.push(say("probe-shadow-distance", &distance));
        }
        None => lines.push(say("probe-no-shadow-ray", &[("light", light.into())])),
    }
    let brings = triple(direct.brings, language);
    lines.push(say("probe-direct", &[("brings", brings.into())]));
}

/// How the path goes on.
fn write_next(lines: &mut Vec<String>, next: &Next, bounces_left: u32, language: Language) {
    let say = |id: &str, arguments: &[(&str, Argument)]| say(language, id, arguments);
    lines.push(say(
        "probe-next",
        &[
            ("kind", next.kind.say(language).into()),
            ("direction", triple(next.direction, language).into()),
        ],
    ));
    if let (Some(cos), Some(pdf)) = (next.cos, next.pdf) {
        lines.push(say(
            "probe-cos-pdf",
            &[("cos", fixed(cos, 4)), ("pdf", fixed(pdf, 4))],
        ));
    }
    if let Some(fresnel) = next.fresnel {
        lines.push(say("probe-fresnel", &[("fresnel", fixed(fresnel, 4))]));
    }
    lines.push(match next.survival {
        Some(s) => say("probe-roulette", &[("survival", shortest(s))]),
        None => say("probe-bounces-left", &[("left", bounces_left.into())]),
    });
    lines.push(say(
        "probe-weight",
        &[("weight", triple(next.weight, language).into())],
    ));
}

/// Three numbers as the probe writes them: `(0.8000, 0.2000, 0.2000)`, or
/// `(0,8000 ; 0,2000 ; 0,2000)` in French.
fn triple(v: [Real; 3], language: Language) -> String {
    let [x, y, z] = v.map(|c| fixed(c, 4));
    say(language, "probe-triple", &[("x", x), ("y", y), ("z", z)])
}

/// `value` with `places` decimals: its digits as Rust rounds them, written with
/// the message's decimal mark.
fn fixed(value: Real, places: usize) -> Argument<'static> {
    let digits = format!("{value:.places$}");
    decimals(digits.parse().unwrap_or(f64::NAN), places)
}

/// `value` in its shortest form, whatever the precision of `Real` (`2.2`, `2,2`).
fn shortest(value: Real) -> Argument<'static> {
    value.to_string().parse::<f64>().unwrap_or(f64::NAN).into()
}

/// `value` in scientific notation with 3 decimals: `1.234e-5`, `1,234e-5`.
fn scientific(value: Real, language: Language) -> String {
    let text = format!("{value:.3e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let mantissa = decimals(mantissa.parse().unwrap_or(f64::NAN), 3);
    say(language, "probe-number", &[("value", mantissa)]) + "e" + exponent
}
