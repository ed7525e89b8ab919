//! Sine and cosine on lanes: the angles of [`LANES`](super::real_lanes::LANES)
//! bounces or light samples at once, where the C library's `sin` and `cos` take one
//! number at a time.
//!
//! The method is the C library's own, written with the lanes' operators:
//!
//! 1. **Reduce.** `k` is the integer nearest `x / (pi/2)`, and `r = x - k pi/2`, in
//!    `[-pi/4, pi/4]`. `pi/2` is split into parts of few significant bits each
//!    (Cody and Waite), so that `k` times each part is exact and `r` keeps its
//!    relative precision even next to a zero of the sine or the cosine.
//! 2. **Approximate.** On `[-pi/4, pi/4]`, `sin r = r + r z P(z)` and
//!    `cos r = 1 - z/2 + z^2 Q(z)`, with `z = r^2` and `P`, `Q` minimax polynomials:
//!    fdlibm's in double precision, Cephes's in single.
//! 3. **Turn by quarters.** With `q = k mod 4`, `sin x` is `sin r`, `cos r`,
//!    `-sin r`, `-cos r` for `q = 0, 1, 2, 3`, and `cos x` is the sine a quarter
//!    turn on: `cos r`, `-sin r`, `-cos r`, `sin r`.
//!
//! The bound, tested over ten million angles for each precision: within 2 units in
//! the last place of the C library's `sin` and `cos` for `|x| <= 256` (the fast
//! engine's angles lie in `[0, 2 pi)`), next to the zeros of either included; the
//! largest difference measured is 1 unit in double precision and 2 in single. The
//! last bits may differ from the C library's, which the fast engine's promise allows:
//! the same image, not the same last bits.

use crate::fast::simd::real_lanes::{RealLanes, RealSource};
use crate::maths::Real;

/// `2/pi`, rounded.
const TWO_OVER_PI: Real = std::f64::consts::FRAC_2_PI as Real;

/// `1.5 2^(p-1)`, `p` the significand's bits: added to a number below `2^(p-2)` in
/// size and subtracted again, it rounds the number to the nearest integer, which the
/// sum keeps in its lowest bits.
const ROUNDER: Real = (3u64 << (Real::MANTISSA_DIGITS - 2)) as Real;

/// `pi/2` in parts whose sum is `pi/2` to 119 bits, the first two of 33 significant
/// bits, so that `k` times them is exact for `|k| < 2^20`.
#[cfg(not(feature = "f32"))]
const HALF_PI_PARTS: [Real; 3] = [
    1.5707963267341256,
    6.077100506303966e-11,
    2.0222662487959506e-21,
];
/// `pi/2` in parts whose sum is `pi/2` to 77 bits, the first three of 16 significant
/// bits, so that `k` times them is exact for `|k| < 2^8`.
#[cfg(feature = "f32")]
const HALF_PI_PARTS: [Real; 4] = [1.5707703, 2.6063062e-5, 6.0770944e-11, 6.1232336e-17];

/// `P(z)`'s coefficients, the highest power first (fdlibm's `__kernel_sin`,
/// error below 2^-58 on `[-pi/4, pi/4]`).
#[cfg(not(feature = "f32"))]
const SINE: [Real; 6] = [
    1.58969099521155e-10,
    -2.5050760253406863e-8,
    2.7557313707070068e-6,
    -1.984126982985795e-4,
    8.33333333332249e-3,
    -1.6666666666666632e-1,
];
/// `P(z)`'s coefficients, the highest power first (Cephes's `sinf`).
#[cfg(feature = "f32")]
const SINE: [Real; 3] = [-1.9515296e-4, 8.332161e-3, -1.6666655e-1];

/// `Q(z)`'s coefficients, the highest power first (fdlibm's `__kernel_cos`,
/// error below 2^-58 on `[-pi/4, pi/4]`).
#[cfg(not(feature = "f32"))]
const COSINE: [Real; 6] = [
    -1.1359647557788195e-11,
    2.087572321298175e-9,
    -2.7557314351390663e-7,
    2.480158728947673e-5,
    -1.388888888887411e-3,
    4.16666666666666e-2,
];
/// `Q(z)`'s coefficients, the highest power first (Cephes's `cosf`).
#[cfg(feature = "f32")]
const COSINE: [Real; 3] = [2.4433157e-5, -1.3887316e-3, 4.1666646e-2];

