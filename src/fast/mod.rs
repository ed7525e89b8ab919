//! Beyond the course: the fast engine. It renders the same bytes as the course's
//! functions, faster, and is switched on as a whole with `--fast` (`[render] fast =
//! true`); without it, every stage runs the course's code.
//!
//! | folder | what it holds |
//! |---|---|
//! | [`lanes`] | the lanes the engine runs on, chosen once, and work written once for any of them |
//! | [`simd`] | the lanes: four numbers or eight side by side, on any processor and in AVX |
//! | [`paths`] | a row's pixels four paths at a time, their hits, shading and shadow rays |
//! | [`hierarchy`] | the hierarchy of eight-box nodes and eight-triangle groups |
//! | [`brute_force`] | session 5's searches, every triangle, four or eight at once |

pub mod brute_force;
pub mod hierarchy;
pub mod lanes;
pub mod paths;
pub mod simd;

pub use brute_force::fast_brute_force::FastBruteForce;
pub use hierarchy::fast_bvh::FastBvh;
