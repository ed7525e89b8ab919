//! Single-precision numbers side by side in a SIMD register, as one type: the
//! operations the fast hierarchy's slab test and triangle pre-test need, so that
//! each is written once for four lanes on any processor (glam's `Vec4`) and for
//! eight in AVX (`crate::fast::simd::avx_eight`).

use std::ops::{Add, BitAnd, BitOr, Mul, Neg, Sub};

use glam::{BVec4A, Vec4};

/// A SIMD register of `f32` lanes, with arithmetic lane by lane.
pub trait FloatLanes:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Mul<f32, Output = Self>
    + Neg<Output = Self>
{
    /// The result of a comparison: one true or false per lane.
    type Mask: Copy + BitOr<Output = Self::Mask> + BitAnd<Output = Self::Mask>;

    /// How many lanes.
    const LANES: usize;

    /// Each lane's absolute value.
    fn abs(self) -> Self;

    /// Each lane's `self < other`.
    fn lt(self, other: Self) -> Self::Mask;

    /// Each lane's `self > other`.
    fn gt(self, other: Self) -> Self::Mask;

    /// Each lane's `self <= other`.
    fn le(self, other: Self) -> Self::Mask;

    /// Each lane's larger value; `other` where either is NaN (as the SSE and AVX
    /// `max` instructions do).
    fn max(self, other: Self) -> Self;

    /// Each lane's smaller value; `other` where either is NaN.
    fn min(self, other: Self) -> Self;

    /// The mask as bits, bit `i` for lane `i`.
    fn bits(mask: Self::Mask) -> u32;
}

impl FloatLanes for Vec4 {
    type Mask = BVec4A;
    const LANES: usize = 4;

    #[inline(always)]
    fn abs(self) -> Vec4 {
        Vec4::abs(self)
    }

    #[inline(always)]
    fn lt(self, other: Vec4) -> BVec4A {
        self.cmplt(other)
    }

    #[inline(always)]
    fn gt(self, other: Vec4) -> BVec4A {
        self.cmpgt(other)
    }

    #[inline(always)]
    fn le(self, other: Vec4) -> BVec4A {
        self.cmple(other)
    }

    #[inline(always)]
    fn max(self, other: Vec4) -> Vec4 {
        Vec4::max(self, other)
    }

    #[inline(always)]
    fn min(self, other: Vec4) -> Vec4 {
        Vec4::min(self, other)
    }

    #[inline(always)]
    fn bits(mask: BVec4A) -> u32 {
        mask.bitmask()
    }
}

/// Where lanes come from: eight `f32` in a row loaded into one register, or one
/// number in every lane.
pub trait LaneSource: Copy {
    /// The lanes it makes.
    type Lanes: FloatLanes;

    /// The lanes of `row` this source stands for.
    fn load(self, row: &[f32; 8]) -> Self::Lanes;

    /// `x` in every lane.
    fn splat(self, x: f32) -> Self::Lanes;

    /// Writes `lanes` to the places of `row` this source stands for.
    fn store(self, lanes: Self::Lanes, row: &mut [f32; 8]);

    /// The first lane of a row this source stands for: bit `i` of a mask of its
    /// lanes is lane `first + i` of the row.
    fn first(self) -> usize;
}

/// Four lanes of a row of eight, from the given one on (0 or 4).
#[derive(Clone, Copy, Debug)]
pub struct Half(pub usize);

impl LaneSource for Half {
    type Lanes = Vec4;

    #[inline(always)]
    fn load(self, row: &[f32; 8]) -> Vec4 {
        Vec4::from_slice(&row[self.0..])
    }

    #[inline(always)]
    fn splat(self, x: f32) -> Vec4 {
        Vec4::splat(x)
    }

    #[inline(always)]
    fn store(self, lanes: Vec4, row: &mut [f32; 8]) {
        lanes.write_to_slice(&mut row[self.0..]);
    }

    #[inline(always)]
    fn first(self) -> usize {
        self.0
    }
}
