//! The slab test of a node's eight boxes in AVX instructions, eight `f32` per
//! instruction, on the x86-64 processors that have them. The processor is asked at
//! run time ([`AvxBoxes::detect`]), so the build needs no flag.
//!
//! As in [`crate::fast::avx`], the functions using AVX are compiled with it
//! (`#[target_feature(enable = "avx")]`), and code compiled without it calls them
//! only where an [`AvxBoxes`] proves that the processor has AVX.
#![allow(unsafe_code)]

use std::arch::x86_64::{
    __m256, _CMP_LE_OQ, _mm256_cmp_ps, _mm256_load_ps, _mm256_max_ps, _mm256_min_ps,
    _mm256_movemask_ps, _mm256_mul_ps, _mm256_set1_ps, _mm256_setzero_ps, _mm256_storeu_ps,
    _mm256_sub_ps,
};

use crate::fast::wide_node::{Limit, NodeTest, WIDENING, WIDTH, WideNode, WideRay};

/// Proof that this processor has AVX: made only by [`AvxBoxes::detect`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AvxBoxes(());

impl AvxBoxes {
    /// `Some` where the processor has AVX.
    pub fn detect() -> Option<AvxBoxes> {
        std::arch::is_x86_feature_detected!("avx").then_some(AvxBoxes(()))
    }

    /// Runs `search` compiled with AVX, so that the slab tests it makes inline
    /// into it as AVX instructions instead of being called one node at a time.
    #[inline(always)]
    pub fn run<T>(self, search: impl FnOnce(AvxBoxes) -> T) -> T {
        // SAFETY: an `AvxBoxes` is made only by `detect`, where the processor has
        // AVX, so code compiled with AVX can run.
        unsafe { with_avx(self, search) }
    }
}

/// `search(avx)`, compiled with AVX.
#[target_feature(enable = "avx")]
fn with_avx<T>(avx: AvxBoxes, search: impl FnOnce(AvxBoxes) -> T) -> T {
    search(avx)
}

impl NodeTest for AvxBoxes {
    /// The slab test of [`Portable`](crate::fast::wide_node::Portable), on the
    /// eight boxes at once.
    #[inline(always)]
    fn enters(self, ray: &WideRay, node: &WideNode, limit: Limit) -> (u32, [f32; WIDTH]) {
        // SAFETY: an `AvxBoxes` is made only by `detect`, where the processor has
        // AVX.
        unsafe { enters(ray, node, limit) }
    }
}

/// The eight lanes of `plane` of `node`.
#[target_feature(enable = "avx")]
#[inline]
fn plane(node: &WideNode, plane: usize) -> __m256 {
    // SAFETY: `planes[plane]` is eight `f32`, 32-byte aligned (a node is aligned to
    // 64 bytes and each plane is 32 bytes long).
    unsafe { _mm256_load_ps(node.planes[plane].as_ptr()) }
}

#[target_feature(enable = "avx")]
#[inline]
fn enters(ray: &WideRay, node: &WideNode, limit: Limit) -> (u32, [f32; WIDTH]) {
    let mut entry = _mm256_setzero_ps();
    let mut exit = _mm256_set1_ps(f32::INFINITY);
    for axis in 0..3 {
        let inv_direction = _mm256_set1_ps(ray.inv_direction[axis]);
        let crossing = |p: usize, origin: f32| {
            _mm256_mul_ps(
                _mm256_sub_ps(plane(node, p), _mm256_set1_ps(origin)),
                inv_direction,
            )
        };
        entry = _mm256_max_ps(entry, crossing(ray.near[axis], ray.near_origin[axis]));
        exit = _mm256_min_ps(exit, crossing(ray.far[axis], ray.far_origin[axis]));
    }
    let exit = _mm256_min_ps(
        _mm256_mul_ps(exit, _mm256_set1_ps(WIDENING)),
        _mm256_set1_ps(limit.0),
    );
    let mask = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(entry, exit)) as u32;
    let mut entries = [0.0; WIDTH];
    // SAFETY: `entries` holds eight `f32`.
    unsafe { _mm256_storeu_ps(entries.as_mut_ptr(), entry) };
    (mask, entries)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fast::wide_node::Portable;
    use crate::geometry::Ray;
    use crate::maths::{Real, Vec3, pixel_rng, to_single, uniform};

    /// The AVX lanes and the portable ones report the same boxes entered at the same
    /// distances, to the bit, for rays in every direction, parallel to the axes
    /// (zero components, of either sign) and starting inside boxes, and for empty
    /// slots.
    #[test]
    fn avx_and_portable_lanes_agree_to_the_bit() {
        let Some(avx) = AvxBoxes::detect() else {
            return;
        };
        let mut rng = pixel_rng(11, 0);
        let mut coordinate = |r: Real| (uniform(&mut rng) * 2.0 - 1.0) * r;
        let mut entered = 0;
        for trial in 0..20_000 {
            let mut node = WideNode::EMPTY;
            for lane in 0..WIDTH - trial % 3 {
                for axis in 0..3 {
                    let (a, b) = (coordinate(2.0), coordinate(2.0));
                    node.planes[axis][lane] = to_single(a.min(b));
                    node.planes[axis + 3][lane] = to_single(a.max(b));
                }
            }
            let mut direction = Vec3::new(coordinate(1.0), coordinate(1.0), coordinate(1.0));
            direction[trial % 4 % 3] *= if trial % 8 < 4 { 0.0 } else { 1.0 };
            direction[(trial + 1) % 3] *= if trial % 16 == 0 { -0.0 } else { 1.0 };
            let ray = Ray::new(
                Vec3::new(coordinate(1.0), coordinate(1.0), coordinate(1.0)),
                direction.normalize(),
            );
            let wide = WideRay::new(&ray, ray.direction.recip());
            let limit = Limit::new(coordinate(10.0).abs());
            let (mask, entries) = avx.run(|avx| avx.enters(&wide, &node, limit));
            let (portable_mask, portable_entries) = Portable.enters(&wide, &node, limit);
            assert_eq!(mask, portable_mask, "{ray:?} {node:?}");
            for lane in 0..WIDTH {
                if mask & (1 << lane) != 0 {
                    assert_eq!(entries[lane].to_bits(), portable_entries[lane].to_bits());
                }
            }
            entered += mask.count_ones();
        }
        assert!(
            entered > 20_000,
            "only {entered} boxes entered: the test is vacuous"
        );
    }
}
