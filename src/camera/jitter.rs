//! Camera rays from session 3 on: through random points of their pixel, so that the
//! mean of many samples smooths the edges (antialiasing).

use crate::camera::Camera;
use crate::geometry::Ray;
use crate::maths::{PixelRng, Vec3};

impl Camera {
    // ANCHOR: sample_ray
    /// A camera ray through pixel (`row`, `column`), aimed where the pixel filter
    /// says and, from session 4, starting where the lens says; drawing from `rng`
    /// when either is random.
    pub fn sample_ray(&self, row: u32, column: u32, rng: &mut PixelRng) -> Ray {
        let (dx, dy) = self.filter.offset(rng);
        let direction = self.pixel_direction(row, column) + Vec3::new(dx, dy, 0.0);
        let start = Vec3::ZERO;
        #[cfg(feature = "s4")]
        let (start, direction) = self.lens.refocus(start, direction, rng);
        self.place(start, direction)
    }
    // ANCHOR_END: sample_ray
}
