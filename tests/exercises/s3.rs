//! Session 3: the cosine-weighted direction, its frame, the indirect bounce, the
//! Gaussian pixel filter.

use raycourse::geometry::{Hit, Ray};
use raycourse::integrator::Tracer;
use raycourse::maths::frame::Frame;
use raycourse::maths::sampling::{sample_cosine_hemisphere, sample_gaussian};
use raycourse::maths::{Colour, PI, Real, Vec3};

use crate::checklist::Exercise;
use crate::generated;
use crate::known::{Outcome, close, close_vec, ensure, grid_mean, num, vec};
use crate::s1::scene;
use crate::say;
use crate::words::{decimal, separator};

/// Session 3's exercises, in the book's order.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "s3.1",
        name: "s3_1_sample_cosine_hemisphere",
        shown_by: "indirect",
        needs: &[],
        check: cosine_direction,
    },
    Exercise {
        id: "s3.2",
        name: "s3_2_frame_new",
        shown_by: "indirect",
        needs: &[],
        check: frame,
    },
    Exercise {
        id: "s3.3",
        name: "s3_3_tracer_indirect_light",
        shown_by: "indirect",
        needs: &["s3.1", "s3.2"],
        check: indirect_bounce,
    },
    Exercise {
        id: "s3.4",
        name: "s3_4_sample_gaussian",
        shown_by: "antialiasing",
        needs: &[],
        check: gaussian,
    },
];

/// The grid used for the samplers' averages: 64 x 64 points.
const GRID: u32 = 64;

/// With density `cos(theta) / pi`, `E[cos theta] = int cos^2 / pi dw = 2/3` and
/// `E[cos^2 theta] = 1/2`; the azimuth is uniform, so `E[x] = E[y] = 0` and
/// `E[x^2] = E[sin^2 theta] / 2 = 1/4`. Every direction is a unit vector above
/// the surface (`z >= 0`).
fn cosine_direction() -> Outcome {
    let mut worst: Option<(Real, Real, Vec3)> = None;
    let [z, z2, x, y, x2] = grid_mean(GRID, |u1, u2| {
        let w = sample_cosine_hemisphere(u1, u2);
        if w.z < -1e-6 || (w.length() - 1.0).abs() > 1e-4 {
            worst.get_or_insert((u1, u2, w));
        }
        [w.z, w.z * w.z, w.x, w.y, w.x * w.x]
    });
    if let Some((u1, u2, w)) = worst {
        let (u1, u2, s) = (num(u1), num(u2), separator());
        return Err(say!(
            "s3-u1-u2-gave-expected-a-unit",
            vec_w = vec(w),
            u1 = u1,
            u2 = u2,
            s = s
        ));
    }
    close(&say!("s3-the-mean-of-cos-theta-z"), z, 2.0 / 3.0, 0.01)
        .map_err(|e| say!("s3-uniform-directions-would-give-1-2", e = e))?;
    close(&mean_of("cos^2(theta)"), z2, 0.5, 0.01)?;
    let whole_circle = |e: String| say!("s3-the-azimuth-phi-2-pi-u", e = e);
    close(&mean_of("x"), x, 0.0, 0.01).map_err(whole_circle)?;
    close(&mean_of("y"), y, 0.0, 0.01).map_err(whole_circle)?;
    close(&mean_of("x^2"), x2, 0.25, 0.01)?;
    generated::cosine_direction(sample_cosine_hemisphere)
}

/// `the mean of x`, in the checklist's language.
pub fn mean_of(what: &str) -> String {
    say!("s3-the-mean-of", what = what)
}

