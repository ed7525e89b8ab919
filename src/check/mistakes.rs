//! The classic mistakes of a student's ray tracer, each as the image it would make
//! of the stage, so that the checker can tell which one explains a difference.

use image::RgbImage;

use crate::check::compare::{Linear, compare_blocks, compare_pixels, displayed};
use crate::check::expected::{Expected, Source};
use crate::lights::Light;
use crate::materials::Material;
use crate::maths::{PI, Real};
use crate::meshes::MeshAlbedo;
use crate::messages::language::Language;
use crate::messages::say;
use crate::render::Film;
use crate::scene_file::SceneError;

/// A classic mistake: what it is called and what to look for.
#[derive(Debug)]
pub struct Mistake {
    /// Its id in the catalogue (`messages/`), whose message `mistake-<id>` is its
    /// short name, for tables, and whose attribute `.hint` says what to check in
    /// one's own code.
    pub id: &'static str,
    /// The image the mistake makes of the stage, as a film read like the student's
    /// (`None` when the mistake cannot happen in this stage).
    image: fn(&Candidates) -> Result<Option<Film>, SceneError>,
}

/// Where a pixel `(x, y)` of an image of `width` x `height` takes its colour from,
/// in an image moved or turned: `(x, y, width, height)` to the source pixel.
type Move = fn(usize, usize, usize, usize) -> (usize, usize);

/// What the mistakes' images are made from.
pub struct Candidates<'a> {
    /// Where renders come from.
    pub source: &'a Source<'a>,
    /// The stage's reference.
    pub expected: &'a Expected,
    /// The reference film (the mean of the halves).
    pub film: Film,
    /// The student's image, which some mistakes' images are fitted to.
    pub student: &'a RgbImage,
}

/// Every mistake the checker recognises.
pub const MISTAKES: &[Mistake] = &[
    Mistake {
        id: "no-gamma",
        image: |c| {
            Ok(c.gamma_applies()
                .then(|| c.map(|l, g| l.min(255.0).powf(g))))
        },
    },
    Mistake {
        id: "gamma-twice",
        image: |c| Ok(c.gamma_applies().then(|| c.map(|l, g| l.powf(1.0 / g)))),
    },
    Mistake {
        id: "one-over-pi-missing",
        image: |c| Ok(Some(c.map(|l, _| l * std::f64::consts::PI))),
    },
    Mistake {
        id: "one-over-pi-twice",
        image: |c| Ok(Some(c.map(|l, _| l / std::f64::consts::PI))),
    },
    Mistake {
        id: "no-falloff",
        image: no_falloff,
    },
    Mistake {
        id: "upside-down",
        image: |c| Ok(Some(c.flipped(true))),
    },
    Mistake {
        id: "mirrored",
        image: |c| Ok(Some(c.flipped(false))),
    },
    Mistake {
        id: "half-a-turn",
        image: |c| Ok(Some(c.moved(|x, y, w, h| (w - 1 - x, h - 1 - y)))),
    },
    Mistake {
        id: "rows-and-columns-swapped",
        image: |c| Ok((c.film.width == c.film.height).then(|| c.moved(|x, y, _, _| (y, x)))),
    },
    Mistake {
        id: "shifted-a-pixel",
        image: |c| Ok(Some(c.shifted())),
    },
    Mistake {
        id: "shadow-acne",
        image: acne,
    },
    Mistake {
        id: "inverted-index",
        image: inverted_index,
    },
    Mistake {
        id: "light-counted-twice",
        image: light_twice,
    },
    Mistake {
        id: "bounce-limit",
        image: one_bounce,
    },
    Mistake {
        id: "bounce-weight",
        image: bounce_weight,
    },
    Mistake {
        id: "texture-gamma",
        image: |c| {
            c.textured(|texel| image::Rgb(texel.0.map(|v| 255.0 * (v / 255.0).powf(1.0 / 2.2))))
        },
    },
    Mistake {
        id: "texture-v-flipped",
        image: |c| c.textured(|texture| texture),
    },
];

impl Mistake {
    /// The name and the hint in `language`.
    pub fn words(&self, language: Language) -> [String; 2] {
        let id = format!("mistake-{}", self.id);
        [
            say(language, &id, &[]),
            say(language, &format!("{id}.hint"), &[]),
        ]
    }
}

