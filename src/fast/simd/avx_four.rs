//! Four `f64` in one AVX register: the lanes of the four paths followed at once on
//! the processors that have AVX, in double precision.
#![allow(unsafe_code)]

use std::arch::x86_64::{
    __m128d, __m256d, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_OQ, _mm_add_epi64,
    _mm_castpd_si128, _mm_castsi128_pd, _mm_cvtsd_f64, _mm_set1_epi64x, _mm_slli_epi64,
    _mm_srli_epi64, _mm_sub_epi64, _mm_unpackhi_pd, _mm256_add_pd, _mm256_and_pd, _mm256_andnot_pd,
    _mm256_blendv_pd, _mm256_castpd128_pd256, _mm256_castpd256_pd128, _mm256_cmp_pd, _mm256_div_pd,
    _mm256_extractf128_pd, _mm256_insertf128_pd, _mm256_max_pd, _mm256_movemask_pd, _mm256_mul_pd,
    _mm256_or_pd, _mm256_set_pd, _mm256_set1_pd, _mm256_sqrt_pd, _mm256_sub_pd, _mm256_xor_pd,
};
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Sub};

use crate::fast::simd::avx::Avx;
use crate::fast::simd::real_lanes::{RealLanes, RealSource};

/// Four `f64` in an AVX register, made only from an [`Avx`].
#[derive(Clone, Copy)]
pub struct Four(__m256d);

impl RealSource for Avx {
    type Wide = Four;

    #[inline(always)]
    fn splat(self, x: f64) -> Four {
        // SAFETY: an `Avx` is made only where the processor has AVX.
        Four(unsafe { _mm256_set1_pd(x) })
    }

    #[inline(always)]
    fn gather(self, values: [f64; 4]) -> Four {
        let [a, b, c, d] = values;
        // SAFETY: an `Avx` is made only where the processor has AVX.
        Four(unsafe { _mm256_set_pd(d, c, b, a) })
    }
}

/// Implements a binary operator of [`Four`] by an AVX instruction on its registers.
macro_rules! four_operator {
    ($trait:ident, $method:ident, $instruction:expr) => {
        impl $trait for Four {
            type Output = Four;
            #[inline(always)]
            fn $method(self, other: Four) -> Four {
                // SAFETY: a `Four` exists only where the processor has AVX.
                Four(unsafe { $instruction(self.0, other.0) })
            }
        }
    };
}

four_operator!(Add, add, _mm256_add_pd);
four_operator!(Sub, sub, _mm256_sub_pd);
four_operator!(Mul, mul, _mm256_mul_pd);
four_operator!(Div, div, _mm256_div_pd);
four_operator!(BitAnd, bitand, _mm256_and_pd);
four_operator!(BitOr, bitor, _mm256_or_pd);

impl Neg for Four {
    type Output = Four;
    /// The sign bits flipped.
    #[inline(always)]
    fn neg(self) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)) })
    }
}

impl RealLanes for Four {
    #[inline(always)]
    fn sqrt(self) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_sqrt_pd(self.0) })
    }

    #[inline(always)]
    fn abs(self) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) })
    }

    #[inline(always)]
    fn max(self, other: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_max_pd(self.0, other.0) })
    }

    #[inline(always)]
    fn and_not(self, other: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_andnot_pd(self.0, other.0) })
    }

    #[inline(always)]
    fn lt(self, other: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_cmp_pd::<_CMP_LT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn gt(self, other: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_cmp_pd::<_CMP_GT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn ge(self, other: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_cmp_pd::<_CMP_GE_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn ne(self, other: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_cmp_pd::<_CMP_NEQ_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn select(self, yes: Four, no: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        Four(unsafe { _mm256_blendv_pd(no.0, yes.0, self.0) })
    }

    #[inline(always)]
    fn all(self) -> bool {
        // SAFETY: a `Four` exists only where the processor has AVX.
        unsafe { _mm256_movemask_pd(self.0) == 0b1111 }
    }

    #[inline(always)]
    fn bits(self) -> u32 {
        // SAFETY: a `Four` exists only where the processor has AVX.
        unsafe { _mm256_movemask_pd(self.0) as u32 }
    }

    /// In two halves, AVX having no 64-bit integer addition on its full registers.
    #[inline(always)]
    fn step_towards(self, towards: Four) -> Four {
        // SAFETY: a `Four` exists only where the processor has AVX.
        unsafe {
            let differ = _mm256_xor_pd(self.0, towards.0);
            let low = step_half(
                _mm256_castpd256_pd128(self.0),
                _mm256_castpd256_pd128(differ),
            );
            let high = step_half(
                _mm256_extractf128_pd::<1>(self.0),
                _mm256_extractf128_pd::<1>(differ),
            );
            Four(_mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(low), high))
        }
    }

    #[inline(always)]
    fn to_array(self) -> [f64; 4] {
        // SAFETY: a `Four` exists only where the processor has AVX.
        unsafe {
            let (low, high) = (
                _mm256_castpd256_pd128(self.0),
                _mm256_extractf128_pd::<1>(self.0),
            );
            [
                _mm_cvtsd_f64(low),
                _mm_cvtsd_f64(_mm_unpackhi_pd(low, low)),
                _mm_cvtsd_f64(high),
                _mm_cvtsd_f64(_mm_unpackhi_pd(high, high)),
            ]
        }
    }
}

/// `step_towards` on two lanes, `differ` holding the bits of `p ^ towards`: the
/// bits of `p` plus one, minus two where the signs differ.
#[inline(always)]
fn step_half(p: __m128d, differ: __m128d) -> __m128d {
    // SAFETY: SSE2, which every x86-64 processor has.
    unsafe {
        let signs = _mm_srli_epi64::<63>(_mm_castpd_si128(differ));
        let delta = _mm_sub_epi64(_mm_set1_epi64x(1), _mm_slli_epi64::<1>(signs));
        _mm_castsi128_pd(_mm_add_epi64(_mm_castpd_si128(p), delta))
    }
}
