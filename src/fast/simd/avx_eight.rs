//! Eight `f32` in one AVX register: the lanes of the fast hierarchy's tests (a
//! node's eight boxes, a group's eight triangles) on the processors that have AVX,
//! and in single precision those of the paths followed at once too
//! (`avx_eight_reals`).
#![allow(unsafe_code)]

use std::arch::x86_64::{
    __m256, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_LT_OQ, _mm256_add_ps, _mm256_and_ps, _mm256_andnot_ps,
    _mm256_cmp_ps, _mm256_div_ps, _mm256_max_ps, _mm256_min_ps, _mm256_movemask_ps, _mm256_mul_ps,
    _mm256_or_ps, _mm256_set1_ps, _mm256_sub_ps, _mm256_xor_ps,
};
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Sub};

use crate::fast::simd::float_lanes::FloatLanes;

/// Eight `f32` in an AVX register, made only from an [`Avx`](super::avx::Avx).
#[derive(Clone, Copy)]
pub struct Eight(pub(super) __m256);

/// Implements a binary operator of [`Eight`] by an AVX instruction.
macro_rules! eight_operator {
    ($trait:ident, $method:ident, $instruction:ident) => {
        impl $trait for Eight {
            type Output = Eight;
            #[inline(always)]
            fn $method(self, other: Eight) -> Eight {
                // SAFETY: an `Eight` exists only where the processor has AVX.
                Eight(unsafe { $instruction(self.0, other.0) })
            }
        }
    };
}

eight_operator!(Add, add, _mm256_add_ps);
eight_operator!(Sub, sub, _mm256_sub_ps);
eight_operator!(Mul, mul, _mm256_mul_ps);
eight_operator!(Div, div, _mm256_div_ps);
eight_operator!(BitAnd, bitand, _mm256_and_ps);
eight_operator!(BitOr, bitor, _mm256_or_ps);

impl Mul<f32> for Eight {
    type Output = Eight;
    #[inline(always)]
    fn mul(self, x: f32) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        self * Eight(unsafe { _mm256_set1_ps(x) })
    }
}

impl Neg for Eight {
    type Output = Eight;
    #[inline(always)]
    fn neg(self) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_xor_ps(self.0, _mm256_set1_ps(-0.0)) })
    }
}

impl FloatLanes for Eight {
    /// A comparison's result: all ones in a true lane, zeros in a false one.
    type Mask = Eight;
    const LANES: usize = 8;

    #[inline(always)]
    fn abs(self) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_andnot_ps(_mm256_set1_ps(-0.0), self.0) })
    }

    #[inline(always)]
    fn lt(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_LT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn gt(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_GT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn le(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_LE_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn max(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_max_ps(self.0, other.0) })
    }

    #[inline(always)]
    fn min(self, other: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        Eight(unsafe { _mm256_min_ps(self.0, other.0) })
    }

    #[inline(always)]
    fn bits(mask: Eight) -> u32 {
        // SAFETY: an `Eight` exists only where the processor has AVX.
        unsafe { _mm256_movemask_ps(mask.0) as u32 }
    }
}

#[cfg(test)]
mod tests {
    use crate::fast::hierarchy::triangle_group::{GROUP, GroupRay, TriangleGroup};
    use crate::fast::hierarchy::wide_node::{EightLanes, Limit, WIDTH, WideNode, WideRay};
    use crate::fast::simd::avx::Avx;
    use crate::fast::simd::portable::Portable;
    use crate::geometry::{Ray, ShearedRay};
    use crate::maths::{Real, Vec3, pixel_rng, to_single, uniform};

    /// The AVX lanes and the portable ones report the same boxes entered at the same
    /// distances, to the bit, for rays in every direction, parallel to the axes
    /// (zero components, of either sign) and starting inside boxes, and for empty
    /// slots.
    #[test]
    #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
    fn avx_and_portable_lanes_enter_the_same_boxes_to_the_bit() {
        let avx = Avx::for_test();
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
            let (mask, entries) = avx.enters(&wide, &node, limit);
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

    /// The AVX lanes and the portable ones keep the same triangles of a group, for
    /// rays aimed at the group's corners from near and far.
    #[test]
    #[cfg_attr(not(processor_has_avx), ignore = "this processor has no AVX")]
    fn avx_and_portable_lanes_keep_the_same_triangles() {
        let avx = Avx::for_test();
        let mut rng = pixel_rng(12, 0);
        let mut point = |r: Real| {
            Vec3::new(uniform(&mut rng), uniform(&mut rng), uniform(&mut rng)) * (2.0 * r)
                - Vec3::splat(r)
        };
        let (mut kept, mut set_aside) = (0, 0);
        for trial in 0..20_000 {
            let triangles: Vec<[Vec3; 3]> = (0..1 + trial % GROUP)
                .map(|_| {
                    let centre = point(1.0);
                    [0, 1, 2].map(|_| centre + point(0.05))
                })
                .collect();
            let group = TriangleGroup::new(&triangles);
            let target = triangles[0][trial % 3];
            let origin = target + point(if trial % 2 == 0 { 2.0 } else { 1e-3 });
            let ray = Ray::new(origin, (target - origin).normalize());
            let group_ray = GroupRay::new(&ShearedRay::new(&ray));
            let lanes = avx.candidates(&group, &group_ray);
            assert_eq!(lanes, group.candidates(&group_ray), "{ray:?} {triangles:?}");
            kept += lanes.count_ones();
            set_aside += 8 - lanes.count_ones();
        }
        assert!(
            kept > 20_000 && set_aside > 20_000,
            "{kept} kept, {set_aside} set aside"
        );
    }
}
