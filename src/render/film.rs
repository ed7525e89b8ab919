//! The film: linear radiance per pixel, turned into 8-bit colour only at output.

use crate::maths::{Colour, Real};

/// A `width` x `height` grid of linear radiance values, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Radiance of each pixel, row-major from the top-left corner.
    pub pixels: Vec<Colour>,
}

// ANCHOR: display
/// The 8-bit value of one linear radiance channel. As in the course, radiance is on
/// the display's scale: `min(255, L^(1/gamma))`, rounded, with 255 full white.
/// Negative and NaN values show as 0.
///
/// Exercise s2.1, gamma: book session 2, "Gamma correction".
pub fn display(radiance: Real, gamma: Real) -> u8 {
    let v = radiance.max(0.0).powf(1.0 / gamma).min(255.0);
    if v.is_nan() { 0 } else { v.round() as u8 }
}
// ANCHOR_END: display

impl Film {
    /// The film as 8-bit RGB bytes, row-major, each channel mapped by [`display`].
    pub fn to_rgb8(&self, gamma: Real) -> Vec<u8> {
        self.pixels
            .iter()
            .flat_map(|c| c.to_array().map(|v| display(v, gamma)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_mapping_values() {
        assert_eq!(display(0.0, 2.2), 0);
        assert_eq!(display(1.0, 2.2), 1);
        assert_eq!(display(255.0, 1.0), 255);
        assert_eq!(display(1e9, 2.2), 255);
        // 128^2.2 is the radiance that shows as 128 under gamma 2.2.
        let mid: Real = (128.0 as Real).powf(2.2);
        assert_eq!(display(mid, 2.2), 128);
        // Linear output of the same radiance saturates.
        assert_eq!(display(mid, 1.0), 255);
        // 100 under gamma 2.2: 100^(1/2.2) = 8.10..., rounds to 8.
        assert_eq!(display(100.0, 2.2), 8);
    }

    #[test]
    fn invalid_radiance_shows_black() {
        assert_eq!(display(-3.0, 2.2), 0);
        assert_eq!(display(Real::NAN, 2.2), 0);
    }
}
