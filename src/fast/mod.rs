//! Beyond the course: the fast engine. It renders the same bytes as the course's
//! functions, faster, and is switched on as a whole with `--fast` (`[render] fast =
//! true`); without it, every stage runs the course's code.
//!
//! | folder | what it holds |
//! |---|---|
//! | [`simd`] | the lanes: the four-ray sphere test and the boxes' and triangles' tests, on any processor and in AVX |
//! | [`paths`] | a row's pixels four paths at a time, their hits, shading and shadow rays |
//! | [`hierarchy`] | the hierarchy of eight-box nodes and eight-triangle groups |

pub mod hierarchy;
pub mod paths;
pub mod simd;

pub use hierarchy::fast_bvh::FastBvh;
