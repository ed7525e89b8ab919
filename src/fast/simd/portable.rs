//! The four-ray sphere test and the four hits' shading on any processor: the lanes
//! of the `wide` crate, which uses the SIMD instructions the build targets (two
//! `f64` per instruction on any x86-64) and plain arithmetic elsewhere.

use crate::fast::paths::shading::four_hit_shading;
use crate::fast::simd::lanes::four_ray_sphere_test;
use crate::maths::Real;

/// Four [`Real`] numbers, one per lane.
#[cfg(not(feature = "f32"))]
type L = wide::f64x4;
/// Four [`Real`] numbers, one per lane.
#[cfg(feature = "f32")]
type L = wide::f32x4;

/// `x` in every lane.
#[inline]
fn splat(x: Real) -> L {
    L::splat(x)
}
/// The four numbers of `values`, one per lane.
#[inline]
fn gather(values: [Real; 4]) -> L {
    L::from(values)
}
/// The four numbers of `v`.
#[inline]
fn lanes(v: L) -> [Real; 4] {
    v.to_array()
}
/// `a + b`, lane by lane.
#[inline]
fn add(a: L, b: L) -> L {
    a + b
}
/// `a - b`, lane by lane.
#[inline]
fn sub(a: L, b: L) -> L {
    a - b
}
/// `a * b`, lane by lane.
#[inline]
fn mul(a: L, b: L) -> L {
    a * b
}
/// `a / b`, lane by lane.
#[inline]
fn div(a: L, b: L) -> L {
    a / b
}
/// `-a`, lane by lane (the sign bit flipped).
#[inline]
fn neg(a: L) -> L {
    -a
}
/// The square root of `a`, lane by lane.
#[inline]
fn sqrt(a: L) -> L {
    a.sqrt()
}
/// `|a|`, lane by lane (the sign bit cleared).
#[inline]
fn abs(a: L) -> L {
    a.abs()
}
/// The larger of `a` and `b`, lane by lane; `b` where `a` is NaN.
#[inline]
fn max(a: L, b: L) -> L {
    a.max(b)
}
/// The bits of `a` or those of `b`.
#[inline]
fn or(a: L, b: L) -> L {
    a | b
}
/// The bits of `a` and those of `b`.
#[inline]
fn and(a: L, b: L) -> L {
    a & b
}
/// The bits of `b` where those of `a` are clear.
#[inline]
fn and_not(a: L, b: L) -> L {
    !a & b
}
/// A mask, all ones in the lanes where `a < b`.
#[inline]
fn lt(a: L, b: L) -> L {
    a.simd_lt(b)
}
/// A mask, all ones in the lanes where `a > b`.
#[inline]
fn gt(a: L, b: L) -> L {
    a.simd_gt(b)
}
/// A mask, all ones in the lanes where `a >= b`.
#[inline]
fn ge(a: L, b: L) -> L {
    a.simd_ge(b)
}
/// A mask, all ones in the lanes where `a != b`.
#[inline]
fn ne(a: L, b: L) -> L {
    a.simd_ne(b)
}
/// Whether every lane of `mask` is set.
#[inline]
fn all(mask: L) -> bool {
    mask.all()
}
/// The float next to `p` (finite, not zero) away from zero where `o` (not zero) has
/// the sign of `p`, towards zero where it has the other: the bits of `p` plus one,
/// or minus one, as in `one_ulp_towards`.
#[cfg(not(feature = "f32"))]
#[inline]
fn step_towards(p: L, o: L) -> L {
    use wide::{bytemuck::cast, u64x4};
    let (bits, differ): (u64x4, u64x4) = (cast(p), cast(p ^ o));
    cast(bits + u64x4::splat(1) - ((differ >> 63) << 1))
}
/// The float next to `p` (finite, not zero) away from zero where `o` (not zero) has
/// the sign of `p`, towards zero where it has the other: the bits of `p` plus one,
/// or minus one, as in `one_ulp_towards`.
#[cfg(feature = "f32")]
#[inline]
fn step_towards(p: L, o: L) -> L {
    use wide::{bytemuck::cast, u32x4};
    let (bits, differ): (u32x4, u32x4) = (cast(p), cast(p ^ o));
    cast(bits + u32x4::splat(1) - ((differ >> 31) << 1))
}
/// `a` in the lanes where `mask` is set, `b` in the others.
#[inline]
fn select(mask: L, a: L, b: L) -> L {
    mask.select(a, b)
}

four_ray_sphere_test!();
four_hit_shading!();
