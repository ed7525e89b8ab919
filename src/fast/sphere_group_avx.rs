//! [`Group::intersect`] with AVX instructions, four `f64` per instruction, for the
//! x86-64 processors that have them (almost all made since 2011). The portable
//! version works on two numbers per instruction; this one needs no change to the
//! build, as the processor is asked at run time ([`SphereLanes`]).
//!
//! [`SphereLanes`]: crate::fast::sphere_lanes::SphereLanes

use std::arch::x86_64::{
    __m256d, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_OQ, _mm256_add_pd, _mm256_and_pd,
    _mm256_andnot_pd, _mm256_blendv_pd, _mm256_cmp_pd, _mm256_div_pd, _mm256_loadu_pd,
    _mm256_mul_pd, _mm256_or_pd, _mm256_set1_pd, _mm256_setzero_pd, _mm256_sqrt_pd,
    _mm256_storeu_pd, _mm256_sub_pd, _mm256_xor_pd,
};

use crate::fast::sphere_group::{Group, LANES, nearest_with};
use crate::geometry::Ray;

/// The nearest sphere of `groups` that `ray` hits: [`nearest_with`] and
/// [`intersect`], compiled together with AVX.
///
/// # Safety
///
/// The processor must have AVX.
#[target_feature(enable = "avx")]
pub unsafe fn nearest(groups: &[Group], ray: &Ray) -> Option<(f64, usize)> {
    // SAFETY: this function runs only where the processor has AVX.
    nearest_with(groups, ray, |group, ray| unsafe { intersect(group, ray) })
}

/// For each sphere of `group`, the smallest `t > 0` at which `ray` meets it, or
/// infinity: `meet` with the ray copied into every lane.
///
/// # Safety
///
/// The processor must have AVX.
#[target_feature(enable = "avx")]
#[inline]
pub unsafe fn intersect(group: &Group, ray: &Ray) -> [f64; LANES] {
    let splat = |v: crate::maths::Vec3| v.to_array().map(|x| _mm256_set1_pd(x));
    // SAFETY: each array holds four f64, read unaligned.
    let [x, y, z, radius] = [group.x, group.y, group.z, group.radius]
        .map(|lane| unsafe { _mm256_loadu_pd(lane.as_ptr()) });
    lanes(meet(
        splat(ray.origin),
        splat(ray.direction),
        [x, y, z],
        radius,
    ))
}

/// For each of four `rays`, the distance to the nearest of `groups`' spheres it hits
/// and that sphere's index: [`SphereLanes::nearest_of_four`], one AVX instruction
/// per step.
///
/// # Safety
///
/// The processor must have AVX.
///
/// [`SphereLanes::nearest_of_four`]: crate::fast::sphere_lanes::SphereLanes::nearest_of_four
#[target_feature(enable = "avx")]
pub unsafe fn nearest_of_four(spheres: &[[f64; 5]], rays: [&Ray; 4]) -> [Option<(f64, usize)>; 4] {
    let four = |f: fn(&Ray) -> f64| {
        let values = rays.map(f);
        // SAFETY: `values` holds four f64, read unaligned.
        unsafe { _mm256_loadu_pd(values.as_ptr()) }
    };
    let origin = [
        four(|r| r.origin.x),
        four(|r| r.origin.y),
        four(|r| r.origin.z),
    ];
    let direction = [
        four(|r| r.direction.x),
        four(|r| r.direction.y),
        four(|r| r.direction.z),
    ];
    let mut nearest = _mm256_set1_pd(f64::INFINITY);
    let mut which = _mm256_setzero_pd();
    for &[x, y, z, radius, index] in spheres {
        let centre = [x, y, z].map(|c| _mm256_set1_pd(c));
        let t = meet(origin, direction, centre, _mm256_set1_pd(radius));
        let closer = _mm256_cmp_pd::<_CMP_LT_OQ>(t, nearest);
        nearest = _mm256_blendv_pd(nearest, t, closer);
        which = _mm256_blendv_pd(which, _mm256_set1_pd(index), closer);
    }
    let (nearest, which) = (lanes(nearest), lanes(which));
    let mut out = [None; 4];
    for k in 0..4 {
        if nearest[k] < f64::INFINITY {
            out[k] = Some((nearest[k], which[k].to_bits() as usize));
        }
    }
    out
}

/// The four numbers of `v`.
#[target_feature(enable = "avx")]
#[inline]
fn lanes(v: __m256d) -> [f64; LANES] {
    let mut out = [0.0; LANES];
    // SAFETY: `out` holds four f64, written unaligned.
    unsafe { _mm256_storeu_pd(out.as_mut_ptr(), v) };
    out
}

/// The steps of [`sphere_group::meet`](crate::fast::sphere_group::meet), one AVX
/// instruction each, in the same order: the same numbers to the last bit.
#[target_feature(enable = "avx")]
#[inline]
fn meet(
    origin: [__m256d; 3],
    direction: [__m256d; 3],
    centre: [__m256d; 3],
    radius: __m256d,
) -> __m256d {
    let [x, y, z] = centre;
    let (add, sub, mul) = (_mm256_add_pd, _mm256_sub_pd, _mm256_mul_pd);
    let [dx, dy, dz] = direction;
    let zero = _mm256_setzero_pd();
    let sign = _mm256_set1_pd(-0.0);
    let sx = sub(origin[0], x);
    let sy = sub(origin[1], y);
    let sz = sub(origin[2], z);
    let dot = |a: [__m256d; 3], b: [__m256d; 3]| {
        add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]))
    };
    let sd = dot([sx, sy, sz], [dx, dy, dz]);
    let r2 = mul(radius, radius);
    let c = sub(dot([sx, sy, sz], [sx, sy, sz]), r2);
    let m = [
        sub(sx, mul(sd, dx)),
        sub(sy, mul(sd, dy)),
        sub(sz, mul(sd, dz)),
    ];
    let discriminant = sub(r2, dot(m, m));
    let root = _mm256_or_pd(_mm256_sqrt_pd(discriminant), _mm256_and_pd(sd, sign));
    let mu = _mm256_xor_pd(add(sd, root), sign);
    let t0 = _mm256_div_pd(c, mu);
    let before = _mm256_cmp_pd::<_CMP_LT_OQ>(t0, mu);
    let near = _mm256_blendv_pd(mu, t0, before);
    let far = _mm256_blendv_pd(t0, mu, before);
    let positive = |v| _mm256_cmp_pd::<_CMP_GT_OQ>(v, zero);
    let t = _mm256_blendv_pd(far, near, positive(near));
    let away = _mm256_and_pd(positive(c), positive(sd));
    let valid = _mm256_and_pd(
        _mm256_cmp_pd::<_CMP_GE_OQ>(discriminant, zero),
        _mm256_and_pd(_mm256_cmp_pd::<_CMP_NEQ_OQ>(mu, zero), positive(far)),
    );
    let hit = _mm256_andnot_pd(away, valid);
    _mm256_blendv_pd(_mm256_set1_pd(f64::INFINITY), t, hit)
}
