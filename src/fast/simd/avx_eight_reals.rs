//! AVX's eight `f32` ([`Eight`], the hierarchy's lanes) as [`RealLanes`] too: the
//! lanes of the eight paths followed at once on the processors that have AVX, in
//! single precision (the `f32` feature; in double precision they are `avx_four`'s
//! four `f64`).
#![allow(unsafe_code)]

use std::arch::x86_64::{
    __m128, _CMP_GE_OQ, _CMP_NEQ_OQ, _mm_add_epi32, _mm_castps_si128, _mm_castsi128_ps,
    _mm_set1_epi32, _mm_slli_epi32, _mm_srli_epi32, _mm_sub_epi32, _mm256_andnot_ps,
    _mm256_blendv_ps, _mm256_castps128_ps256, _mm256_castps256_ps128, _mm256_cmp_ps,
    _mm256_extractf128_ps, _mm256_insertf128_ps, _mm256_loadu_ps, _mm256_movemask_ps,
    _mm256_set1_ps, _mm256_sqrt_ps, _mm256_storeu_ps, _mm256_xor_ps,
};

use crate::fast::simd::avx::Avx;
use crate::fast::simd::avx_eight::Eight;
use crate::fast::simd::float_lanes::FloatLanes;
use crate::fast::simd::real_lanes::{RealLanes, RealSource};

impl RealSource for Avx {
    type Wide = Eight;

    #[inline(always)]
    fn splat(self, x: f32) -> Eight {
        // SAFETY: an `Avx` is made only where the processor has AVX.
        Eight(unsafe { _mm256_set1_ps(x) })
    }

    #[inline(always)]
    fn gather(self, values: [f32; 8]) -> Eight {
        // SAFETY: an `Avx` is made only where the processor has AVX, and `values`
        // holds eight `f32`.
        Eight(unsafe { _mm256_loadu_ps(values.as_ptr()) })
    }
}

/// The operations the hierarchy's lanes already have ([`FloatLanes`]) are theirs.
impl RealLanes for Eight {
    #[inline(always)]
    fn sqrt(self) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_sqrt_ps(self.0) })
    }

    #[inline(always)]
    fn abs(self) -> Eight {
        FloatLanes::abs(self)
    }

    #[inline(always)]
    fn max(self, other: Eight) -> Eight {
        FloatLanes::max(self, other)
    }

    #[inline(always)]
    fn and_not(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_andnot_ps(self.0, other.0) })
    }

    #[inline(always)]
    fn lt(self, other: Eight) -> Eight {
        FloatLanes::lt(self, other)
    }

    #[inline(always)]
    fn gt(self, other: Eight) -> Eight {
        FloatLanes::gt(self, other)
    }

    #[inline(always)]
    fn ge(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_GE_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn ne(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_NEQ_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn select(self, yes: Eight, no: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_blendv_ps(no.0, yes.0, self.0) })
    }

    #[inline(always)]
    fn all(self) -> bool {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        unsafe { _mm256_movemask_ps(self.0) == 0xff }
    }

    #[inline(always)]
    fn bits(self) -> u32 {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        unsafe { _mm256_movemask_ps(self.0) as u32 }
    }

    #[inline(always)]
    fn step_towards(self, towards: Eight) -> Eight {
        // AVX has no 256-bit integer arithmetic (AVX2 has): each half of four by SSE2.
        // SAFETY: an `Eight` exists only where the processor has AVX.
        unsafe {
            let differ = _mm256_xor_ps(self.0, towards.0);
            let low = step_half(
                _mm256_castps256_ps128(self.0),
                _mm256_castps256_ps128(differ),
            );
            let high = step_half(
                _mm256_extractf128_ps::<1>(self.0),
                _mm256_extractf128_ps::<1>(differ),
            );
            Eight(_mm256_insertf128_ps::<1>(_mm256_castps128_ps256(low), high))
        }
    }

    #[inline(always)]
    fn to_array(self) -> [f32; 8] {
        let mut values = [0.0; 8];
        // SAFETY: an `Eight` exists only where the processor has AVX, and
        // `values` holds eight `f32`.
        unsafe { _mm256_storeu_ps(values.as_mut_ptr(), self.0) };
        values
    }
}

/// [`RealLanes::step_towards`] on four of the lanes: their bits plus one, minus two
/// where `differ`'s sign bit is set (the signs of the two numbers differ).
#[inline(always)]
fn step_half(p: __m128, differ: __m128) -> __m128 {
    // SAFETY: SSE2, which every x86-64 processor has.
    unsafe {
        let signs = _mm_srli_epi32::<31>(_mm_castps_si128(differ));
        let delta = _mm_sub_epi32(_mm_set1_epi32(1), _mm_slli_epi32::<1>(signs));
        _mm_castsi128_ps(_mm_add_epi32(_mm_castps_si128(p), delta))
    }
}
