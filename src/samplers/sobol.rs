//! Owen-scrambled Sobol points: well spread points of the unit square, a different
//! random-looking copy for every pixel and dimension (pbrt-v4, section 8.7).
//!
//! The first two dimensions of the Sobol sequence form a (0,2)-sequence: every
//! block of `2^k` consecutive points, starting at a multiple of `2^k`, puts exactly one
//! point in each of the `2^k` boxes `[a/2^i, (a+1)/2^i) x [b/2^j, (b+1)/2^j)` with
//! `i + j = k` (the "elementary intervals"). Owen scrambling flips each binary digit
//! of a coordinate according to a hash of the digits above it, which keeps that
//! property and makes every scrambled copy as likely as any other.

// ANCHOR: sobol_pair
/// The first two Sobol coordinates of point `index`, as 32-bit binary fractions: the
/// van der Corput sequence (the bits of `index` mirrored) and the second dimension,
/// whose direction numbers are `v_0 = 1/2`, `v_k = v_(k-1) xor v_(k-1)/2`.
pub fn sobol_pair(index: u32) -> (u32, u32) {
    let mut second = 0;
    let mut direction = 1 << 31;
    let mut rest = index;
    while rest != 0 {
        if rest & 1 == 1 {
            second ^= direction;
        }
        direction ^= direction >> 1;
        rest >>= 1;
    }
    (index.reverse_bits(), second)
}
// ANCHOR_END: sobol_pair

// ANCHOR: owen_scramble
/// `value`, a 32-bit binary fraction, Owen-scrambled with `seed`: each binary digit
/// is flipped according to `seed` and the digits above it, so points that share
/// their first digits are moved alike and stay spread. With the digits mirrored,
/// "the digits above" become the lower bits, and multiplying by a constant, adding
/// or xoring a multiple of itself only ever carries lower bits into higher ones:
/// the hash of Laine and Karras, as refined by Burley and in pbrt-v4's
/// `FastOwenScrambler`.
pub fn owen_scramble(value: u32, seed: u64) -> u32 {
    let seed = seed as u32 ^ (seed >> 32) as u32;
    let mut v = value.reverse_bits();
    v ^= v.wrapping_mul(0x3d20_adea);
    v = v.wrapping_add(seed);
    v = v.wrapping_mul((seed >> 16) | 1);
    v ^= v.wrapping_mul(0x0552_6c56);
    v ^= v.wrapping_mul(0x53a2_2864);
    v.reverse_bits()
}
// ANCHOR_END: owen_scramble

/// The place of `index` in a random-looking permutation of `0..count` chosen by
/// `seed`: the bits of `index` scrambled as in [`owen_scramble`] (a one-to-one map
/// of `0..2^k`, the next power of two), repeated until the result falls below
/// `count` ("cycle walking").
pub fn permute(index: u32, count: u32, seed: u64) -> u32 {
    debug_assert!(index < count);
    let bits = count.next_power_of_two().trailing_zeros();
    if bits == 0 {
        return 0;
    }
    let mut value = index;
    loop {
        value = owen_scramble(value << (32 - bits), seed) >> (32 - bits);
        if value < count {
            return value;
        }
    }
}

/// A 64-bit hash with well mixed bits (pbrt-v4's `MixBits`).
pub fn mix_bits(mut v: u64) -> u64 {
    v ^= v >> 31;
    v = v.wrapping_mul(0x7fb5_d329_728e_a185);
    v ^= v >> 27;
    v = v.wrapping_mul(0x81da_def4_bc2d_d44d);
    v ^ (v >> 33)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_points_are_the_textbooks() {
        let points: Vec<(u32, u32)> = (0..4).map(sobol_pair).collect();
        let half = 1 << 31;
        assert_eq!(
            points,
            vec![
                (0, 0),
                (half, half),
                (half >> 1, half | half >> 1),
                (half | half >> 1, half >> 1)
            ]
        );
    }

    #[test]
    fn scrambling_and_permuting_are_one_to_one() {
        for seed in [1, 2, 0xdead_beef] {
            let mut seen = [false; 256];
            for v in 0..256u32 {
                let top = owen_scramble(v << 24, seed) >> 24;
                assert!(!seen[top as usize], "seed {seed}: {v} collides");
                seen[top as usize] = true;
            }
            for count in [1, 7, 100, 128] {
                let mut places: Vec<u32> = (0..count).map(|i| permute(i, count, seed)).collect();
                places.sort_unstable();
                assert_eq!(places, (0..count).collect::<Vec<_>>());
            }
        }
    }

    #[test]
    fn different_seeds_scramble_differently() {
        let a: Vec<u32> = (0..16).map(|i| owen_scramble(i << 28, 1)).collect();
        let b: Vec<u32> = (0..16).map(|i| owen_scramble(i << 28, 2)).collect();
        assert_ne!(a, b);
    }
}
