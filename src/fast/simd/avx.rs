//! The four-ray sphere test and the four hits' shading in AVX instructions, four
//! `f64` per instruction, on the x86-64 processors that have them (almost all made
//! since 2011). The processor is asked at run time ([`Avx::detect`]), so the build
//! needs no flag.
//!
//! Every function here is a safe function compiled with AVX
//! (`#[target_feature(enable = "avx")]`): inside them the AVX instructions are safe
//! to call. Calling one from code compiled without AVX is not, and is done in one
//! place, the methods of [`Avx`], which hold the proof that the processor has
//! AVX. Those calls are this file's only `unsafe` code (the eight-lane tests of the
//! fast hierarchy, in `avx_lanes`, follow the same rule).
#![allow(unsafe_code)]

use std::arch::x86_64::{
    __m128d, __m256d, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_OQ, _mm_add_epi64,
    _mm_castpd_si128, _mm_castsi128_pd, _mm_cvtsd_f64, _mm_set1_epi64x, _mm_slli_epi64,
    _mm_srli_epi64, _mm_sub_epi64, _mm_unpackhi_pd, _mm256_add_pd, _mm256_and_pd, _mm256_andnot_pd,
    _mm256_blendv_pd, _mm256_castpd128_pd256, _mm256_castpd256_pd128, _mm256_cmp_pd, _mm256_div_pd,
    _mm256_extractf128_pd, _mm256_insertf128_pd, _mm256_max_pd, _mm256_movemask_pd, _mm256_mul_pd,
    _mm256_or_pd, _mm256_set_pd, _mm256_set1_pd, _mm256_sqrt_pd, _mm256_sub_pd, _mm256_xor_pd,
};

use crate::fast::paths::shading::{
    FourVectors, LightSamples, PointLit, SphereHits, four_hit_shading,
};
use crate::fast::simd::lanes::four_ray_sphere_test;
use crate::geometry::{Hit, Ray};
use crate::lights::PointLight;
use crate::maths::{Colour, Vec3};

/// Four `f64`, one per lane of an AVX register.
type L = __m256d;

/// Proof that this processor has AVX: made only by [`Avx::detect`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Avx(());

impl Avx {
    /// `Some` where the processor has AVX.
    pub fn detect() -> Option<Avx> {
        std::arch::is_x86_feature_detected!("avx").then_some(Avx(()))
    }

    /// The four-ray test of [`crate::fast::simd::lanes`] (its `nearest_of_four`) in AVX
    /// instructions, on this processor, which has them.
    pub fn nearest_of_four(
        self,
        spheres: &[[f64; 5]],
        rays: [&Ray; 4],
    ) -> [Option<(f64, usize)>; 4] {
        // SAFETY: an `Avx` is made only by `detect`, where the processor has AVX, so
        // the AVX instructions of `nearest_of_four` can run.
        unsafe { nearest_of_four(spheres, rays) }
    }

    /// The hit records of [`crate::fast::paths::shading`] (its `sphere_hits`) in AVX
    /// instructions.
    pub fn sphere_hits(self, rays: [&Ray; 4], t: [f64; 4], spheres: [&[f64; 5]; 4]) -> SphereHits {
        // SAFETY: as in `nearest_of_four`, an `Avx` proves the processor has AVX.
        unsafe { sphere_hits(rays, t, spheres) }
    }

    /// The direct light of [`crate::fast::paths::shading`] (its `point_light`) in AVX
    /// instructions.
    pub fn point_light(self, hits: [&Hit; 4], albedo: [Colour; 4], light: &PointLight) -> PointLit {
        // SAFETY: as in `nearest_of_four`, an `Avx` proves the processor has AVX.
        unsafe { point_light(hits, albedo, light) }
    }

    /// The light samples of [`crate::fast::paths::shading`] (its `sphere_light`) in AVX
    /// instructions.
    pub fn sphere_light(
        self,
        hits: [&Hit; 4],
        albedo: [Colour; 4],
        samples: [[f64; 3]; 4],
        light: (Vec3, f64, Colour),
    ) -> LightSamples {
        // SAFETY: as in `nearest_of_four`, an `Avx` proves the processor has AVX.
        unsafe { sphere_light(hits, albedo, samples, light) }
    }

