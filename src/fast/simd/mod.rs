//! The lanes the fast engine computes on: one operation on several numbers at once
//! (SIMD), on any processor and in AVX instructions on the x86-64 ones that have them.
//!
//! | file | what it holds | in place of |
//! |---|---|---|
//! | [`lanes`] | the four-ray sphere test, written once for any type of lanes | `Sphere::intersect` |
//! | [`portable`] | its lanes on any processor (the `wide` crate) | |
//! | `avx` | its lanes in AVX instructions, on x86-64 | |
//! | [`four_lanes`] | the choice of AVX or portable lanes for the sphere test (`lanes`) and the shading (`shading`) | |
//! | [`float_lanes`] | `f32` lanes as one type, for the triangle groups' test | |
//! | `avx_lanes` | the boxes' and triangles' tests in AVX instructions, on x86-64 | |

#[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
pub mod avx;
#[cfg(target_arch = "x86_64")]
pub mod avx_lanes;
pub mod float_lanes;
pub mod four_lanes;
pub mod lanes;
pub mod portable;
