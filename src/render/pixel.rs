//! One pixel of sessions 1 and 2: the radiance of the ray through its centre.
//! Session 3 replaces it by the mean of many samples (`render/samples.rs`).

use crate::integrator::Tracer;
use crate::maths::Colour;

// ANCHOR: pixel
/// The radiance of pixel (`row`, `column`): that of the camera ray through its
/// centre, its one sample.
pub fn pixel(tracer: &mut Tracer, row: u32, column: u32) -> Colour {
    let scene = tracer.scene;
    tracer.samples += 1;
    let ray = scene.camera.ray(row, column);
    tracer.radiance(&ray, scene.settings.bounces)
}
// ANCHOR_END: pixel