/// The mistake whose image the student's fits, if one does: it must differ in at
/// most half as many places as the stage's own image does (`differing`).
pub fn best_explanation(
    c: &Candidates,
    differing: f64,
) -> Result<Option<&'static Mistake>, SceneError> {
    let mut best: Option<(f64, &Mistake)> = None;
    for mistake in MISTAKES {
        let Some(film) = (mistake.image)(c)? else {
            continue;
        };
        let share = c.share_differing(c.student, &film);
        if share <= differing / 2.0 && best.is_none_or(|(b, _)| share < b) {
            best = Some((share, mistake));
        }
    }
    Ok(best.map(|(_, m)| m))
}

impl Candidates<'_> {
    /// The stage's display gamma.
    fn gamma(&self) -> f64 {
        crate::maths::to_double(self.expected.scene.settings.gamma)
    }

    /// Whether the stage corrects gamma, so that a mistake of gamma shows.
    fn gamma_applies(&self) -> bool {
        self.gamma() != 1.0
    }

    /// The reference film with each radiance `l` replaced by `f(l, gamma)`.
    fn map(&self, f: impl Fn(f64, f64) -> f64) -> Film {
        let g = self.gamma();
        let mut film = self.film.clone();
        for pixel in &mut film.pixels {
            *pixel = pixel.map(|v| f(crate::maths::to_double(v), g) as Real);
        }
        film
    }

    /// The reference film upside down (`vertically`) or mirrored.
    fn flipped(&self, vertically: bool) -> Film {
        match vertically {
            true => self.moved(|x, y, _, h| (x, h - 1 - y)),
            false => self.moved(|x, y, w, _| (w - 1 - x, y)),
        }
    }

    /// The reference film moved by one pixel, in whichever of the four directions
    /// the student's image is closest to.
    pub fn shifted(&self) -> Film {
        let moves: [Move; 4] = [
            |x, y, _, _| (x, y.saturating_sub(1)),
            |x, y, _, h| (x, (y + 1).min(h - 1)),
            |x, y, _, _| (x.saturating_sub(1), y),
            |x, y, w, _| ((x + 1).min(w - 1), y),
        ];
        let films = moves.map(|m| self.moved(m));
        let share = |film: &Film| self.share_differing(self.student, film);
        let best = (0..4).min_by(|&a, &b| share(&films[a]).total_cmp(&share(&films[b])));
        films[best.unwrap_or(0)].clone()
    }

    /// The reference film with each pixel `(x, y)` taken from the pixel
    /// `from(x, y, width, height)` of the reference.
    fn moved(&self, from: Move) -> Film {
        let (w, h) = (self.film.width as usize, self.film.height as usize);
        let mut film = self.film.clone();
        for (i, pixel) in film.pixels.iter_mut().enumerate() {
            let (sx, sy) = from(i % w, i / w, w, h);
            *pixel = self.film.pixels[sy * w + sx];
        }
        film
    }

    /// How much of the student's image differs from `film`, compared as the stage's
    /// own image is.
    pub fn share_differing(&self, student: &RgbImage, film: &Film) -> f64 {
        let gamma = self.expected.scene.settings.gamma;
        if self.expected.deterministic {
            compare_pixels(student, &displayed(film, gamma), 3).share()
        } else {
            let linear = Linear::from_rgb8(student, gamma);
            compare_blocks(&linear, &Linear::from_film(film, gamma), gamma).share()
        }
    }

    /// The samples of a Monte Carlo render made for a mistake: half the course's.
    fn samples(&self) -> u32 {
        (self.expected.scene.settings.samples / 2).max(1)
    }

    /// The stage rendered with its scene file's keys changed by `edit`. The file is
    /// read as TOML, edited and written out again, so its spacing and comments do
    /// not matter.
    fn variant(&self, edit: impl Fn(&mut toml::Table)) -> Result<Film, SceneError> {
        let mut file: toml::Table = self
            .source
            .stage
            .source
            .parse()
            .expect("a stage's scene file is TOML");
        edit(&mut file);
        let text = toml::to_string(&file).expect("a TOML table writes out");
        self.source.film(&text, self.samples(), Some(0x7e57))
    }

    /// For a textured stage, the stage rendered with its texture changed texel by
    /// texel by `change` (each channel's 8-bit value) and then flipped upside down if
    /// `change` is the identity, that is when the v coordinate is the mistake.
    fn textured(
        &self,
        change: impl Fn(image::Rgb<f64>) -> image::Rgb<f64>,
    ) -> Result<Option<Film>, SceneError> {
        let Some(texture) = self
            .expected
            .scene
            .meshes
            .iter()
            .find_map(|m| m.texture_file.clone())
        else {
            return Ok(None);
        };
        let textured = |m: &crate::meshes::Mesh| matches!(m.albedo, MeshAlbedo::Texture(_));
        if !self.expected.scene.meshes.iter().any(textured) {
            return Ok(None);
        }
        let Ok(picture) = image::open(&texture).map(|p| p.to_rgb8()) else {
            return Ok(None);
        };
        let changed = image::RgbImage::from_fn(picture.width(), picture.height(), |x, y| {
            let v = image::Rgb(picture.get_pixel(x, y).0.map(f64::from));
            image::Rgb(change(v).0.map(|c| c.round().clamp(0.0, 255.0) as u8))
        });
        let flip = changed == picture;
        let changed = if flip {
            image::imageops::flip_vertical(&changed)
        } else {
            changed
        };
        let Some(folder) = self.source.cache.folder() else {
            return Ok(None);
        };
        let file = folder.join(format!(
            "texture-{}.png",
            if flip { "flipped" } else { "raw" }
        ));
        if std::fs::create_dir_all(folder).is_err() || changed.save(&file).is_err() {
            return Ok(None);
        }
        let path = toml::Value::String(file.to_string_lossy().into_owned());
        self.variant(|scene| {
            for mesh in tables(scene, "meshes") {
                mesh.insert("texture".into(), path.clone());
            }
        })
        .map(Some)
    }
}

