//! The pinhole camera of the course: one ray from the eye through each pixel.

use crate::geometry::ray::Ray;
use crate::maths::numbers::{Real, Vec3};
use crate::maths::random::PixelRng;

/// Where in its pixel a camera ray aims.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PixelFilter {
    /// At the centre: one ray per pixel is enough, and edges are jagged.
    Centre,
    /// At a point scattered around the centre with a Gaussian of standard deviation
    /// `sigma` pixels: averaging many samples smooths the edges (antialiasing).
    #[cfg(feature = "s3")]
    Gaussian {
        /// Standard deviation, in pixels.
        sigma: Real,
    },
}

/// Where camera rays start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lens {
    /// All at the eye: everything is sharp.
    Pinhole,
    /// Anywhere on a lens: only the focus plane is sharp (depth of field).
    #[cfg(feature = "s4")]
    Thin(crate::camera::lens::ThinLens),
}

/// Which way the camera looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Orientation {
    /// Down `-z`, with `y` up: the camera of the first six sessions.
    Fixed,
    /// Along any direction: camera-space `x`, `y`, `z` become `right`, `up` and
    /// `back` (minus the viewing direction).
    #[cfg(feature = "s7")]
    Aimed {
        /// Unit vector to the right of the image.
        right: Vec3,
        /// Unit vector to the top of the image.
        up: Vec3,
        /// Unit vector from the scene towards the eye.
        back: Vec3,
    },
}

impl Orientation {
    /// The world vector of camera-space `v`.
    pub fn to_world(&self, v: Vec3) -> Vec3 {
        match *self {
            Orientation::Fixed => v,
            #[cfg(feature = "s7")]
            Orientation::Aimed { right, up, back } => v.x * right + v.y * up + v.z * back,
        }
    }
}

/// A camera at `position`, looking down `-z` with `y` up unless aimed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The eye: where every camera ray starts.
    pub position: Vec3,
    /// The vertical field of view, in radians.
    pub fov: Real,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Where in its pixel a ray aims.
    pub filter: PixelFilter,
    /// Where rays start.
    pub lens: Lens,
    /// Which way it looks.
    pub orientation: Orientation,
}

impl Camera {
    // ANCHOR: pixel_direction
    /// The (unnormalised) direction through the centre of pixel (`row`, `column`),
    /// rows counted from the top of the image. With `i = H - 1 - row` the row counted
    /// from the bottom, as in the course:
    /// `(j - W/2 + 0.5, i - H/2 + 0.5, -H / (2 tan(fov/2)))`.
    /// The image plane sits at the distance where `H` pixels span the field of view.
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

    // ANCHOR: camera_ray
    /// A camera ray through pixel (`row`, `column`): aimed where the pixel filter says,
    /// starting where the lens says, drawing from `rng` when either is random.
    pub fn ray(
        &self,
        row: u32,
        column: u32,
        #[cfg_attr(not(feature = "s3"), expect(unused_variables))] rng: &mut PixelRng,
    ) -> Ray {
        let (dx, dy) = match self.filter {
            PixelFilter::Centre => (0.0, 0.0),
            #[cfg(feature = "s3")]
            PixelFilter::Gaussian { sigma } => {
                let (u1, u2) = (
                    crate::maths::random::uniform(rng),
                    crate::maths::random::uniform(rng),
                );
                crate::maths::sampling::sample_gaussian(u1, u2, sigma)
            }
        };
        let direction = self.pixel_direction(row, column) + Vec3::new(dx, dy, 0.0);
        let (start, direction) = match self.lens {
            Lens::Pinhole => (Vec3::ZERO, direction),
            #[cfg(feature = "s4")]
            Lens::Thin(lens) => lens.ray(direction, rng),
        };
        let o = &self.orientation;
        Ray::new(self.position + o.to_world(start), o.to_world(direction))
    }
    // ANCHOR_END: camera_ray
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera {
            position: Vec3::new(0.0, 0.0, 55.0),
            fov: (60.0 as Real).to_radians(),
            width: 512,
            height: 256,
            filter: PixelFilter::Centre,
            lens: Lens::Pinhole,
            orientation: Orientation::Fixed,
        }
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