/// The frame of a normal `N`: two tangents `T1`, `T2` of length 1, at right angles
/// to each other and to `N`, with `N` itself as the third axis, for every normal
/// (the poles and the axes included).
fn frame() -> Outcome {
    let normals = [
        Vec3::Z,
        -Vec3::Z,
        Vec3::X,
        -Vec3::Y,
        Vec3::new(1.0, 2.0, 3.0).normalize(),
        Vec3::new(-0.3, 0.1, -0.9).normalize(),
        Vec3::new(1e-4, 0.0, -1.0).normalize(),
    ];
    for n in normals {
        let f = Frame::new(n);
        let what = say!("s3-the-frame-of-n", vec = vec(n));
        let colon = say!("s3-message");
        close_vec(&say!("s3-its-axis-n", what = what), f.n, n, 1e-6)?;
        for (name, t) in [("T1", f.t1), ("T2", f.t2)] {
            close(
                &say!("s3-the-length-of", vec = vec(t), what = what, name = name),
                t.length(),
                1.0,
                1e-5,
            )?;
            close(&format!("{what}{colon} {name} . N"), t.dot(n), 0.0, 1e-5)?;
        }
        close(&format!("{what}{colon} T1 . T2"), f.t1.dot(f.t2), 0.0, 1e-5)?;
    }
    generated::frame(Frame::new)
}

/// A furnace with a known answer: inside a sphere of radius 10 and albedo 0.5, a
/// point light of power `Phi = 800 pi^2` at its centre lights every point of the
/// wall head on, so the wall sends `Phi / (4 pi 10^2) * 1 * 0.5 / pi = 1` in every
/// direction by direct light alone. Every point of the wall sees the same wall, so
/// with `k` bounces left it sends `L_k = 1 + 0.5 L_(k-1)`, `L_0 = 1`: `L_1 = 1.5`,
/// `L_2 = 1.75`. A bounce from the floor with `b` bounces allowed brings back
/// `albedo * L_(b-1)` whichever direction it draws, if its weight matches its
/// density, and its ray starts off the floor so that it meets the wall, not the
/// floor it leaves.
fn indirect_bounce() -> Outcome {
    let furnace = scene(
        "[render]\nwidth = 8\nheight = 8\nbounces = 1\nindirect = true\ngamma = 2.2\n\
         [camera]\nposition = [0, 0, 0]\nfov = 60\n\
         [light]\nposition = [0, 0, 0]\nintensity = 7895.6835208714865\n\
         [[spheres]]\ncentre = [0, 0, 0]\nradius = 10\nmaterial = { diffuse = [0.5, 0.5, 0.5] }\n",
    );
    let mut tracer = Tracer::new(&furnace);
    // A point of the floor whose coordinates are rounded, as a hit's usually are.
    let down = Vec3::new(0.3, -1.0, 0.2).normalize();
    let floor = tracer
        .trace(&Ray::new(Vec3::ZERO, down))
        .expect("the ray down meets the furnace's floor")
        .facing_the_ray();
    bounce_start(&mut tracer, &floor)?;
    bounce_weight(&mut tracer, &floor)?;
    bounces_passed_on(&mut tracer, &floor)?;
    generated::indirect_light(|tracer, hit, albedo, bounces| {
        tracer.indirect_light(hit, albedo, bounces)
    })
}

/// The albedo of the furnace's checks.
const ALBEDO: Colour = Colour::new(0.8, 0.4, 0.2);

/// The mean of `n` bounces from `floor` with `bounces` allowed, over `ALBEDO`.
fn mean_bounce(tracer: &mut Tracer, floor: &Hit, bounces: u32, n: u32) -> Colour {
    (0..n)
        .map(|_| tracer.indirect_light(floor, ALBEDO, bounces))
        .sum::<Colour>()
        / n as Real
}

/// One bounce allowed: the mean of 20,000 bounces is `albedo * L_0 = albedo`
/// within 3%.
fn bounce_weight(tracer: &mut Tracer, floor: &Hit) -> Outcome {
    let n = 20_000;
    let mean = mean_bounce(tracer, floor, 1, n);
    let right = (mean / ALBEDO - Colour::ONE).abs().max_element() < 0.03;
    ensure(right, || {
        let albedo = vec(ALBEDO);
        say!(
            "s3-inside-a-furnace-whose-wall-glows",
            vec_mean = vec(mean),
            mean_element_sum = weight_hint((mean / ALBEDO).element_sum() / 3.0),
            n = n,
            albedo = albedo
        )
    })
}

