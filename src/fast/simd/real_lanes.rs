//! [`Real`] numbers side by side in a 256-bit SIMD register, as one type: four
//! `f64`, or with the `f32` feature eight `f32`. The operations the paths followed at
//! once need, so that their sphere test and their shading are written once, with the
//! usual operators, for the portable lanes (the `wide` crate's) and for AVX's, in
//! either precision.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Sub};

use crate::maths::{Real, Vec3};

/// How many [`Real`] numbers a kind of lanes holds: a 256-bit register's worth, four
/// `f64` or eight `f32`.
pub const LANES: usize = 32 / std::mem::size_of::<Real>();

/// A SIMD register of [`LANES`] [`Real`] lanes, with arithmetic lane by lane. A
/// comparison gives a mask of the same type: all ones in a lane where it holds,
/// zeros where it does not, which `&`, `|` and [`RealLanes::select`] combine.
pub trait RealLanes:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + BitAnd<Output = Self>
    + BitOr<Output = Self>
{
    /// Each lane's square root.
    fn sqrt(self) -> Self;

    /// Each lane's absolute value (the sign bit cleared).
    fn abs(self) -> Self;

    /// Each lane's larger value; `other` where either is NaN (as the SSE and AVX
    /// `max` instructions do).
    fn max(self, other: Self) -> Self;

    /// The bits of `other` where those of `self` are clear.
    fn and_not(self, other: Self) -> Self;

    /// The mask of the lanes where `self < other`.
    fn lt(self, other: Self) -> Self;

    /// The mask of the lanes where `self > other`.
    fn gt(self, other: Self) -> Self;

    /// The mask of the lanes where `self >= other`.
    fn ge(self, other: Self) -> Self;

    /// The mask of the lanes where `self != other`.
    fn ne(self, other: Self) -> Self;

    /// With `self` a mask: `yes` in the lanes where it is set, `no` in the others.
    fn select(self, yes: Self, no: Self) -> Self;

    /// With `self` a mask: whether every lane is set.
    fn all(self) -> bool;

    /// With `self` a mask: its lanes as bits, bit `k` set where lane `k` is.
    fn bits(self) -> u32;

    /// The float next to `self` (finite, not zero) away from zero where `towards`
    /// (not zero) has the sign of `self`, towards zero where it has the other: the
    /// bits of `self` plus one, or minus one, as in
    /// [`one_ulp_towards`](crate::geometry::spawn::one_ulp_towards).
    fn step_towards(self, towards: Self) -> Self;

    /// The numbers, lane 0 first.
    fn to_array(self) -> [Real; LANES];
}

/// Where lanes come from: a kind of lanes ([`Portable`](super::portable::Portable)
/// or, proving the processor has it, [`Avx`](super::avx::Avx)) makes them from
/// numbers.
pub trait RealSource: Copy {
    /// The lanes it makes.
    type Wide: RealLanes;

    /// `x` in every lane.
    fn splat(self, x: Real) -> Self::Wide;

    /// The numbers of `values`, one per lane.
    fn gather(self, values: [Real; LANES]) -> Self::Wide;
}

/// [`LANES`] vectors by coordinate, each coordinate in lanes: lane `k` of `v[axis]` is
/// coordinate `axis` of vector `k`.
pub type VectorLanes<F> = [F; 3];

/// The coordinates of [`LANES`] vectors, one vector per lane.
#[inline(always)]
pub fn gather3<L: RealSource>(lanes: L, v: [Vec3; LANES]) -> VectorLanes<L::Wide> {
    [
        lanes.gather(v.map(|v| v.x)),
        lanes.gather(v.map(|v| v.y)),
        lanes.gather(v.map(|v| v.z)),
    ]
}

/// The numbers of three coordinates' lanes: `[axis][k]` is coordinate `axis` of
/// vector `k`.
#[inline(always)]
pub fn scatter3<F: RealLanes>(v: VectorLanes<F>) -> [[Real; LANES]; 3] {
    [v[0].to_array(), v[1].to_array(), v[2].to_array()]
}

/// `a . b`, glam's order: `(a_x b_x + a_y b_y) + a_z b_z`.
#[inline(always)]
pub fn dot<F: RealLanes>(a: VectorLanes<F>, b: VectorLanes<F>) -> F {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a x b`, glam's order: `(a_y b_z - b_y a_z, a_z b_x - b_z a_x, a_x b_y - b_x a_y)`.
#[inline(always)]
pub fn cross<F: RealLanes>(a: VectorLanes<F>, b: VectorLanes<F>) -> VectorLanes<F> {
    [
        a[1] * b[2] - b[1] * a[2],
        a[2] * b[0] - b[2] * a[0],
        a[0] * b[1] - b[0] * a[1],
    ]
}

/// `s v`, lane by lane.
#[inline(always)]
pub fn scale<F: RealLanes>(s: F, v: VectorLanes<F>) -> VectorLanes<F> {
    [s * v[0], s * v[1], s * v[2]]
}

/// `a + b`, lane by lane.
#[inline(always)]
pub fn plus<F: RealLanes>(a: VectorLanes<F>, b: VectorLanes<F>) -> VectorLanes<F> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a - b`, lane by lane.
#[inline(always)]
pub fn minus<F: RealLanes>(a: VectorLanes<F>, b: VectorLanes<F>) -> VectorLanes<F> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `|v|` coordinate by coordinate, lane by lane.
#[inline(always)]
pub fn abs3<F: RealLanes>(v: VectorLanes<F>) -> VectorLanes<F> {
    [v[0].abs(), v[1].abs(), v[2].abs()]
}

/// `v` in every lane.
#[inline(always)]
pub fn splat3<L: RealSource>(lanes: L, v: Vec3) -> VectorLanes<L::Wide> {
    [lanes.splat(v.x), lanes.splat(v.y), lanes.splat(v.z)]
}

/// `v / s`, lane by lane.
#[inline(always)]
pub fn divide<F: RealLanes>(v: VectorLanes<F>, s: F) -> VectorLanes<F> {
    [v[0] / s, v[1] / s, v[2] / s]
}

/// Entry `i` of each of [`LANES`] rows, one row per lane.
#[inline(always)]
pub fn column<L: RealSource, const N: usize>(
    lanes: L,
    rows: [[Real; N]; LANES],
    i: usize,
) -> L::Wide {
    lanes.gather(rows.map(|row| row[i]))
}