/// The image of a point-light stage whose light does not fall off: the light
/// reflected at each pixel's first hit multiplied by `4 pi d^2`.
fn no_falloff(c: &Candidates) -> Result<Option<Film>, SceneError> {
    let scene = &c.expected.scene;
    let Some(Light::Point(light)) = scene.light else {
        return Ok(None);
    };
    let mut film = c.film.clone();
    let camera = scene.camera;
    for (i, pixel) in film.pixels.iter_mut().enumerate() {
        let (row, column) = (i as u32 / camera.width, i as u32 % camera.width);
        if let Some(hit) = scene.intersect(&camera.ray(row, column))
            && matches!(hit.material, Material::Diffuse { .. })
        {
            let d2 = (light.position - hit.point).length_squared();
            *pixel = (*pixel - hit.emission) * (4.0 * PI * d2) + hit.emission;
        }
    }
    Ok(Some(film))
}

/// The image of a stage with glass whose refractive indices are swapped: each glass
/// sphere's index `n` made `1 / n`.
fn inverted_index(c: &Candidates) -> Result<Option<Film>, SceneError> {
    let glass = |m: &Material| matches!(m, Material::Glass { .. } | Material::FresnelGlass { .. });
    if !c.expected.scene.spheres.iter().any(|s| glass(&s.material)) {
        return Ok(None);
    }
    let film = c.variant(|scene| {
        for sphere in tables(scene, "spheres") {
            let material = sphere
                .get_mut("material")
                .and_then(toml::Value::as_table_mut);
            for (kind, index) in material.into_iter().flatten() {
                let n = index.as_float().or(index.as_integer().map(|n| n as f64));
                if let (true, Some(n)) = (kind == "glass" || kind == "fresnel-glass", n) {
                    *index = toml::Value::Float(1.0 / n);
                }
            }
        }
    })?;
    Ok(Some(film))
}

/// The tables of the array of tables `key` of a scene file (`[[spheres]]`,
/// `[[meshes]]`).
fn tables<'t>(file: &'t mut toml::Table, key: &str) -> impl Iterator<Item = &'t mut toml::Table> {
    let items = file.get_mut(key).and_then(toml::Value::as_array_mut);
    items
        .into_iter()
        .flatten()
        .filter_map(toml::Value::as_table_mut)
}

