//! The texture lookup on generated textures that are not square, both filters,
//! and coordinates from -3 to 4.

use proptest::collection::vec;
use proptest::prelude::*;
use raycourse::materials::texture::{Filter, Texture};
use raycourse::maths::{Colour, Real};

use super::super::v as vector;
use super::super::{differs, n, on_generated, ulps};
use crate::known::Outcome;
use crate::say;
use crate::words::separator;

/// The most texels a generated texture has each way.
const SIDE: u32 = 7;

/// A texture of 1 to 7 texels each way, its width and height drawn apart, rows
/// from the top, either filter. Its texels have any red and green, and blue
/// `0.01`, `0.02`, ... in reading order, so that no two are alike.
fn textures() -> impl Strategy<Value = Texture> {
    let colours = vec((0.0..1.0 as Real, 0.0..1.0 as Real), (SIDE * SIDE) as usize);
    (1..=SIDE, 1..=SIDE, colours, any::<bool>()).prop_map(|(width, height, colours, bilinear)| {
        let texels = colours
            .into_iter()
            .take((width * height) as usize)
            .enumerate()
            .map(|(k, (r, g))| Colour::new(r, g, (k + 1) as Real / 100.0))
            .collect();
        let filter = if bilinear {
            Filter::Bilinear
        } else {
            Filter::Nearest
        };
        Texture {
            width,
            height,
            texels,
            filter,
        }
    })
}

/// A texture coordinate from -3 to 4, before the texture's size is known.
#[derive(Clone, Copy, Debug)]
enum Address {
    /// This coordinate: `0`, `-0`, `1` or another integer, or anywhere.
    At(Real),
    /// The `k`th texel edge from -3 (modulo the texture's 7 widths).
    Edge(u32),
    /// The `k`th texel centre from -3 (modulo the texture's 7 widths).
    Centre(u32),
}

/// Addresses of every kind.
fn addresses() -> impl Strategy<Value = Address> {
    let many = 7 * SIDE;
    prop_oneof![
        prop_oneof![Just(0.0 as Real), Just(-0.0 as Real), Just(1.0 as Real)].prop_map(Address::At),
        (-3i32..=4).prop_map(|i| Address::At(i as Real)),
        (0..many).prop_map(Address::Edge),
        (0..many).prop_map(Address::Centre),
        (-3.0..4.0 as Real).prop_map(Address::At),
    ]
}

impl Address {
    /// The coordinate across `size` texels.
    fn on(self, size: u32) -> Real {
        let texel = |k: u32| (k % (7 * size)) as Real / size as Real - 3.0;
        match self {
            Address::At(x) => x,
            Address::Edge(k) => texel(k),
            Address::Centre(k) => texel(k) + 0.5 / size as Real,
        }
    }
}

/// The course's copy of the student's texture.
pub fn course_texture(texture: &Texture) -> course::materials::texture::Texture {
    use course::materials::texture::Filter as CourseFilter;
    course::materials::texture::Texture {
        width: texture.width,
        height: texture.height,
        texels: texture.texels.clone(),
        filter: match texture.filter {
            Filter::Nearest => CourseFilter::Nearest,
            Filter::Bilinear => CourseFilter::Bilinear,
        },
    }
}

/// A rounding of a texel-space coordinate to its texel: `floor`, or a mistake's.
pub type Round = fn(Real) -> Real;

/// The lookup of `texture` at the texel-space point `[x, y]` as the chapter
/// writes it, with `round` (`floor` for the chapter) taking each coordinate to its
/// texel and `shift` the bilinear filter's half texel: the texel the point falls
/// in, or the blend of the four whose centres surround it.
pub fn lookup_at(
    texture: &course::materials::texture::Texture,
    [x, y]: [Real; 2],
    round: [Round; 2],
    shift: Real,
) -> Colour {
    use course::materials::texture::Filter as CourseFilter;
    if texture.filter == CourseFilter::Nearest {
        return texture.texel(round[0](x) as i64, round[1](y) as i64);
    }
    let (x, y) = (x - shift, y - shift);
    let (x0, y0) = (round[0](x), round[1](y));
    let (fx, fy) = (x - x0, y - y0);
    let (i, j) = (x0 as i64, y0 as i64);
    let row = |j| texture.texel(i, j) * (1.0 - fx) + texture.texel(i + 1, j) * fx;
    row(j) * (1.0 - fy) + row(j + 1) * fy
}

/// Whether `gave` is what `lookup` reads at `[u, v]` or at `u` and `v` moved by
/// 16 roundings each way, within 64 roundings: a point on a texel's edge may
/// rightly fall on either side.
fn reads(gave: Colour, lookup: impl Fn([Real; 2]) -> Colour, [u, v]: [Real; 2]) -> bool {
    let moved = |x: Real, k: Real| {
        if k == 0.0 {
            x
        } else {
            x + k * ulps(16.0) * x.abs().max(1.0)
        }
    };
    let steps = [0.0, -1.0, 1.0];
    steps.iter().any(|&i| {
        steps.iter().any(|&j| {
            let read = lookup([moved(u, i), moved(v, j)]);
            (gave - read).abs().max_element() <= ulps(64.0)
        })
    })
}

