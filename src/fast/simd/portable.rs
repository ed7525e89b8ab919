//! The lanes of any processor: four [`Real`] numbers in the `wide` crate's type,
//! which uses the SIMD instructions the build targets (two `f64` per instruction
//! on any x86-64) and plain arithmetic elsewhere.

use crate::fast::simd::real_lanes::{RealLanes, RealSource};
use crate::maths::Real;

/// The lanes of any processor, for the four paths followed at once (four [`Real`]
/// lanes, [`RealSource`]) and for the fast hierarchy's tests (eight `f32` lanes as
/// two halves of four, `EightLanes`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Portable;

/// Four [`Real`] numbers, one per lane, on any processor.
#[cfg(not(feature = "f32"))]
pub type PortableFour = wide::f64x4;
/// Four [`Real`] numbers, one per lane, on any processor.
#[cfg(feature = "f32")]
pub type PortableFour = wide::f32x4;

impl RealSource for Portable {
    type Four = PortableFour;

    #[inline(always)]
    fn splat(self, x: Real) -> PortableFour {
        PortableFour::splat(x)
    }

    #[inline(always)]
    fn gather(self, values: [Real; 4]) -> PortableFour {
        PortableFour::from(values)
    }
}

impl RealLanes for PortableFour {
    #[inline(always)]
    fn sqrt(self) -> Self {
        PortableFour::sqrt(self)
    }

    #[inline(always)]
    fn abs(self) -> Self {
        PortableFour::abs(self)
    }

    #[inline(always)]
    fn max(self, other: Self) -> Self {
        PortableFour::max(self, other)
    }

    #[inline(always)]
    fn and_not(self, other: Self) -> Self {
        !self & other
    }

    #[inline(always)]
    fn lt(self, other: Self) -> Self {
        PortableFour::simd_lt(self, other)
    }

    #[inline(always)]
    fn gt(self, other: Self) -> Self {
        PortableFour::simd_gt(self, other)
    }

    #[inline(always)]
    fn ge(self, other: Self) -> Self {
        PortableFour::simd_ge(self, other)
    }

    #[inline(always)]
    fn ne(self, other: Self) -> Self {
        PortableFour::simd_ne(self, other)
    }

    #[inline(always)]
    fn select(self, yes: Self, no: Self) -> Self {
        PortableFour::select(self, yes, no)
    }

    #[inline(always)]
    fn all(self) -> bool {
        PortableFour::all(self)
    }

    #[inline(always)]
    fn step_towards(self, towards: Self) -> Self {
        step_towards(self, towards)
    }

    #[inline(always)]
    fn to_array(self) -> [Real; 4] {
        PortableFour::to_array(self)
    }
}

/// [`RealLanes::step_towards`] on the bits of four `f64`: plus one, minus two
/// where the signs differ.
#[cfg(not(feature = "f32"))]
#[inline(always)]
fn step_towards(p: PortableFour, o: PortableFour) -> PortableFour {
    use wide::{bytemuck::cast, u64x4};
    let (bits, differ): (u64x4, u64x4) = (cast(p), cast(p ^ o));
    cast(bits + u64x4::splat(1) - ((differ >> 63) << 1))
}

/// [`RealLanes::step_towards`] on the bits of four `f32`: plus one, minus two
/// where the signs differ.
#[cfg(feature = "f32")]
#[inline(always)]
fn step_towards(p: PortableFour, o: PortableFour) -> PortableFour {
    use wide::{bytemuck::cast, u32x4};
    let (bits, differ): (u32x4, u32x4) = (cast(p), cast(p ^ o));
    cast(bits + u32x4::splat(1) - ((differ >> 31) << 1))
}
