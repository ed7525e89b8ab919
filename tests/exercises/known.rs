//! Known answers: comparisons that say what was given and what was expected.

// Some helpers serve only later sessions' checks.
#![allow(dead_code)]

use raycourse::maths::{Real, Vec3};

use crate::say;
use crate::words::{decimal, separator};

/// A check's result: `Err` says what went wrong, in the book's notation.
pub type Outcome = Result<(), String>;

/// `Ok` when `holds`, otherwise the message `why` gives.
pub fn ensure(holds: bool, why: impl FnOnce() -> String) -> Outcome {
    if holds { Ok(()) } else { Err(why()) }
}

/// `gave` within `tolerance` of `expected`.
pub fn close(what: &str, gave: Real, expected: Real, tolerance: Real) -> Outcome {
    ensure((gave - expected).abs() <= tolerance, || {
        gave_expected(what, &num(gave), &num(expected), tolerance)
    })
}

/// `gave` within `tolerance` of `expected`, component by component.
pub fn close_vec(what: &str, gave: Vec3, expected: Vec3, tolerance: Real) -> Outcome {
    ensure((gave - expected).abs().max_element() <= tolerance, || {
        gave_expected(what, &vec(gave), &vec(expected), tolerance)
    })
}

/// `what: gave G, expected E (within T)`, in the checklist's language.
fn gave_expected(what: &str, gave: &str, expected: &str, tolerance: Real) -> String {
    let tolerance = decimal(tolerance.to_string());
    say!(
        "known-gave-expected-within",
        what = what,
        gave = gave,
        expected = expected,
        tolerance = tolerance
    )
}

/// A number as the book writes it: a few significant digits, with the language's
/// decimal mark.
pub fn num(x: Real) -> String {
    let text = format!("{x:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    decimal(if text == "-0" {
        "0".into()
    } else {
        text.into()
    })
}

/// A vector as the book writes it: `(0, 0.5, -1)`, or `(0 ; 0,5 ; -1)` in French.
pub fn vec(v: Vec3) -> String {
    let s = separator();
    format!("({}{s}{}{s}{})", num(v.x), num(v.y), num(v.z))
}

/// Whether two optional distances agree: both absent, or both within `tolerance`.
pub fn same_distance(gave: Option<Real>, expected: Option<Real>, tolerance: Real) -> bool {
    match (gave, expected) {
        (Some(t), Some(e)) => (t - e).abs() < tolerance,
        (None, None) => true,
        _ => false,
    }
}

/// An optional distance as the book writes it: `t = 4`, or `no hit`.
pub fn maybe(t: Option<Real>) -> String {
    t.map_or(say!("known-no-hit"), |t| format!("t = {}", num(t)))
}

/// A nearest hit (its distance and object) as the book writes it: `sphere 1 at
/// t = 4`, or `no hit`.
pub fn nearest(hit: Option<(Real, usize)>) -> String {
    hit.map_or(say!("known-no-hit"), |(t, i)| {
        let t = num(t);
        say!("known-sphere-at-t", i = i, t = t)
    })
}

/// The means of `f(u1, u2)` over an `n` x `n` grid of cell centres of the unit
/// square: the quadrature a sampler's averages are checked with, exact to about
/// `1 / n^2` for smooth integrands and the same whatever random numbers the
/// student's code is given.
pub fn grid_mean<const K: usize>(n: u32, mut f: impl FnMut(Real, Real) -> [Real; K]) -> [Real; K] {
    let mut sum = [0.0; K];
    for i in 0..n {
        for j in 0..n {
            let (u1, u2) = ((i as Real + 0.5) / n as Real, (j as Real + 0.5) / n as Real);
            for (s, v) in sum.iter_mut().zip(f(u1, u2)) {
                *s += v;
            }
        }
    }
    sum.map(|s| s / (n * n) as Real)
}