    /// The bounces of [`crate::fast::paths::shading`] (its `bounces`) in AVX instructions.
    pub fn bounces(self, hits: [&Hit; 4], samples: [[f64; 3]; 4]) -> (FourVectors, FourVectors) {
        // SAFETY: as in `nearest_of_four`, an `Avx` proves the processor has AVX.
        unsafe { bounces(hits, samples) }
    }
}

#[target_feature(enable = "avx")]
#[inline]
fn splat(x: f64) -> L {
    _mm256_set1_pd(x)
}
#[target_feature(enable = "avx")]
#[inline]
fn gather(values: [f64; 4]) -> L {
    _mm256_set_pd(values[3], values[2], values[1], values[0])
}
#[target_feature(enable = "avx")]
#[inline]
fn lanes(v: L) -> [f64; 4] {
    let (low, high) = (_mm256_castpd256_pd128(v), _mm256_extractf128_pd::<1>(v));
    let second = |half| _mm_cvtsd_f64(_mm_unpackhi_pd(half, half));
    [
        _mm_cvtsd_f64(low),
        second(low),
        _mm_cvtsd_f64(high),
        second(high),
    ]
}
#[target_feature(enable = "avx")]
#[inline]
fn add(a: L, b: L) -> L {
    _mm256_add_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn sub(a: L, b: L) -> L {
    _mm256_sub_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn mul(a: L, b: L) -> L {
    _mm256_mul_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn div(a: L, b: L) -> L {
    _mm256_div_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn neg(a: L) -> L {
    _mm256_xor_pd(a, _mm256_set1_pd(-0.0))
}
#[target_feature(enable = "avx")]
#[inline]
fn sqrt(a: L) -> L {
    _mm256_sqrt_pd(a)
}
#[target_feature(enable = "avx")]
#[inline]
fn abs(a: L) -> L {
    _mm256_andnot_pd(_mm256_set1_pd(-0.0), a)
}
#[target_feature(enable = "avx")]
#[inline]
fn max(a: L, b: L) -> L {
    _mm256_max_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn or(a: L, b: L) -> L {
    _mm256_or_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn and(a: L, b: L) -> L {
    _mm256_and_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn and_not(a: L, b: L) -> L {
    _mm256_andnot_pd(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn lt(a: L, b: L) -> L {
    _mm256_cmp_pd::<_CMP_LT_OQ>(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn gt(a: L, b: L) -> L {
    _mm256_cmp_pd::<_CMP_GT_OQ>(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn ge(a: L, b: L) -> L {
    _mm256_cmp_pd::<_CMP_GE_OQ>(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn ne(a: L, b: L) -> L {
    _mm256_cmp_pd::<_CMP_NEQ_OQ>(a, b)
}
#[target_feature(enable = "avx")]
#[inline]
fn all(mask: L) -> bool {
    _mm256_movemask_pd(mask) == 0b1111
}
/// The float next to `p` (finite, not zero) away from zero where `o` (not zero) has
/// the sign of `p`, towards zero where it has the other: the bits of `p` plus one,
/// or minus one, as in `one_ulp_towards`; in two halves, AVX having no 64-bit
/// integer addition on its full registers.
#[target_feature(enable = "avx")]
#[inline]
fn step_towards(p: L, o: L) -> L {
    let differ = _mm256_xor_pd(p, o);
    let low = step_half(_mm256_castpd256_pd128(p), _mm256_castpd256_pd128(differ));
    let high = step_half(
        _mm256_extractf128_pd::<1>(p),
        _mm256_extractf128_pd::<1>(differ),
    );
    _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(low), high)
}
/// `step_towards` on two lanes, `differ` holding the bits of `p ^ o`.
#[target_feature(enable = "avx")]
#[inline]
fn step_half(p: __m128d, differ: __m128d) -> __m128d {
    let signs = _mm_srli_epi64::<63>(_mm_castpd_si128(differ));
    let delta = _mm_sub_epi64(_mm_set1_epi64x(1), _mm_slli_epi64::<1>(signs));
    _mm_castsi128_pd(_mm_add_epi64(_mm_castpd_si128(p), delta))
}
#[target_feature(enable = "avx")]
#[inline]
fn select(mask: L, a: L, b: L) -> L {
    _mm256_blendv_pd(b, a, mask)
}

four_ray_sphere_test!(#[target_feature(enable = "avx")]);
four_hit_shading!(#[target_feature(enable = "avx")]);
