//! The lanes of any processor: four `f64` or eight `f32` ([`LANES`] [`Real`]
//! numbers) in the `wide` crate's types, which use the SIMD instructions the build
//! targets (two `f64` or four `f32` per instruction on any x86-64, and on
//! WebAssembly with its 128-bit SIMD) and plain arithmetic elsewhere.

use crate::fast::simd::real_lanes::{LANES, RealLanes, RealSource};
use crate::maths::Real;

/// The lanes of any processor, for the paths followed at once ([`LANES`] [`Real`]
/// lanes, [`RealSource`]) and for the fast hierarchy's tests (eight `f32` lanes as
/// two halves of four, `EightLanes`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Portable;

/// Four `f64`, one per lane, on any processor.
#[cfg(not(feature = "f32"))]
pub type PortableLanes = wide::f64x4;
/// Eight `f32`, one per lane, on any processor.
#[cfg(feature = "f32")]
pub type PortableLanes = wide::f32x8;

impl RealSource for Portable {
    type Wide = PortableLanes;

    #[inline(always)]
    fn splat(self, x: Real) -> PortableLanes {
        PortableLanes::splat(x)
    }

    #[inline(always)]
    fn gather(self, values: [Real; LANES]) -> PortableLanes {
        PortableLanes::from(values)
    }
}

impl RealLanes for PortableLanes {
    #[inline(always)]
    fn sqrt(self) -> Self {
        PortableLanes::sqrt(self)
    }

    #[inline(always)]
    fn abs(self) -> Self {
        PortableLanes::abs(self)
    }

    #[inline(always)]
    fn max(self, other: Self) -> Self {
        PortableLanes::max(self, other)
    }

    #[inline(always)]
    fn and_not(self, other: Self) -> Self {
        !self & other
    }

    #[inline(always)]
    fn lt(self, other: Self) -> Self {
        PortableLanes::simd_lt(self, other)
    }

    #[inline(always)]
    fn gt(self, other: Self) -> Self {
        PortableLanes::simd_gt(self, other)
    }

    #[inline(always)]
    fn ge(self, other: Self) -> Self {
        PortableLanes::simd_ge(self, other)
    }

    #[inline(always)]
    fn ne(self, other: Self) -> Self {
        PortableLanes::simd_ne(self, other)
    }

    #[inline(always)]
    fn select(self, yes: Self, no: Self) -> Self {
        PortableLanes::select(self, yes, no)
    }

    #[inline(always)]
    fn all(self) -> bool {
        PortableLanes::all(self)
    }

    #[inline(always)]
    fn bits(self) -> u32 {
        self.to_bitmask()
    }

    #[inline(always)]
    fn step_towards(self, towards: Self) -> Self {
        step_towards(self, towards)
    }

    #[inline(always)]
    fn to_array(self) -> [Real; LANES] {
        PortableLanes::to_array(self)
    }
}

/// [`RealLanes::step_towards`] on the bits of four `f64`: plus one, minus two
/// where the signs differ.
#[cfg(not(feature = "f32"))]
#[inline(always)]
fn step_towards(p: PortableLanes, o: PortableLanes) -> PortableLanes {
    use wide::{bytemuck::cast, u64x4};
    let (bits, differ): (u64x4, u64x4) = (cast(p), cast(p ^ o));
    cast(bits + u64x4::splat(1) - ((differ >> 63) << 1))
}

/// [`RealLanes::step_towards`] on the bits of eight `f32`: plus one, minus two
/// where the signs differ.
#[cfg(feature = "f32")]
#[inline(always)]
fn step_towards(p: PortableLanes, o: PortableLanes) -> PortableLanes {
    use wide::{bytemuck::cast, u32x8};
    let (bits, differ): (u32x8, u32x8) = (cast(p), cast(p ^ o));
    cast(bits + u32x8::splat(1) - ((differ >> 31) << 1))
}