/// The bounce's ray, written down by the tracer's log, meets the wall at a
/// distance `20 cos(theta)`, never the floor it starts from at a distance of the
/// order of the rounding (`1e-15`).
fn bounce_start(tracer: &mut Tracer, floor: &Hit) -> Outcome {
    tracer.log = Some(vec![]);
    for _ in 0..200 {
        tracer.indirect_light(floor, ALBEDO, 1);
    }
    let log = tracer.log.take().unwrap_or_default();
    let own = log.iter().filter_map(|r| r.hit).find(|h| h.t < 1e-9);
    ensure(own.is_none(), || {
        say!(
            "s3-a-bounce-from-the-furnace-s",
            h_h = decimal(format!("{:.1e}", own.map_or(0.0, |h| h.t)))
        )
    })
}

/// Three bounces allowed: the floor sees the wall with two bounces left,
/// `albedo * L_2 = 1.75 albedo`; a path cut after the first bounce brings back
/// `albedo` alone.
fn bounces_passed_on(tracer: &mut Tracer, floor: &Hit) -> Outcome {
    let mean = mean_bounce(tracer, floor, 3, 2_000);
    let ratio = (mean / ALBEDO).element_sum() / 3.0;
    ensure((ratio / 1.75 - 1.0).abs() < 0.03, || {
        let hint = if (ratio - 1.0).abs() < 0.03 {
            say!("s3-the-wall-was-seen-with-no")
        } else {
            String::new()
        };
        say!(
            "s3-inside-the-same-furnace-with-3",
            vec_mean = vec(mean),
            vec = vec(1.75 * ALBEDO),
            hint = hint
        )
    })
}

/// What a bounce that brings back `ratio` times the right light most likely got
/// wrong in its weight.
pub fn weight_hint(ratio: Real) -> String {
    let near = |target: Real| (ratio / target - 1.0).abs() < 0.03;
    if near(2.0 / 3.0) {
        say!("s3-2-3-of-it-is-the")
    } else if near(1.0 / PI) {
        say!("s3-1-pi-of-it-the-brdf")
    } else if near(2.0) {
        say!("s3-twice-it-the-weight-divides-by")
    } else {
        String::new()
    }
}

/// Box-Muller: two independent normal numbers, so over the grid `E[x] = E[y] = 0`,
/// `E[x^2] = E[y^2] = sigma^2`, `E[xy] = 0`, and a share `1 - e^(-1/2) = 0.3935`
/// of the points within `sigma` of the centre; finite for `u1 = 0` and for the
/// largest `u1` below 1.
fn gaussian() -> Outcome {
    let sigma = 0.5;
    let [x, y, x2, y2, xy, within] = grid_mean(GRID, |u1, u2| {
        let (x, y) = sample_gaussian(u1, u2, sigma);
        let inside = if x * x + y * y <= sigma * sigma {
            1.0
        } else {
            0.0
        };
        [x, y, x * x, y * y, x * y, inside]
    });
    let sigma_is = format!(", sigma = {}", num(sigma));
    close(&mean_of("x"), x, 0.0, 0.01)?;
    close(&mean_of("y"), y, 0.0, 0.01)?;
    close(&(mean_of("x^2") + &sigma_is), x2, 0.25, 0.01)?;
    close(&(mean_of("y^2") + &sigma_is), y2, 0.25, 0.01)?;
    close(&mean_of("x y"), xy, 0.0, 0.01)?;
    close(
        &say!("s3-the-share-of-offsets-within-sigma"),
        within,
        0.3935,
        0.01,
    )?;
    for u1 in [0.0, 1.0 - Real::EPSILON] {
        let (x, y) = sample_gaussian(u1, 0.3, sigma);
        ensure(x.is_finite() && y.is_finite(), || {
            let [u1, x, y] = [u1, x, y].map(|v| decimal(v.to_string()));
            let s = separator();
            say!(
                "s3-u1-gave-expected-finite-numbers-the",
                u1 = u1,
                x = x,
                y = y,
                s = s
            )
        })?;
    }
    generated::gaussian(sample_gaussian)
}
