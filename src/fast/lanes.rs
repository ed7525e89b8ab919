//! The lanes the fast engine runs on, chosen once: AVX's where the processor has
//! them (asked at run time), the portable ones elsewhere. Every kind of lanes
//! computes the same numbers to the last bit; this only chooses, and runs work
//! written once for any kind ([`OnLanes`]) on the one chosen.
//!
//! AVX's instructions may run only on a processor that has them, and code compiled
//! without them may call them only after asking. So the AVX lanes are made only
//! from an [`Avx`], the proof that the processor has them, and [`Lanes::run`] runs
//! the work in one function compiled with AVX. Everything between that function and
//! the lanes' operations is `#[inline(always)]` and free of closures, so that it all
//! inlines into it and each operation becomes one AVX instruction: a function that
//! did not inline (a closure, or a generic function such as `<[T; 3]>::map`) would
//! be compiled without AVX and call each operation instead, several times slower.
#![allow(unsafe_code)]

use crate::fast::hierarchy::wide_node::EightLanes;
#[cfg(target_arch = "x86_64")]
use crate::fast::simd::avx::Avx;
use crate::fast::simd::portable::Portable;
use crate::fast::simd::real_lanes::RealSource;

/// A kind of lanes: four [`Real`](crate::maths::Real) lanes for the paths followed
/// at once, and the hierarchy's eight-lane tests.
pub trait LaneKind: RealSource + EightLanes {}

impl<L: RealSource + EightLanes> LaneKind for L {}

/// Work written once for any kind of lanes.
pub trait OnLanes {
    /// What the work gives.
    type Output;

    /// Does the work on `lanes`. Implementations are `#[inline(always)]`, so that
    /// the work compiles into [`Lanes::run`]'s function for each kind.
    fn on<L: LaneKind>(self, lanes: L) -> Self::Output;
}

/// The kind of lanes that the paths followed at once and the fast hierarchy's tests
/// run on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lanes {
    /// AVX: four `f64` or eight `f32` per instruction, on the x86-64 processors
    /// that have it.
    #[cfg(target_arch = "x86_64")]
    Avx(Avx),
    /// The lanes of any processor.
    Portable,
}

impl Lanes {
    /// The fastest lanes this processor has.
    pub fn fastest() -> Lanes {
        #[cfg(target_arch = "x86_64")]
        if let Some(avx) = Avx::detect() {
            return Lanes::Avx(avx);
        }
        Lanes::Portable
    }

    /// Does `work` on these lanes: with AVX, in a function compiled with it.
    #[inline(always)]
    pub fn run<W: OnLanes>(self, work: W) -> W::Output {
        match self {
            #[cfg(target_arch = "x86_64")]
            // SAFETY: an `Avx` is made only where the processor has AVX, so code
            // compiled with AVX can run.
            Lanes::Avx(avx) => unsafe { with_avx(avx, work) },
            Lanes::Portable => work.on(Portable),
        }
    }
}

/// `work` on the AVX lanes, compiled with AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
fn with_avx<W: OnLanes>(avx: Avx, work: W) -> W::Output {
    work.on(avx)
}
