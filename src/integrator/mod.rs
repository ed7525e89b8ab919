//! The integrator: the radiance arriving at the eye along a ray, the course's
//! recursive `radiance` (`obtenirCouleur`), and each material's and light's part of
//! it. Every function here is a method of [`Tracer`], which holds the scene, the
//! pixel's random numbers and the count of rays traced.
//!
//! | file | session | what it holds |
//! |---|---|---|
//! | [`tracer`] | 1 | the tracer and its one way of tracing a ray |
//! | [`radiance`] | 1 | `radiance`: emitted plus reflected light, by material |
//! | `diffuse_direct` | 1, 2 | a diffuse surface's light: the light source's |
//! | [`direct`] | 1 | light from the light source: Lambert's law under a point light |
//! | [`shadows`] | 2 | shadow rays |
//! | [`bounce`] | 2 | one more bounce, weighted, while the path goes on |
//! | `bounce_limit` | 2, 3 | whether the path goes on: while bounces are left |
//! | [`specular`] | 2 | mirrors and glass |
//! | [`diffuse`] | 3 | a diffuse surface's direct and indirect light; cosine-weighted directions |
//! | `indirect` | 3 | indirect light by Monte Carlo: one bounce in a random direction |
//! | [`light_sampling`] | 4 | direct light from a sphere light, sampled; indirect light without it |
//! | [`roulette`] | 4 | whether the path goes on: Russian roulette past the bounce limit |
//! | [`fresnel_glass`] | 4 | glass that reflects part of the light |

pub mod direct;
pub mod radiance;
pub mod tracer;

#[cfg(not(feature = "s3"))]
pub mod diffuse_direct;

#[cfg(feature = "s2")]
pub mod bounce;
#[cfg(all(feature = "s2", not(feature = "s4")))]
pub mod bounce_limit;
#[cfg(feature = "s2")]
pub mod shadows;
#[cfg(feature = "s2")]
pub mod specular;

#[cfg(feature = "s3")]
pub mod diffuse;
#[cfg(all(feature = "s3", not(feature = "s4")))]
pub mod indirect;

#[cfg(feature = "s4")]
pub mod fresnel_glass;
#[cfg(feature = "s4")]
pub mod light_sampling;
#[cfg(feature = "s4")]
pub mod roulette;

pub use tracer::Tracer;
