//! Beyond the course: the fast engine. It renders the same bytes as the course's
//! functions, faster, and is switched on as a whole with `--fast` (`[render] fast =
//! true`); without it, every stage runs the course's code.
//!
//! | file | session | what it holds | in place of |
//! |---|---|---|---|
//! | [`lanes`] | 3 | the four-ray sphere test, written once for any type of lanes | `Sphere::intersect` |
//! | [`portable`] | 3 | its lanes on any processor (the `wide` crate) | |
//! | `avx` | 3 | its lanes in AVX instructions, on x86-64 | |
//! | [`sphere_lanes`] | 3 | the nearest sphere of each of four rays | `Scene::nearest_sphere` |
//! | [`shading`] | 3 | four hits' records, direct light and bounces, written once for any lanes | `hit_at`, `direct_light`, `light_sample`, `cosine_direction`, `Hit::spawn` |
//! | [`four_lanes`] | 3 | the choice of AVX or portable lanes for the sphere test (`lanes`) and the shading (`shading`) | |
//! | [`paths_at_once`] | 3 | a row's pixels four paths at a time | `pixel` and `radiance` |
//! | [`path`] | 3 | one pixel's samples, one hit per step, summed as the recursion returns | `radiance` |
//! | [`hits_at_once`] | 3 | the work at those four paths' hits, on the lanes | `diffuse` |
//! | [`light_samples_at_once`] | 4 | their samples of a sphere light, on the lanes | `light_sample` |
//! | [`direct_at_once`] | 3 | the direct light of four paths, their shadow rays traced together | `direct_light` |
//! | [`meshes_at_once`] | 5 | the meshes those paths meet, searched after their spheres | `Scene::intersect` |
//! | [`sah`] | 6 | splits chosen by the surface area heuristic | `Bvh::build` |
//! | [`wide_node`] | 6 | eight boxes tested at once, on any processor | `Aabb::entry` |
//! | [`float_lanes`] | 6 | `f32` lanes as one type, for the triangle groups' test | |
//! | `avx_lanes` | 6 | the boxes' and triangles' tests in AVX instructions, on x86-64 | |
//! | [`traversal_stack`] | 6 | the children yet to visit, nearest on top | the course's stack |
//! | [`fast_bvh`] | 6 | the hierarchy of eight-box nodes and eight-triangle groups | `Bvh` |
//! | [`triangle_group`] | 6 | the single-precision pre-test of eight triangles | the ray-triangle test |

#[cfg(all(target_arch = "x86_64", not(feature = "f32")))]
pub mod avx;
pub mod direct_at_once;
pub mod four_lanes;
pub mod hits_at_once;
pub mod lanes;
pub mod path;
pub mod paths_at_once;
pub mod portable;
pub mod shading;
pub mod sphere_lanes;

#[cfg(target_arch = "x86_64")]
pub mod avx_lanes;
pub mod fast_bvh;
pub mod float_lanes;
pub mod light_samples_at_once;
pub mod meshes_at_once;
pub mod sah;
pub mod traversal_stack;
pub mod triangle_group;
pub mod wide_node;

pub use fast_bvh::FastBvh;
