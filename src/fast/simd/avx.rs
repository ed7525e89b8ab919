//! The lanes of the x86-64 processors that have AVX (almost all made since 2011):
//! four `f64` or eight `f32` per instruction. The processor is asked at run time
//! ([`Avx::detect`]), so the build needs no flag.
//!
//! The lanes' operations use AVX instructions, which code compiled without AVX may
//! call only where the processor has them. So the AVX lanes (`Four` for the
//! paths in double precision, [`Eight`] for the hierarchy and the paths in single)
//! are made only from an [`Avx`], the proof that it has, and the work on them runs
//! in a function compiled with AVX
//! ([`Lanes::run`](crate::fast::lanes::Lanes::run)).
#![allow(unsafe_code)]

use std::arch::x86_64::{
    _MM_HINT_T0, _mm_prefetch, _mm256_loadu_ps, _mm256_set1_ps, _mm256_storeu_ps,
};

use crate::fast::simd::avx_eight::Eight;
use crate::fast::simd::float_lanes::LaneSource;

/// Proof that this processor has AVX: made only by [`Avx::detect`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Avx(());

impl Avx {
    /// `Some` where the processor has AVX.
    pub fn detect() -> Option<Avx> {
        std::arch::is_x86_feature_detected!("avx").then_some(Avx(()))
    }

    /// The AVX lanes for a test marked `#[cfg_attr(not(processor_has_avx), ignore =
    /// ...)]`: the build found AVX on this processor (`build.rs`), so a test that
    /// runs where it is missing fails rather than passing untested.
    #[cfg(test)]
    pub fn for_test() -> Avx {
        Avx::detect().expect("build.rs found AVX on the building processor; this one has none")
    }

    /// Asks the processor to start loading `item`, every 64-byte cache line of it,
    /// into its nearest cache, so that a read a little later finds it there instead
    /// of waiting on memory. A hint: it reads nothing the program sees and changes no
    /// result.
    #[inline(always)]
    pub fn prefetch<T>(self, item: &T) {
        let start: *const i8 = (item as *const T).cast();
        for offset in (0..size_of::<T>()).step_by(64) {
            // SAFETY: a prefetch is a hint that cannot fault, and every address is
            // inside `item`.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(start.wrapping_add(offset)) }
        }
    }
}

impl LaneSource for Avx {
    type Lanes = Eight;

    /// The eight numbers of `row`.
    #[inline(always)]
    fn load(self, row: &[f32; 8]) -> Eight {
        // SAFETY: an `Avx` is made only where the processor has AVX, and `row`
        // holds eight `f32`.
        Eight(unsafe { _mm256_loadu_ps(row.as_ptr()) })
    }

    /// `x` in every lane.
    #[inline(always)]
    fn splat(self, x: f32) -> Eight {
        // SAFETY: an `Avx` is made only where the processor has AVX.
        Eight(unsafe { _mm256_set1_ps(x) })
    }

    /// Writes the eight lanes to `row`.
    #[inline(always)]
    fn store(self, lanes: Eight, row: &mut [f32; 8]) {
        // SAFETY: an `Avx` is made only where the processor has AVX, and `row`
        // holds eight `f32`.
        unsafe { _mm256_storeu_ps(row.as_mut_ptr(), lanes.0) }
    }

    #[inline(always)]
    fn first(self) -> usize {
        0
    }
}
