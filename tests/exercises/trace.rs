//! A stage that differs though the exercises pass, traced to the call that
//! differs. In a student's exercise crate the course's answers are a crate of
//! their own (`course`): the stage is rendered by both, the pixel the most off is
//! followed ray by ray with each tracer writing down what it traces (as `probe`
//! does), and the first ray or hit that differs is explained by the exercise's
//! function that made it, with its inputs and both answers.

use raycourse::maths::{Colour, Real, Vec3};
use raycourse::{Overrides, Stage};

use crate::generated::{n, v};
use crate::say;

/// One ray of a pixel's path and what it met, in numbers both crates share.
#[derive(Clone, Copy, Debug)]
struct Step {
    origin: Vec3,
    direction: Vec3,
    hit: Option<Met>,
}

/// A hit of a path: where, its normal, the object, and what the object is.
#[derive(Clone, Copy, Debug)]
struct Met {
    t: Real,
    point: Vec3,
    normal: Vec3,
    object: usize,
    surface: Surface,
}

/// What a surface does to the ray that meets it, read from its material's name
/// (the same in both crates, whatever the session).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Surface {
    Diffuse,
    Mirror,
    Glass,
}

impl Surface {
    /// The surface of a material written `{:?}`: `Mirror`, `Glass { index: 1.5 }`.
    fn named(material: &str) -> Surface {
        if material.starts_with("Mirror") {
            Surface::Mirror
        } else if material.contains("Glass") {
            Surface::Glass
        } else {
            Surface::Diffuse
        }
    }
}

/// The path of pixel (`row`, `column`) of `scene` as the crate `$krate` traces it,
/// and the pixel's colour.
macro_rules! path_of {
    ($krate:ident, $scene:expr, $row:expr, $column:expr) => {{
        let mut tracer = $krate::integrator::Tracer::new($scene);
        tracer.log = Some(vec![]);
        let colour = $krate::render::rows::pixel(&mut tracer, $row, $column);
        let log = tracer.log.take().unwrap_or_default();
        let steps: Vec<Step> = log
            .iter()
            .map(|traced| Step {
                origin: traced.ray.origin,
                direction: traced.ray.direction,
                hit: traced.hit.map(|h| Met {
                    t: h.t,
                    point: h.point,
                    normal: h.normal,
                    object: h.object,
                    surface: Surface::named(&format!("{:?}", h.material)),
                }),
            })
            .collect();
        (steps, colour)
    }};
}

/// The overrides of the stage lines, for the course's crate.
fn course_overrides(overrides: &Overrides) -> course::Overrides {
    course::Overrides {
        width: overrides.width,
        height: overrides.height,
        samples: overrides.samples,
        seed: overrides.seed,
        ..course::Overrides::default()
    }
}

/// In a student's exercise crate, why the stage rendered with `overrides` (its
/// pixels `rendered` by the student's code) differs from the course's: the first
/// call along the path of the pixel the most off whose result differs. Nothing in the course's own crate, where the course is
/// the code under test, or when the course's render is the same.
pub fn trace(stage: &Stage, overrides: &Overrides, rendered: &[Colour]) -> Option<String> {
    if !cfg!(course_answers) {
        return None;
    }
    let yours = stage.scene(overrides).ok()?;
    let theirs = course::stages()
        .find(|s| s.name == stage.name)?
        .scene(&course_overrides(overrides))
        .ok()?;
    let gamma = yours.settings.gamma;
    let (row, column) = most_off(
        rendered,
        &course::render(&theirs).film.pixels,
        yours.camera.width,
        gamma,
    )?;
    let (your_path, your_colour) = path_of!(raycourse, &yours, row, column);
    let (course_path, course_colour) = path_of!(course, &theirs, row, column);
    let pixel = say!("trace-pixel-row-column", row = row, column = column);
    let found = first_difference(&your_path, &course_path, &yours, &theirs, (row, column))
        .or_else(|| shading(your_colour, course_colour, gamma))?;
    Some(say!(
        "trace-followed-ray-by-ray-differs-first",
        pixel = pixel,
        found = found
    ))
}