/// The stage's direct light alone: its scene with `indirect = false`.
fn direct_only(c: &Candidates) -> Result<Film, SceneError> {
    c.variant(|scene| {
        if let Some(render) = scene.get_mut("render").and_then(toml::Value::as_table_mut) {
            render.insert("indirect".into(), toml::Value::Boolean(false));
        }
    })
}

/// The image of a light-sampling stage that counts the light twice: once sampled,
/// once more when a bounced ray meets it; about the stage's image plus its direct
/// light.
fn light_twice(c: &Candidates) -> Result<Option<Film>, SceneError> {
    if !c.expected.scene.settings.light_sampling || !c.expected.scene.settings.indirect {
        return Ok(None);
    }
    let direct = direct_only(c)?;
    let mut film = c.film.clone();
    for (a, b) in film.pixels.iter_mut().zip(&direct.pixels) {
        *a += *b;
    }
    Ok(Some(film))
}

/// The image of a stage with indirect light whose paths stop after one bounce, as a
/// bounce counter tested or decremented in the wrong place makes them.
fn one_bounce(c: &Candidates) -> Result<Option<Film>, SceneError> {
    let settings = &c.expected.scene.settings;
    if !settings.indirect || c.expected.deterministic || settings.bounces <= 1 {
        return Ok(None);
    }
    let film = c.variant(|scene| {
        if let Some(render) = scene.get_mut("render").and_then(toml::Value::as_table_mut) {
            render.insert("bounces".into(), toml::Value::Integer(1));
        }
    })?;
    Ok(Some(film))
}

/// The image of a stage whose indirect light is off by a factor: its direct light
/// plus its indirect light (the rest) times the factor `k` that fits the student's
/// image best, when `k` is at least 15% away from 1.
fn bounce_weight(c: &Candidates) -> Result<Option<Film>, SceneError> {
    if !c.expected.scene.settings.indirect || c.expected.deterministic {
        return Ok(None);
    }
    let direct = direct_only(c)?;
    let gamma = c.expected.scene.settings.gamma;
    let s = Linear::from_rgb8(c.student, gamma);
    let (r, d) = (
        Linear::from_film(&c.film, gamma),
        Linear::from_film(&direct, gamma),
    );
    let (mut num, mut den) = (0.0, 0.0);
    for ((s, r), d) in s.values.iter().zip(&r.values).zip(&d.values) {
        let white = 255f64.powf(crate::maths::to_double(gamma)) * 0.999;
        if *s < white && *r < white {
            num += (s - d) * (r - d);
            den += (r - d) * (r - d);
        }
    }
    let k = if den > 0.0 { num / den } else { 1.0 };
    if (k - 1.0).abs() < 0.15 {
        return Ok(None);
    }
    let mut film = c.film.clone();
    for (a, b) in film.pixels.iter_mut().zip(&direct.pixels) {
        *a = *b + (*a - *b) * k as Real;
    }
    Ok(Some(film))
}

/// For a deterministic stage with shadow rays, the reference with the student's
/// isolated dark pixels on lit surfaces made black: it fits an image speckled by
/// shadow acne, and is the reference itself for any other.
fn acne(c: &Candidates) -> Result<Option<Film>, SceneError> {
    let settings = c.expected.scene.settings;
    if !settings.shadows || !c.expected.deterministic {
        return Ok(None);
    }
    let reference = displayed(&c.film, settings.gamma);
    let (w, h) = reference.dimensions();
    let brightness = |image: &RgbImage, x: u32, y: u32| {
        image
            .get_pixel(x, y)
            .0
            .iter()
            .map(|&v| u32::from(v))
            .sum::<u32>()
    };
    let dark = |x: u32, y: u32| {
        let r = brightness(&reference, x, y);
        r >= 60 && brightness(c.student, x, y) * 10 <= r * 4
    };
    let mut film = c.film.clone();
    for y in 1..h.saturating_sub(1) {
        for x in 1..w.saturating_sub(1) {
            let lit_around = [(x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)]
                .iter()
                .filter(|&&(i, j)| !dark(i, j))
                .count();
            if dark(x, y) && lit_around >= 3 {
                film.pixels[(y * w + x) as usize] = crate::maths::Colour::ZERO;
            }
        }
    }
    Ok(Some(film))
}
