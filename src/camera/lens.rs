//! The thin lens: depth of field from an aperture of finite size.

use crate::maths::{PI, PixelRng, Real, Vec3, uniform_pair};

// ANCHOR: disk
/// A point of the unit disk, uniformly distributed, from two uniform numbers in
/// `[0, 1)`: Shirley and Chiu's concentric map, which sends squares around the
/// centre of `[-1, 1]^2` to circles and so keeps neighbouring samples neighbours.
///
/// Exercise s4.3, a point of the lens: book session 4, "Depth of field".
pub fn sample_disk(u1: Real, u2: Real) -> (Real, Real) {
    let (a, b) = (2.0 * u1 - 1.0, 2.0 * u2 - 1.0);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, phi) = if a.abs() > b.abs() {
        (a, PI / 4.0 * (b / a))
    } else {
        (b, PI / 2.0 - PI / 4.0 * (a / b))
    };
    (r * phi.cos(), r * phi.sin())
}

/// Density of [`sample_disk`] per unit area: `1 / pi` inside the unit disk.
pub fn disk_pdf(x: Real, y: Real) -> Real {
    if x * x + y * y <= 1.0 { 1.0 / PI } else { 0.0 }
}
// ANCHOR_END: disk

// ANCHOR: lens
/// Where camera rays start.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Lens {
    /// All at the eye: everything is sharp.
    #[default]
    Pinhole,
    /// Anywhere on a lens: only the focus plane is sharp (depth of field).
    Thin(ThinLens),
}

impl Lens {
    /// The camera-space ray from `start` along `direction` as this lens makes it:
    /// unchanged through a pinhole, refocused through a thin lens.
    pub fn refocus(&self, start: Vec3, direction: Vec3, rng: &mut PixelRng) -> (Vec3, Vec3) {
        match self {
            Lens::Pinhole => (start, direction),
            Lens::Thin(lens) => lens.refocus(start, direction, rng),
        }
    }
}
// ANCHOR_END: lens

/// A thin lens of radius `aperture` focused at distance `focus` in front of the eye.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThinLens {
    /// Radius of the lens opening; 0 would be a pinhole.
    pub aperture: Real,
    /// Distance from the eye to the plane that is sharp.
    pub focus: Real,
}

impl ThinLens {
    // ANCHOR: thin_lens
    /// The camera-space ray through the lens for the pinhole ray from `start` (the
    /// eye) along `direction`: the pinhole ray meets the focus plane, at distance
    /// `focus` in front of the eye, at a point every ray through the lens passes
    /// through, so that plane is sharp; the ray starts at a random point of the
    /// aperture disk around the eye.
    ///
    /// Exercise s4.4, the thin lens: book session 4, "Depth of field".
    pub fn refocus(&self, start: Vec3, direction: Vec3, rng: &mut PixelRng) -> (Vec3, Vec3) {
        let focus_point = start + direction * (self.focus / -direction.z);
        let (u1, u2) = uniform_pair(rng);
        let (x, y) = sample_disk(u1, u2);
        let origin = start + Vec3::new(x, y, 0.0) * self.aperture;
        (origin, focus_point - origin)
    }
    // ANCHOR_END: thin_lens
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maths::pixel_rng;

    #[test]
    fn disk_samples_stay_in_the_disk() {
        for (u1, u2) in [(0.0, 0.0), (0.999, 0.5), (0.5, 0.5), (0.25, 0.999)] {
            let (x, y) = sample_disk(u1, u2);
            assert!(x * x + y * y <= 1.0 + 1e-15);
        }
    }

    #[test]
    fn every_lens_ray_passes_through_the_focus_point() {
        let lens = ThinLens {
            aperture: 2.0,
            focus: 55.0,
        };
        let direction = Vec3::new(3.0, -2.0, -10.0);
        let target = direction * 5.5;
        let mut rng = pixel_rng(3, 4);
        for _ in 0..100 {
            let (origin, through) = lens.refocus(Vec3::ZERO, direction, &mut rng);
            assert!(origin.length() <= 2.0 && origin.z == 0.0);
            let t = (target.z - origin.z) / through.z;
            assert!((origin + t * through - target).length() < 1e-12);
        }
    }
}