/// Whether a stage's failure `why` already names the call that differs: traced
/// ray by ray, or a panic in an exercise's function (`panics::explain`).
pub fn names_the_call(why: &str) -> bool {
    [
        "followed ray by ray",
        "suivi rayon par rayon",
        "panicked in exercise",
        "panique dans l'exercice",
    ]
    .iter()
    .any(|words| why.contains(words))
}

/// The pixel whose displayed levels differ the most between two films of `width`
/// columns, if any does.
fn most_off(yours: &[Colour], theirs: &[Colour], width: u32, gamma: Real) -> Option<(u32, u32)> {
    let level = |c: Colour| {
        c.to_array()
            .map(|x| raycourse::render::film::display(x, gamma))
    };
    let off = |k: usize| {
        let (a, b) = (level(yours[k]), level(theirs[k]));
        (0..3).map(|i| a[i].abs_diff(b[i])).max().unwrap_or(0)
    };
    let worst = (0..yours.len().min(theirs.len())).max_by_key(|&k| off(k))?;
    (off(worst) > 0).then(|| (worst as u32 / width, worst as u32 % width))
}

/// Whether two vectors differ by more than rounding, relative to their size.
fn apart(a: Vec3, b: Vec3) -> bool {
    (a - b).length() > 1e-6 * a.length().max(b.length()).max(1e-30)
}

/// The first step where the two paths differ, explained.
fn first_difference(
    yours: &[Step],
    theirs: &[Step],
    your_scene: &raycourse::scene::Scene,
    course_scene: &course::scene::Scene,
    (row, column): (u32, u32),
) -> Option<String> {
    for (k, (y, c)) in yours.iter().zip(theirs).enumerate() {
        if apart(y.origin, c.origin) || apart(y.direction, c.direction) {
            return Some(if k == 0 {
                camera_ray(y, c, your_scene, course_scene, (row, column))
            } else {
                new_ray(y, c, &theirs[k - 1])
            });
        }
        if let Some(found) = hit(y, c, your_scene, course_scene) {
            return Some(found);
        }
    }
    (yours.len() != theirs.len()).then(|| {
        say!(
            "trace-the-number-of-rays-yours-traced",
            yours = yours.len(),
            theirs = theirs.len()
        )
    })
}

/// The exercise's words: `exercise s1.1, Camera::pixel_direction`.
fn exercise(id: &str, function: &str) -> String {
    say!("trace-exercise", id = id, function = function)
}

/// The camera ray differs: the course's pixel direction compared first.
fn camera_ray(
    y: &Step,
    c: &Step,
    your_scene: &raycourse::scene::Scene,
    course_scene: &course::scene::Scene,
    (row, column): (u32, u32),
) -> String {
    let gave = your_scene.camera.pixel_direction(row, column);
    let expected = course_scene.camera.pixel_direction(row, column);
    if apart(gave, expected) {
        return say!(
            "trace-the-camera-ray-pixel-direction-row",
            s1_pixel_direction = exercise("s1.1", "Camera::pixel_direction"),
            camera_width = your_scene.camera.width,
            camera_height = your_scene.camera.height,
            gave = v(gave),
            expected = v(expected),
            row = row,
            column = column
        );
    }
    say!(
        "trace-the-camera-ray-yours-from-along",
        y_origin = v(y.origin),
        y_direction = v(y.direction),
        c_origin = v(c.origin),
        c_direction = v(c.direction)
    )
}

/// A ray after the first differs, though the hit it leaves is the same: its
/// origin is the spawn's, its direction the surface's.
fn new_ray(y: &Step, c: &Step, before: &Step) -> String {
    let Some(at) = before.hit else {
        return say!(
            "trace-a-ray-after-a-miss-yours",
            y_origin = v(y.origin),
            y_direction = v(y.direction),
            c_origin = v(c.origin),
            c_direction = v(c.direction)
        );
    };
    let from = say!(
        "trace-the-ray-leaving-the-hit-at",
        at_point = v(at.point),
        at_normal = v(at.normal),
        c_direction = v(c.direction)
    );
    if !apart(y.direction, c.direction) {
        return say!(
            "trace-its-origin-yours-the-course-s",
            s2_spawn = exercise("s2.2", "Hit::spawn"),
            y_origin = v(y.origin),
            c_origin = v(c.origin),
            from = from
        );
    }
    let (id, function) = match at.surface {
        Surface::Mirror => ("s2.4", "reflect"),
        Surface::Glass => ("s2.5", "refract"),
        Surface::Diffuse => (
            "s3.1, s3.2, s3.3, s4.1",
            "sample_cosine_hemisphere, Frame::new, Tracer::indirect_light, Cone::sample",
        ),
    };
    say!(
        "trace-the-incoming-direction-d-its-direction",
        id_function = exercise(id, function),
        before_direction = v(before.direction),
        y_direction = v(y.direction),
        c_direction = v(c.direction),
        from = from
    )
}

