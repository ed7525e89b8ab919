//! The false-colour scale of the images of depth and cost, and their legend: a bar
//! of the scale with its smallest and largest values written under it.

use crate::maths::Real;

/// Viridis at five evenly spaced points, from dark purple to yellow: a scale whose
/// brightness grows steadily, readable in grey and by most colour-blind readers.
const STOPS: [[Real; 3]; 5] = [
    [68.0, 1.0, 84.0],
    [59.0, 82.0, 139.0],
    [33.0, 145.0, 140.0],
    [94.0, 201.0, 98.0],
    [253.0, 231.0, 37.0],
];

/// The colour of `x` in `[0, 1]` (clamped): linear between the stops.
pub fn scale_colour(x: Real) -> [u8; 3] {
    let at = x.clamp(0.0, 1.0) * (STOPS.len() - 1) as Real;
    let below = (at.floor() as usize).min(STOPS.len() - 2);
    let f = at - below as Real;
    let (a, b) = (STOPS[below], STOPS[below + 1]);
    [0, 1, 2].map(|k| (a[k] + f * (b[k] - a[k])).round() as u8)
}

/// The legend under an image `width` pixels wide: the scale from `low` to `high`.
pub struct Legend {
    width: u32,
    low: Real,
    high: Real,
}

/// Rows of the legend: a gap, the bar, a gap and a line of digits.
const GAP: u32 = 2;
const BAR: u32 = 6;
const DIGITS: u32 = 5;

impl Legend {
    /// The legend of values from `low` to `high` for an image `width` wide.
    pub fn new(width: u32, low: Real, high: Real) -> Legend {
        Legend { width, low, high }
    }

    /// Its height in pixels.
    pub fn height(&self) -> u32 {
        GAP + BAR + 1 + DIGITS + 1
    }

    /// Its pixels, 8-bit RGB, row-major: the bar, then `low` at the left and `high`
    /// at the right in white digits, when both fit.
    pub fn rgb(&self) -> Vec<u8> {
        let w = self.width as usize;
        let mut rgb = vec![0u8; w * self.height() as usize * 3];
        for row in GAP..GAP + BAR {
            for x in 0..w {
                let colour = scale_colour(x as Real / (w.max(2) - 1) as Real);
                let at = (row as usize * w + x) * 3;
                rgb[at..at + 3].copy_from_slice(&colour);
            }
        }
        let (low, high) = (label(self.low), label(self.high));
        let needed = (low.len() + high.len() + 2) * 4;
        if needed <= w {
            let top = (GAP + BAR + 1) as usize;
            write_text(&mut rgb, w, top, 1, &low);
            write_text(&mut rgb, w, top, w - high.len() * 4, &high);
        }
        rgb
    }
}

/// A value as the legend writes it: three significant digits at most, no exponent.
pub fn label(value: Real) -> String {
    match value.abs() {
        v if v >= 100.0 || value.fract() == 0.0 => format!("{value:.0}"),
        v if v >= 10.0 => format!("{value:.1}"),
        _ => format!("{value:.2}"),
    }
}

/// Writes `text` in white 3x5 digits into `rgb` (`width` pixels wide) with its top
/// left corner at (`left`, `top`).
fn write_text(rgb: &mut [u8], width: usize, top: usize, left: usize, text: &str) {
    for (k, c) in text.chars().enumerate() {
        for (row, bits) in glyph(c).iter().enumerate() {
            for column in 0..3 {
                if bits & (0b100 >> column) != 0 {
                    let at = ((top + row) * width + left + 4 * k + column) * 3;
                    rgb[at..at + 3].copy_from_slice(&[255; 3]);
                }
            }
        }
    }
}

/// The five rows of a character of the legend, three bits each, leftmost first.
fn glyph(c: char) -> [u8; 5] {
    match c {
        '0' => [0b111, 0b101, 0b101, 0b101, 0b111],
        '1' => [0b010, 0b110, 0b010, 0b010, 0b111],
        '2' => [0b111, 0b001, 0b111, 0b100, 0b111],
        '3' => [0b111, 0b001, 0b111, 0b001, 0b111],
        '4' => [0b101, 0b101, 0b111, 0b001, 0b001],
        '5' => [0b111, 0b100, 0b111, 0b001, 0b111],
        '6' => [0b111, 0b100, 0b111, 0b101, 0b111],
        '7' => [0b111, 0b001, 0b001, 0b001, 0b001],
        '8' => [0b111, 0b101, 0b111, 0b101, 0b111],
        '9' => [0b111, 0b101, 0b111, 0b001, 0b111],
        '.' => [0, 0, 0, 0, 0b010],
        '-' => [0, 0, 0b111, 0, 0],
        _ => [0; 5],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_runs_from_its_first_stop_to_its_last_and_brightens() {
        assert_eq!(scale_colour(0.0), [68, 1, 84]);
        assert_eq!(scale_colour(1.0), [253, 231, 37]);
        assert_eq!(scale_colour(-1.0), scale_colour(0.0));
        let brightness = |x: Real| scale_colour(x).iter().map(|&c| u32::from(c)).sum::<u32>();
        for k in 0..20 {
            let x = k as Real / 20.0;
            assert!(brightness(x + 0.05) > brightness(x), "at {x}");
        }
    }

    #[test]
    fn labels_are_short() {
        assert_eq!(label(41.25), "41.2");
        assert_eq!(label(3.0), "3");
        assert_eq!(label(1234.7), "1235");
        assert_eq!(label(0.123), "0.12");
    }

    #[test]
    fn the_legend_writes_both_ends_when_they_fit() {
        let white = |rgb: &[u8]| rgb.chunks(3).filter(|p| p == &[255, 255, 255]).count();
        let wide = Legend::new(64, 3.0, 120.0);
        // "3" has 11 lit dots of 15, "120" has 8 + 11 + 12.
        assert_eq!(white(&wide.rgb()), 11 + 8 + 11 + 12);
        assert_eq!(
            white(&Legend::new(8, 3.0, 120.0).rgb()),
            0,
            "too narrow: no digits"
        );
    }
}
