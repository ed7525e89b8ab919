//! One pixel with a sampler beyond the course: its samples' random numbers spread
//! evenly (stratified or Sobol), and with adaptive sampling as many samples as the
//! pixel needs. With the course's settings it takes the same samples as the course's
//! pixel ([`pixel`](crate::render::samples::pixel)).

use crate::geometry::Ray;
use crate::integrator::Tracer;
use crate::maths::{Colour, PixelRng, pixel_rng};
use crate::samplers::adaptive::{Estimate, MOST_SAMPLES, batch, precise_enough};
use crate::samplers::spread::Spread;
use crate::scene::Scene;
use crate::scene::beyond::{Beyond, Sampler};

/// The random numbers of pixel number `pixel` for the scene seed `seed`, chosen by
/// `sampler` and spread evenly over each `block` of consecutive samples: the course's
/// [`pixel_rng`] for independent numbers.
pub fn sampler_rng(sampler: Sampler, seed: u64, pixel: u64, block: u32) -> PixelRng {
    match sampler {
        Sampler::Independent => pixel_rng(seed, pixel),
        _ => PixelRng::Given(Box::new(Spread::new(sampler, seed, pixel, block))),
    }
}

/// Starts sample number `sample` of the pixel whose numbers `rng` draws: a spread
/// sampler's points depend on it, independent numbers do not.
pub fn start_sample(rng: &mut PixelRng, sample: u32) {
    if let PixelRng::Given(numbers) = rng {
        numbers.start_sample(sample);
    }
}

/// Gives `tracer` the random numbers of pixel (`row`, `column`), chosen as `beyond`
/// says and from the scene's seed and the pixel's index alone, and returns how many
/// samples the pixel may take: the scene's count, or with adaptive sampling up to
/// [`MOST_SAMPLES`] times as many.
pub fn start_pixel(tracer: &mut Tracer, beyond: &Beyond, row: u32, column: u32) -> u32 {
    let scene = tracer.scene;
    let settings = scene.settings;
    let index = u64::from(row) * u64::from(scene.camera.width) + u64::from(column);
    let (count, block) = match beyond.noise {
        None => (settings.samples, settings.samples),
        Some(_) => (settings.samples * MOST_SAMPLES, batch(settings.samples)),
    };
    tracer.rng = sampler_rng(beyond.sampler, settings.seed, index, block);
    count
}

/// The camera ray of sample `i` of pixel (`row`, `column`), counted in
/// [`Tracer::samples`]; the sample's random numbers start here.
pub fn camera_sample(tracer: &mut Tracer, row: u32, column: u32, i: u32) -> Ray {
    start_sample(&mut tracer.rng, i);
    tracer.samples += 1;
    tracer.scene.camera.sample_ray(row, column, &mut tracer.rng)
}

/// The radiance of each of the samples that pixel (`row`, `column`) may take with
/// the settings `beyond`, in order (with adaptive sampling, up to [`MOST_SAMPLES`]
/// times the scene's count: the caller stops).
pub fn pixel_samples<'t, 's>(
    tracer: &'t mut Tracer<'s>,
    beyond: &Beyond,
    row: u32,
    column: u32,
) -> impl Iterator<Item = Colour> + use<'t, 's> {
    let count = start_pixel(tracer, beyond, row, column);
    (0..count).map(move |i| {
        let ray = camera_sample(tracer, row, column, i);
        tracer.radiance(&ray, tracer.scene.settings.bounces)
    })
}

/// The radiance of pixel (`row`, `column`) with the settings `beyond`: the mean of
/// its samples, those that were not finite left out and counted in
/// [`Tracer::dropped`]. With adaptive sampling the pixel stops after the first batch
/// whose mean is precise enough.
pub fn pixel(tracer: &mut Tracer, beyond: &Beyond, row: u32, column: u32) -> Colour {
    let samples = tracer.scene.settings.samples;
    let mut estimate = Estimate::default();
    for (i, sample) in pixel_samples(tracer, beyond, row, column).enumerate() {
        estimate.add(sample);
        if precise_enough(beyond.noise, samples, &estimate, i as u32 + 1) {
            break;
        }
    }
    tracer.dropped += u64::from(estimate.mean.dropped);
    estimate.mean.mean()
}

/// Renders row `row` of `scene` with the settings `beyond` into `line` (each pixel's
/// radiance) and `taken` (the samples each took) with [`pixel`]; returns the rays
/// traced and the samples dropped.
pub fn row(
    scene: &Scene,
    beyond: &Beyond,
    row: u32,
    line: &mut [Colour],
    taken: &mut [u32],
) -> (u64, u64) {
    let mut tracer = Tracer::new(scene);
    for (column, (value, taken)) in line.iter_mut().zip(taken).enumerate() {
        let before = tracer.samples;
        *value = pixel(&mut tracer, beyond, row, column as u32);
        *taken = (tracer.samples - before) as u32;
    }
    (tracer.rays, tracer.dropped)
}
