//! White-furnace tests: inside an enclosure that glows uniformly, a surface that
//! loses no energy is invisible. Every pixel must see exactly the enclosure's
//! radiance, within the Monte Carlo noise. Then the bias of the bounce limit, and the
//! unbiasedness of Russian roulette, measured against a closed form.

use raycourse::Scene;
use raycourse::camera::Camera;
use raycourse::geometry::Sphere;
use raycourse::integrator::Tracer;
use raycourse::materials::Material;
use raycourse::maths::{Colour, Real, Vec3};
use raycourse::scene::Settings;

const SIZE: u32 = 24;

/// A camera inside an enclosure of radius 100 (albedo `rho`, emission `le`), looking
/// at `object` (if any) at the centre.
fn furnace(rho: Real, le: Real, object: Option<Material>, settings: Settings) -> Scene {
    let mut spheres = vec![Sphere {
        centre: Vec3::ZERO,
        radius: 100.0,
        material: Material::Diffuse {
            albedo: Colour::splat(rho),
        },
        emission: Colour::splat(le),
    }];
    if let Some(material) = object {
        spheres.push(Sphere {
            centre: Vec3::ZERO,
            radius: 10.0,
            material,
            emission: Colour::ZERO,
        });
    }
    let camera = Camera::new(
        Vec3::new(0.0, 0.0, 40.0),
        (40.0 as Real).to_radians(),
        SIZE,
        SIZE,
    );
    Scene::new(camera, spheres, None, settings)
}

/// Stop paths at the bounce limit.
const LIMIT: Option<Real> = None;

#[allow(
    clippy::needless_update,
    reason = "from session 3 `Settings` has more fields"
)]
fn settings(bounces: u32, russian_roulette: Option<Real>) -> Settings {
    Settings {
        samples: 64,
        bounces,
        seed: 11,
        gamma: 1.0,
        shadows: false,
        indirect: true,
        light_sampling: false,
        russian_roulette,
        ..Settings::default()
    }
}

/// The radiance of every sample of pixel (`row`, `column`), red channel (the
/// scenes are grey).
#[cfg(feature = "s3")]
fn pixel(tracer: &mut Tracer, row: u32, column: u32) -> Vec<Real> {
    raycourse::render::samples::pixel_samples(tracer, row, column)
        .map(|c| c.x)
        .collect()
}

/// The radiance of the one sample of pixel (`row`, `column`) before session 3, red
/// channel.
#[cfg(not(feature = "s3"))]
fn pixel(tracer: &mut Tracer, row: u32, column: u32) -> Vec<Real> {
    vec![raycourse::render::pixel::pixel(tracer, row, column).x]
}

/// Every sample's radiance, pixel by pixel.
fn samples(scene: &Scene) -> Vec<Vec<Real>> {
    let mut tracer = Tracer::new(scene);
    let mut pixels = Vec::new();
    for row in 0..SIZE {
        for column in 0..SIZE {
            pixels.push(pixel(&mut tracer, row, column));
        }
    }
    pixels
}

/// Mean and standard error of the mean (0 for a single value).
fn mean_and_error(values: &[Real]) -> (Real, Real) {
    let n = values.len() as Real;
    let mean = values.iter().sum::<Real>() / n;
    if values.len() < 2 {
        return (mean, 0.0);
    }
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<Real>() / (n - 1.0);
    (mean, (variance / n).sqrt())
}

/// Asserts that every pixel's mean is within 3 standard errors of `expected` (and
/// within rounding of it where the samples do not vary).
fn every_pixel_sees(scene: &Scene, expected: Real) {
    for (i, values) in samples(scene).iter().enumerate() {
        let (mean, error) = mean_and_error(values);
        assert!(
            (mean - expected).abs() <= 3.0 * error + 1e-12,
            "pixel {i}: {mean} +- {error}, expected {expected}"
        );
    }
}

#[cfg(feature = "s3")]
#[test]
fn a_white_diffuse_sphere_vanishes() {
    let white = Material::Diffuse {
        albedo: Colour::ONE,
    };
    every_pixel_sees(&furnace(0.0, 1.0, Some(white), settings(5, LIMIT)), 1.0);
}

#[test]
fn a_mirror_sphere_vanishes() {
    every_pixel_sees(
        &furnace(0.0, 1.0, Some(Material::Mirror), settings(5, LIMIT)),
        1.0,
    );
}

#[cfg(feature = "s4")]
#[test]
fn a_fresnel_glass_sphere_vanishes() {
    let glass = Material::FresnelGlass { index: 1.5 };
    every_pixel_sees(&furnace(0.0, 1.0, Some(glass), settings(64, LIMIT)), 1.0);
}

#[cfg(feature = "s3")]
#[test]
fn the_bounce_limit_biases_a_grey_enclosure_low() {
    // L = Le + rho L has the solution Le / (1 - rho) = 2 for rho = 1/2. Stopping
    // after 2 bounces keeps Le (1 + rho + rho^2) = 1.75, with no noise at all.
    let scene = furnace(0.5, 1.0, None, settings(2, LIMIT));
    for values in samples(&scene) {
        assert!(values.iter().all(|&v| v == 1.75), "{values:?}");
    }
}

#[cfg(feature = "beyond")]
#[test]
fn russian_roulette_removes_the_bias_with_every_sampler() {
    use raycourse::scene::beyond::{Beyond, Sampler};
    for sampler in [Sampler::Independent, Sampler::Stratified, Sampler::Sobol] {
        let scene = furnace(0.5, 1.0, None, settings(2, Some(0.6)));
        let beyond = Beyond {
            sampler,
            ..Beyond::default()
        };
        let mut tracer = Tracer::new(&scene);
        let mut all: Vec<Real> = vec![];
        for (row, column) in (0..SIZE).flat_map(|r| (0..SIZE).map(move |c| (r, c))) {
            let samples =
                raycourse::samplers::pixel::pixel_samples(&mut tracer, &beyond, row, column);
            all.extend(samples.map(|c| c.x));
        }
        let (mean, error) = mean_and_error(&all);
        assert!(
            (mean - 2.0).abs() <= 3.0 * error,
            "{sampler:?}: {mean} +- {error}"
        );
        assert!(error < 0.01, "enough samples to tell 2 from 1.75: {error}");
        assert!(
            2.0 - 1.75 > 20.0 * error,
            "the bias is far beyond the noise"
        );
    }
}