/// Exercise s7.1 on generated textures that are not square, both filters, and
/// coordinates from -3 to 4: `0`, `-0`, `1`, integers, texel edges, negative and
/// past 1. A right answer reads what the course's does at the point, or at the
/// point moved by a few roundings (see [`reads`]).
pub fn texture_colour(yours: impl Fn(&Texture, [Real; 2]) -> Colour) -> Outcome {
    let inputs = (textures(), addresses(), addresses());
    on_generated("Texture::colour", inputs, |(texture, u, v)| {
        let (u, v) = (u.on(texture.width), v.on(texture.height));
        let course = course_texture(&texture);
        let gave = yours(&texture, [u, v]);
        if reads(gave, |uv| course.colour(uv), [u, v]) {
            return Ok(());
        }
        let expected = course.colour([u, v]);
        let why = texture_rules(&|uv| yours(&texture, uv), &course, [u, v]);
        let case = describe_texture(&texture, [u, v]);
        Err(differs(&case, &vector(gave), &vector(expected), why))
    })
}

/// The texture and the lookup in the book's notation.
fn describe_texture(texture: &Texture, [u, v]: [Real; 2]) -> String {
    let rows: Vec<String> = texture
        .texels
        .chunks(texture.width as usize)
        .map(|row| row.iter().map(|&c| vector(c)).collect::<Vec<_>>().join(" "))
        .collect();
    let (w, h, s) = (texture.width, texture.height, separator());
    let (u, v) = (n(u), n(v));
    let filter = texture.filter;
    let lookup = match filter {
        Filter::Nearest => say!("checklist-filter-nearest"),
        Filter::Bilinear => say!("checklist-filter-bilinear"),
    };
    say!(
        "generated-s7-texture-a-x-texture-rows-from-the",
        rows = rows.join(" / "),
        w = w,
        h = h,
        filter_debug = format!("{:?}", filter),
        u = u,
        v = v,
        lookup = lookup,
        s = s
    )
}

/// A mistake the lookup's diagnoses name.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Rule {
    /// Rows counted from the bottom: `y = v H`.
    FromBottom,
    /// `u` and `v`, or `W` and `H`, swapped.
    Swapped,
    /// A coordinate cast to an integer, truncated towards zero, not floored.
    Truncated,
    /// The bilinear filter without its half-texel shift.
    Unshifted,
}

impl Rule {
    /// The rule of the chapter that this mistake breaks, for a `w` x `h` texture.
    fn why(self, w: u32, h: u32) -> String {
        match self {
            Rule::FromBottom => say!("generated-s7-texture-v-runs-from-the-bottom-v"),
            Rule::Swapped => say!(
                "generated-s7-texture-u-runs-along-the-width-and",
                w = w,
                h = h
            ),
            Rule::Truncated => say!("generated-s7-texture-a-point-s-texel-is-floor"),
            Rule::Unshifted => say!("generated-s7-texture-texel-k-s-centre-is-at"),
        }
    }
}

/// A lookup as a function of `[u, v]`.
type Lookup<'a> = Box<dyn Fn([Real; 2]) -> Colour + 'a>;

/// The mistaken lookups of `texture`, each with the rule it breaks.
fn mistaken(texture: &course::materials::texture::Texture) -> Vec<(Rule, Lookup<'_>)> {
    let (w, h) = (texture.width as Real, texture.height as Real);
    let floor: [Round; 2] = [Real::floor, Real::floor];
    let at = move |point: [Real; 2], round: [Round; 2], shift: Real| {
        lookup_at(texture, point, round, shift)
    };
    let mut all: Vec<(Rule, Lookup)> = vec![
        (
            Rule::FromBottom,
            Box::new(move |[u, v]| at([u * w, v * h], floor, 0.5)),
        ),
        (
            Rule::Swapped,
            Box::new(move |[u, v]| at([v * w, (1.0 - u) * h], floor, 0.5)),
        ),
        (
            Rule::Swapped,
            Box::new(move |[u, v]| at([u * h, (1.0 - v) * w], floor, 0.5)),
        ),
    ];
    let truncated: [[Round; 2]; 3] = [
        [Real::trunc, Real::trunc],
        [Real::floor, Real::trunc],
        [Real::trunc, Real::floor],
    ];
    for round in truncated {
        all.push((
            Rule::Truncated,
            Box::new(move |[u, v]| at([u * w, (1.0 - v) * h], round, 0.5)),
        ));
    }
    if texture.filter == course::materials::texture::Filter::Bilinear {
        all.push((
            Rule::Unshifted,
            Box::new(move |[u, v]| at([u * w, (1.0 - v) * h], floor, 0.0)),
        ));
    }
    all
}

/// The rules of the lookup that `yours` breaks at `point` of the course's
/// `texture`: the mistakes that read what yours reads there and, where some do,
/// at 36 other points too.
fn texture_rules(
    yours: &dyn Fn([Real; 2]) -> Colour,
    texture: &course::materials::texture::Texture,
    point: [Real; 2],
) -> Option<String> {
    let probes = [-2.3, -0.6, 0.2, 0.55, 1.4, 3.7];
    let points: Vec<[Real; 2]> = probes
        .iter()
        .flat_map(|&u| probes.map(|v| [u, v]))
        .collect();
    let explains =
        |lookup: &Lookup, points: &[[Real; 2]]| points.iter().all(|&p| reads(yours(p), lookup, p));
    let here: Vec<(Rule, Lookup)> = mistaken(texture)
        .into_iter()
        .filter(|(_, lookup)| explains(lookup, &[point]))
        .collect();
    let everywhere: Vec<Rule> = here
        .iter()
        .filter(|(_, lookup)| explains(lookup, &points))
        .map(|(rule, _)| *rule)
        .collect();
    let mut rules = if everywhere.is_empty() {
        here.iter().map(|(rule, _)| *rule).collect()
    } else {
        everywhere
    };
    rules.dedup();
    let named: Vec<String> = rules
        .iter()
        .map(|r| r.why(texture.width, texture.height))
        .collect();
    (!named.is_empty()).then(|| named.join(&say!("generated-s7-texture-or")))
}