/// The same ray met different things: each sphere's test is asked, then the
/// nearest of them.
fn hit(
    y: &Step,
    c: &Step,
    your_scene: &raycourse::scene::Scene,
    course_scene: &course::scene::Scene,
) -> Option<String> {
    let same = match (y.hit, c.hit) {
        (None, None) => true,
        (Some(a), Some(b)) => {
            (a.t - b.t).abs() <= 1e-6 * b.t.abs()
                && !apart(a.normal, b.normal)
                && a.object == b.object
        }
        _ => false,
    };
    if same {
        return None;
    }
    let ray = raycourse::geometry::Ray {
        origin: c.origin,
        direction: c.direction,
    };
    let course_ray = course::geometry::Ray {
        origin: c.origin,
        direction: c.direction,
    };
    let shown = say!(
        "trace-the-ray-from-along",
        c_origin = v(c.origin),
        c_direction = v(c.direction)
    );
    let spheres = your_scene.spheres.iter().zip(&course_scene.spheres);
    for (index, (mine, course)) in spheres.enumerate() {
        let (gave, expected) = (mine.intersect(&ray), course.intersect(&course_ray));
        if gave
            .zip(expected)
            .map_or(gave.is_some() != expected.is_some(), |(a, b)| {
                (a - b).abs() > 1e-6 * b.abs()
            })
        {
            return Some(say!(
                "trace-and-sphere-centre-radius-yours-gave",
                course_centre = v(course.centre),
                course_radius = n(course.radius),
                s1_intersect = exercise("s1.2", "Sphere::intersect"),
                distance_gave = distance(gave),
                distance_expected = distance(expected),
                shown = shown,
                index = index
            ));
        }
    }
    Some(say!(
        "trace-yours-met-the-course-s-every",
        y_hit = met(y.hit),
        c_hit = met(c.hit),
        shown = shown
    ))
}

/// A distance as the book writes it: `t = 4`, or no hit.
fn distance(t: Option<Real>) -> String {
    t.map_or(say!("trace-no-hit"), |t| format!("t = {}", n(t)))
}

/// A hit as the book writes it.
fn met(hit: Option<Met>) -> String {
    hit.map_or(say!("trace-nothing"), |h| {
        say!(
            "trace-object-at-t-n",
            h_object = h.object,
            h = n(h.t),
            h_normal = v(h.normal)
        )
    })
}

/// Every ray and hit agree: the difference is in the light computed at them.
fn shading(yours: Colour, theirs: Colour, gamma: Real) -> Option<String> {
    let display = |c: Colour| {
        c.to_array()
            .map(|x| raycourse::render::film::display(x, gamma))
    };
    if !apart(yours, theirs) {
        let course_levels = theirs
            .to_array()
            .map(|x| course::render::film::display(x, gamma));
        return (display(yours) != course_levels).then(|| {
            say!(
                "trace-the-display-of-the-same-radiance",
                theirs = v(theirs),
                exercise_s2 = exercise("s2.1", "display"),
                yours = format!("{:?}", display(yours)),
                course_levels = format!("{:?}", course_levels)
            )
        });
    }
    Some(say!(
        "trace-the-light-computed-along-the-same",
        yours = v(yours),
        theirs = v(theirs)
    ))
}

/// The overrides of a stage line: `width` x `height`, `samples`, `seed`.
pub fn overrides(width: u32, height: u32, samples: u32, seed: Option<u64>) -> Overrides {
    Overrides {
        seed,
        ..Overrides::sized(width, height, samples)
    }
}
