//! Paths followed several at a time: a row's pixels four paths at once, their hits,
//! their shading and their shadow rays on the lanes.
//!
//! | file | what it holds | in place of |
//! |---|---|---|
//! | [`paths_at_once`] | a row's pixels four paths at a time | `pixel` and `radiance` |
//! | [`path`] | one pixel's samples, one hit per step, summed as the recursion returns | `radiance` |
//! | [`hits_at_once`] | the work at those four paths' hits, on the lanes | `diffuse` |
//! | [`light_samples_at_once`] | their samples of a sphere light, written once for any lanes | `light_sample` |
//! | [`direct_at_once`] | the direct light of four paths, their shadow rays traced together | `direct_light` |
//! | [`meshes_at_once`] | the meshes those paths meet, searched after their spheres | `Scene::intersect` |
//! | [`shading`] | four hits' records, point light and bounces, written once for any lanes | `hit_at`, `direct_light`, `cosine_direction`, `Hit::spawn` |
//! | [`sphere_lanes`] | the nearest sphere of each of four rays, written once for any lanes | `Sphere::intersect`, `Scene::nearest_sphere` |

pub mod direct_at_once;
pub mod hits_at_once;
pub mod light_samples_at_once;
pub mod meshes_at_once;
pub mod path;
pub mod paths_at_once;
pub mod shading;
pub mod sphere_lanes;
