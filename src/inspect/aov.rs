//! Images of what the renderer sees (`--aov`): for the camera ray through each
//! pixel's centre, the normal, the distance, the albedo or the object it meets, or
//! what finding it cost, in false colour.

use rayon::prelude::*;

use crate::geometry::cost::{Cost, measure};
use crate::geometry::{Hit, Ray};
use crate::inspect::bounce::diffuse_albedo;
use crate::inspect::false_colour::{Legend, scale_colour};
use crate::maths::{Real, Vec3};
use crate::scene::Scene;

/// What an image of the renderer's view shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aov {
    /// The unit normal `N` at the hit, each coordinate from `[-1, 1]` shown as
    /// `255 (N + 1) / 2`: red for `+x`, green for `+y`, blue for `+z`.
    Normal,
    /// The distance `t` to the hit, on the colour scale.
    Depth,
    /// The surface's albedo as the display shows it; mirrors and glass, which keep
    /// all the light, in white.
    Albedo,
    /// One colour per object.
    Object,
    /// The spheres, boxes and triangles tested to find the hit, on the colour scale.
    Cost,
}

impl Aov {
    /// Every kind, in the order the command line lists them.
    pub const ALL: [Aov; 5] = [Aov::Normal, Aov::Depth, Aov::Albedo, Aov::Object, Aov::Cost];

    /// The name on the command line: `normal`, `depth`, `albedo`, `object`, `cost`.
    pub fn name(self) -> &'static str {
        match self {
            Aov::Normal => "normal",
            Aov::Depth => "depth",
            Aov::Albedo => "albedo",
            Aov::Object => "object",
            Aov::Cost => "cost",
        }
    }

    /// The kind called `name`, if any.
    pub fn from_name(name: &str) -> Option<Aov> {
        Aov::ALL.into_iter().find(|a| a.name() == name)
    }
}

/// An image of the renderer's view: 8-bit RGB, with a legend under it for the
/// kinds shown on a colour scale.
#[derive(Clone, Debug, PartialEq)]
pub struct AovImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels, the legend included.
    pub height: u32,
    /// The pixels, row-major from the top-left.
    pub rgb: Vec<u8>,
    /// The smallest and largest values shown on the colour scale (depth, cost).
    pub range: Option<(Real, Real)>,
    /// The mean value over the pixels (cost: tests per camera ray).
    pub mean: Option<Real>,
}

/// What the camera ray through one pixel's centre met, and what that cost.
struct Seen {
    hit: Option<Hit>,
    cost: Cost,
}

/// The image of `aov` for `scene`, at its size: camera rays through the pixels'
/// centres, traced with the course's [`Scene::intersect`].
pub fn see(scene: &Scene, aov: Aov) -> AovImage {
    let (width, height) = (scene.camera.width, scene.camera.height);
    let seen: Vec<Seen> = (0..width * height)
        .into_par_iter()
        .map(|i| look(scene, &scene.camera.ray(i / width, i % width)))
        .collect();
    match aov {
        Aov::Normal => flat(width, height, &seen, |hit| {
            ((hit.normal + Vec3::ONE) * 127.5).to_array()
        }),
        Aov::Albedo => flat(width, height, &seen, |hit| {
            albedo(hit, scene.settings.gamma)
        }),
        Aov::Object => flat(width, height, &seen, |hit| object_colour(hit.object)),
        Aov::Depth => {
            let values: Vec<Option<Real>> = seen.iter().map(|s| s.hit.map(|h| h.t)).collect();
            scaled(width, height, &values)
        }
        Aov::Cost => {
            let values: Vec<Option<Real>> =
                seen.iter().map(|s| Some(s.cost.tests() as Real)).collect();
            scaled(width, height, &values)
        }
    }
}

/// The nearest hit of `ray` and the tests it took.
fn look(scene: &Scene, ray: &Ray) -> Seen {
    let (hit, mut cost) = measure(|| scene.intersect(ray));
    cost.spheres = scene.spheres.len() as u64;
    Seen { hit, cost }
}

/// An image with `colour(hit)` where the ray met something, black elsewhere.
fn flat(width: u32, height: u32, seen: &[Seen], colour: impl Fn(&Hit) -> [Real; 3]) -> AovImage {
    let rgb = seen
        .iter()
        .flat_map(|s| s.hit.as_ref().map_or([0.0; 3], &colour))
        .map(|c| c.round().clamp(0.0, 255.0) as u8)
        .collect();
    AovImage {
        width,
        height,
        rgb,
        range: None,
        mean: None,
    }
}

/// The values on the colour scale from their smallest to their largest, black
/// where there is none, with the legend under the image.
fn scaled(width: u32, height: u32, values: &[Option<Real>]) -> AovImage {
    let present = values.iter().flatten().copied();
    let low = present.clone().fold(Real::INFINITY, Real::min);
    let high = present.clone().fold(Real::NEG_INFINITY, Real::max);
    let count = present.clone().count();
    let (low, high) = if count == 0 { (0.0, 0.0) } else { (low, high) };
    let span = (high - low).max(Real::MIN_POSITIVE);
    let mut rgb: Vec<u8> = values
        .iter()
        .flat_map(|v| v.map_or([0; 3], |v| scale_colour((v - low) / span)))
        .collect();
    let legend = Legend::new(width, low, high);
    rgb.extend(legend.rgb());
    AovImage {
        width,
        height: height + legend.height(),
        rgb,
        range: Some((low, high)),
        mean: (count > 0).then(|| present.sum::<Real>() / count as Real),
    }
}

/// The albedo of the surface hit as the display shows it, `255 albedo^(1/gamma)`:
/// white for mirrors and glass.
fn albedo(hit: &Hit, gamma: Real) -> [Real; 3] {
    match diffuse_albedo(&hit.material) {
        Some(albedo) => albedo.to_array().map(|a| 255.0 * a.powf(1.0 / gamma)),
        None => [255.0; 3],
    }
}

/// A colour for object number `object`, its hues spread by the golden ratio so
/// that neighbouring numbers differ.
fn object_colour(object: usize) -> [Real; 3] {
    let hue = (object as Real * 0.618_034).fract();
    let channel = |shift: Real| {
        let x = ((hue + shift).fract() * 6.0 - 3.0).abs() - 1.0;
        255.0 * (0.25 + 0.75 * x.clamp(0.0, 1.0))
    };
    [channel(0.0), channel(2.0 / 3.0), channel(1.0 / 3.0)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_has_its_name() {
        for aov in Aov::ALL {
            assert_eq!(Aov::from_name(aov.name()), Some(aov));
        }
        assert_eq!(Aov::from_name("normals"), None);
    }

    #[test]
    fn neighbouring_objects_get_different_colours() {
        for k in 0..20 {
            let (a, b) = (object_colour(k), object_colour(k + 1));
            let difference: Real = a.iter().zip(&b).map(|(x, y)| (x - y).abs()).sum();
            assert!(difference > 60.0, "objects {k} and {}: {a:?} {b:?}", k + 1);
        }
    }

    #[test]
    fn the_scale_spans_the_values_and_misses_are_black() {
        let image = scaled(3, 1, &[Some(2.0), None, Some(6.0)]);
        assert_eq!(image.range, Some((2.0, 6.0)));
        assert_eq!(image.mean, Some(4.0));
        assert_eq!(
            &image.rgb[..9],
            &[scale_colour(0.0), [0; 3], scale_colour(1.0)].concat()[..]
        );
        assert_eq!(image.rgb.len(), (3 * image.height * 3) as usize);
    }
}