// ANCHOR: sin_cos
/// `(sin x, cos x)` lane by lane, within 2 units in the last place of the C
/// library's for `|x| <= 256` (the module's bound).
#[inline(always)]
pub fn sin_cos<L: RealSource>(lanes: L, x: L::Wide) -> (L::Wide, L::Wide) {
    // k, the integer nearest x / (pi/2), is also in the lowest bits of `shifted`.
    let shifted = x * lanes.splat(TWO_OVER_PI) + lanes.splat(ROUNDER);
    let k = shifted - lanes.splat(ROUNDER);
    let mut r = x;
    for part in HALF_PI_PARTS {
        r = r - k * lanes.splat(part);
    }
    let z = r * r;
    let sin_r = r + r * z * polynomial(lanes, &SINE, z);
    // cos r = 1 - z/2 + z^2 Q(z), with what rounding 1 - z/2 lost added back.
    let half_z = lanes.splat(0.5) * z;
    let one = lanes.splat(1.0);
    let w = one - half_z;
    let cos_r = w + (((one - w) - half_z) + z * z * polynomial(lanes, &COSINE, z));
    // q = k mod 4, from k's two lowest bits.
    let zero = lanes.splat(0.0);
    let odd = (shifted & lanes.splat(Real::from_bits(1))).ne(zero);
    let past_half_turn = (shifted & lanes.splat(Real::from_bits(2))).ne(zero);
    let (sin, cos) = (odd.select(cos_r, sin_r), odd.select(sin_r, cos_r));
    let sin = past_half_turn.select(-sin, sin);
    let cos = past_half_turn.select(-cos, cos);
    (sin, odd.select(-cos, cos))
}
// ANCHOR_END: sin_cos

/// `c[0] z^(n-1) + c[1] z^(n-2) + ... + c[n-1]`, by Horner's rule.
#[inline(always)]
fn polynomial<L: RealSource, const N: usize>(lanes: L, c: &[Real; N], z: L::Wide) -> L::Wide {
    let mut sum = lanes.splat(c[0]);
    for &coefficient in &c[1..] {
        sum = sum * z + lanes.splat(coefficient);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fast::simd::portable::Portable;
    use crate::fast::simd::real_lanes::LANES;
    use crate::maths::PI;

    /// How far `found` is from `expected`, in units in the last place of
    /// `expected`.
    fn ulps(found: Real, expected: Real) -> Real {
        let size = expected.abs();
        let ulp = Real::from_bits(size.to_bits() + 1) - size;
        (found - expected).abs() / ulp
    }

    /// The largest error, in units in the last place, of the lanes' sines and
    /// cosines of `angles`, against the C library's.
    fn worst_on<L: RealSource>(lanes: L, angles: impl Iterator<Item = Real>) -> Real {
        let mut worst: Real = 0.0;
        let mut batch = [0.0; LANES];
        for (i, x) in angles.enumerate() {
            batch[i % LANES] = x;
            if i % LANES == LANES - 1 {
                let (sin, cos) = sin_cos(lanes, lanes.gather(batch));
                for (k, x) in batch.iter().enumerate() {
                    worst = worst.max(ulps(sin.to_array()[k], x.sin()));
                    worst = worst.max(ulps(cos.to_array()[k], x.cos()));
                }
            }
        }
        worst
    }

    /// Ten million angles: eight million over the fast engine's `[0, 2 pi)`, evenly
    /// spaced, and two million over `[-256, 256]`.
    fn angles() -> impl Iterator<Item = Real> {
        let turn = (0..8_000_000).map(|i| 2.0 * PI * (i as Real / 8e6));
        let wide = (0..2_000_000).map(|i| -256.0 + 512.0 * (i as Real / 2e6));
        turn.chain(wide)
    }

    #[test]
    fn the_lanes_sines_and_cosines_are_within_two_ulps_of_the_c_library() {
        let worst = worst_on(Portable, angles());
        assert!(worst <= 2.0, "{worst} ulps");
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
    fn the_avx_lanes_sines_and_cosines_are_the_portable_lanes_to_the_bit() {
        let avx = crate::fast::simd::avx::Avx::for_test();
        let worst = worst_on(avx, angles());
        assert_eq!(worst.to_bits(), worst_on(Portable, angles()).to_bits());
    }

    #[test]
    fn the_quarter_turns_and_their_neighbours_have_the_signs_and_sizes_of_the_c_library() {
        let quarters = (-8..=8).map(|q| q as Real * PI / 2.0);
        let near = quarters.flat_map(|x| {
            let up = Real::from_bits(x.to_bits() + 1);
            [
                x,
                up,
                -x,
                -up,
                x * (1.0 + Real::EPSILON),
                x * (1.0 - Real::EPSILON),
            ]
        });
        let padded = near.chain(std::iter::repeat_n(1.0, LANES));
        assert!(worst_on(Portable, padded) <= 2.0);
        let (sin, cos) = sin_cos(Portable, Portable.splat(0.0));
        assert_eq!((sin.to_array()[0], cos.to_array()[0]), (0.0, 1.0));
    }
}
