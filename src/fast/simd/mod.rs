//! The lanes the fast engine computes on: one operation on several numbers at once
//! (SIMD), on any processor and in AVX instructions on the x86-64 ones that have
//! them. Each kind of lanes is a type (`Portable`, or `Avx`, the proof that the
//! processor has AVX), and the work on lanes is written once, generic over it, with
//! the usual operators: [`Real`](crate::maths::Real) lanes for the paths
//! followed at once, four `f64` or eight `f32` ([`real_lanes`]), eight `f32` lanes for the hierarchy's tests
//! ([`float_lanes`]).
//!
//! | file | what it holds |
//! |---|---|
//! | [`real_lanes`] | four or eight `Real` numbers as one type ([`real_lanes::RealLanes`]), and the kinds of lanes that make them |
//! | [`sin_cos`] | the sine and cosine of each lane, within 2 units in the last place of the C library's |
//! | [`float_lanes`] | `f32` lanes as one type ([`float_lanes::FloatLanes`]), and where they are loaded from |
//! | [`portable`] | the lanes of any processor: the `wide` crate's four `f64` or eight `f32`, and the hierarchy's eight `f32` as two halves of four |
//! | `avx` | the proof that the processor has AVX, from which alone AVX's lanes are made |
//! | `avx_four` | four `f64` in one AVX register, for the paths in double precision |
//! | `avx_eight` | eight `f32` in one AVX register, for the hierarchy |
//! | `avx_eight_reals` | the same eight `f32` as `Real` lanes, for the paths in single precision |

#[cfg(target_arch = "x86_64")]
pub mod avx;
#[cfg(target_arch = "x86_64")]
pub mod avx_eight;
#[cfg(all(target_arch = "x86_64", feature = "f32"))]
pub mod avx_eight_reals;
#[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
pub mod avx_four;
pub mod float_lanes;
pub mod portable;
pub mod real_lanes;
pub mod sin_cos;
