//! Image textures: the albedo of a mesh read from a picture at the hit's texture
//! coordinates.

use crate::maths::{Colour, Real};

/// How a texture is read between texel centres.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    /// The texel the point falls in, as in the course.
    Nearest,
    /// The four nearest texels, weighted by distance: no visible texel squares.
    Bilinear,
}

/// A picture in linear colour, ready to be sampled.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// Linear albedo of each texel, rows from the top.
    pub texels: Vec<Colour>,
    /// How it is read.
    pub filter: Filter,
}

// ANCHOR: to_linear
/// The linear value of an 8-bit texel channel. Pictures store
/// gamma-encoded values `c` (the display shows `c^2.2`), while shading needs the
/// reflectance itself: `(c / 255)^2.2`.
pub fn to_linear(c: u8) -> Real {
    (Real::from(c) / 255.0).powf(2.2)
}
// ANCHOR_END: to_linear

impl Texture {
    /// The picture held in `bytes` (a PNG or JPEG file's).
    pub fn decode(bytes: &[u8], filter: Filter) -> Result<Texture, String> {
        let picture = image::load_from_memory(bytes)
            .map_err(|e| e.to_string())?
            .to_rgb8();
        Ok(Texture {
            width: picture.width(),
            height: picture.height(),
            texels: picture
                .pixels()
                .map(|p| Colour::new(to_linear(p[0]), to_linear(p[1]), to_linear(p[2])))
                .collect(),
            filter,
        })
    }

    // ANCHOR: texel
    /// The texel at integer coordinates, wrapped around both ways so that the
    /// texture repeats: `-1` is the last column, `width` the first.
    pub fn texel(&self, x: i64, y: i64) -> Colour {
        let x = x.rem_euclid(i64::from(self.width)) as usize;
        let y = y.rem_euclid(i64::from(self.height)) as usize;
        self.texels[y * self.width as usize + x]
    }
    // ANCHOR_END: texel

    // ANCHOR: lookup
    /// The albedo at texture coordinates `(u, v)`: `u` runs left to right, `v`
    /// bottom to top, and the texture repeats outside `[0, 1]`. The point falls at
    /// `x = u W`, `y = (1 - v) H` in texels. A NaN coordinate reads texel 0.
    ///
    /// Exercise s7.1, the texture lookup: book session 7, "Textures".
    pub fn colour(&self, [u, v]: [Real; 2]) -> Colour {
        let x = u * self.width as Real;
        let y = (1.0 - v) * self.height as Real;
        match self.filter {
            Filter::Nearest => self.texel(x.floor() as i64, y.floor() as i64),
            Filter::Bilinear => {
                let (x, y) = (x - 0.5, y - 0.5);
                let (x0, y0) = (x.floor(), y.floor());
                let (fx, fy) = (x - x0, y - y0);
                let (x0, y0) = (x0 as i64, y0 as i64);
                let top = self.texel(x0, y0) * (1.0 - fx) + self.texel(x0 + 1, y0) * fx;
                let bottom = self.texel(x0, y0 + 1) * (1.0 - fx) + self.texel(x0 + 1, y0 + 1) * fx;
                top * (1.0 - fy) + bottom * fy
            }
        }
    }
    // ANCHOR_END: lookup
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 x 2 texture: black, red on the top row; green, blue below.
    fn checker(filter: Filter) -> Texture {
        Texture {
            width: 2,
            height: 2,
            texels: vec![Colour::ZERO, Colour::X, Colour::Y, Colour::Z],
            filter,
        }
    }

    #[test]
    fn nearest_lookup_wraps_both_ways() {
        let t = checker(Filter::Nearest);
        assert_eq!(t.colour([0.25, 0.75]), Colour::ZERO);
        assert_eq!(t.colour([0.75, 0.75]), Colour::X);
        assert_eq!(t.colour([0.25, 0.25]), Colour::Y);
        assert_eq!(t.colour([1.25, 0.75]), Colour::ZERO, "u past 1 wraps");
        assert_eq!(t.colour([-0.25, 0.75]), Colour::X, "negative u wraps");
        assert_eq!(t.colour([0.25, -0.25]), Colour::ZERO, "negative v wraps");
        assert_eq!(
            t.colour([7.75, -2.25]),
            Colour::X,
            "far outside: (0.75, 0.75)"
        );
        assert!(t.colour([Real::MAX, -Real::MAX]).is_finite());
        assert!(t.colour([Real::INFINITY, 0.5]).is_finite());
        assert!(t.colour([Real::NAN, 0.5]).is_finite());
    }

    #[test]
    fn bilinear_lookup_blends_neighbours() {
        let t = checker(Filter::Bilinear);
        // At a texel centre, the texel itself.
        assert_eq!(t.colour([0.25, 0.75]), Colour::ZERO);
        // Half-way between the two top texels.
        assert_eq!(t.colour([0.5, 0.75]), Colour::X * 0.5);
        // The centre of the texture averages all four.
        assert_eq!(t.colour([0.5, 0.5]), Colour::new(0.25, 0.25, 0.25));
        // Wrapping: between the last and the first column.
        assert_eq!(t.colour([0.0, 0.75]), Colour::X * 0.5);
    }

    #[test]
    fn texture_values_become_linear() {
        assert_eq!(to_linear(0), 0.0);
        assert_eq!(to_linear(255), 1.0);
        assert!((to_linear(128) - 0.2195).abs() < 1e-4);
    }
}
