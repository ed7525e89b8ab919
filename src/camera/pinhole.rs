//! The pinhole camera of the course: one ray from the eye through each pixel.

use crate::geometry::Ray;
use crate::maths::{Real, Vec3};

#[cfg(feature = "s4")]
use crate::camera::Lens;
#[cfg(feature = "s7")]
use crate::camera::Orientation;
#[cfg(feature = "s3")]
use crate::camera::PixelFilter;

// ANCHOR: camera
/// A camera at `position`, looking down `-z` with `y` up, and the image it makes.
/// Later sessions add fields (how rays are spread over a pixel, a lens, an aim);
/// they start at their default, a pinhole looking down `-z`, so the struct is built
/// with `..Default::default()`, and `non_exhaustive` tells other crates so.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct Camera {
    /// The eye: where every camera ray starts.
    pub position: Vec3,
    /// The vertical field of view `alpha`, in radians (the scene file gives it in
    /// degrees).
    pub fov: Real,
    /// Image width `W` in pixels.
    pub width: u32,
    /// Image height `H` in pixels.
    pub height: u32,
    /// Where in its pixel a ray aims (session 3).
    #[cfg(feature = "s3")]
    pub filter: PixelFilter,
    /// Where rays start: the eye, or anywhere on a lens (session 4).
    #[cfg(feature = "s4")]
    pub lens: Lens,
    /// Which way the camera looks (session 7).
    #[cfg(feature = "s7")]
    pub orientation: Orientation,
}
// ANCHOR_END: camera

impl Camera {
    /// A pinhole camera at `position` looking down `-z`, with vertical field of view
    /// `fov` radians, making a `width` x `height` image.
    pub fn new(position: Vec3, fov: Real, width: u32, height: u32) -> Camera {
        Camera {
            position,
            fov,
            width,
            height,
            ..Default::default()
        }
    }

    // ANCHOR: pixel_direction
    /// The (unnormalised) direction through the centre of pixel (`row`, `column`),
    /// rows counted from the top of the image. With `i = H - 1 - row` the row counted
    /// from the bottom, as in the course:
    /// `(j - W/2 + 0.5, i - H/2 + 0.5, -H / (2 tan(alpha/2)))`.
    /// The image plane sits at the distance where `H` pixels span the field of view.
    ///
    /// Exercise s1.1, the camera ray through a pixel: book session 1, "A white disk".
    pub fn pixel_direction(&self, row: u32, column: u32) -> Vec3 {
        let (w, h) = (self.width as Real, self.height as Real);
        let i = (self.height - 1 - row) as Real;
        let j = column as Real;
        Vec3::new(
            j - w / 2.0 + 0.5,
            i - h / 2.0 + 0.5,
            -h / (2.0 * (self.fov / 2.0).tan()),
        )
    }
    // ANCHOR_END: pixel_direction

    // ANCHOR: ray
    /// The camera ray through the centre of pixel (`row`, `column`).
    pub fn ray(&self, row: u32, column: u32) -> Ray {
        self.place(Vec3::ZERO, self.pixel_direction(row, column))
    }

    /// The world ray that starts at `start` and goes along `direction`, both given
    /// in camera space (the eye at the origin, looking down `-z`).
    pub fn place(&self, start: Vec3, direction: Vec3) -> Ray {
        #[cfg(feature = "s7")]
        let (start, direction) = (
            self.orientation.to_world(start),
            self.orientation.to_world(direction),
        );
        Ray::new(self.position + start, direction)
    }
    // ANCHOR_END: ray
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera::new(
            Vec3::new(0.0, 0.0, 55.0),
            (60.0 as Real).to_radians(),
            512,
            256,
        )
    }

    #[test]
    fn centre_pixels_straddle_the_axis() {
        let c = camera();
        let d = c.pixel_direction(127, 255);
        assert_eq!((d.x, d.y), (-0.5, 0.5));
        let d = c.pixel_direction(128, 256);
        assert_eq!((d.x, d.y), (0.5, -0.5));
    }

    #[test]
    fn top_and_bottom_rows_span_the_field_of_view() {
        let c = camera();
        let top = c.pixel_direction(0, 256).normalize();
        let bottom = c.pixel_direction(255, 256).normalize();
        let angle = top.angle_between(bottom);
        let one_pixel = c.fov / c.height as Real;
        assert!((angle - c.fov).abs() < one_pixel, "{angle} vs {}", c.fov);
        assert!(
            top.y > 0.0 && bottom.y < 0.0,
            "rows are counted from the top"
        );
    }
}
