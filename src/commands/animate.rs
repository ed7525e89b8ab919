//! `raycourse animate <stage>`: the camera's move, the eye rising around the point
//! it looks at, as an animated GIF or numbered PNG frames.

use std::num::NonZeroU32;
use std::path::Path;
use std::time::Instant;

use clap::builder::PossibleValuesParser;
use clap::{ArgMatches, FromArgMatches, Parser};
use image::codecs::gif::{GifEncoder, Repeat};
use image::{Delay, Frame, RgbaImage};
use raycourse::maths::Real;
use raycourse::messages::said::Said;
use raycourse::messages::{Argument, say};
use raycourse::{Overrides, Stage, encode_png, find_stage, scene_file::stage_names};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::job::Job;
use crate::commands::options::RenderArgs;
use crate::commands::output::{timed_render, write};

/// Render a stage's camera move, the eye rising around the point it looks at,
/// into an animated GIF (or numbered PNG frames if `--out` ends in `.png`).
#[derive(Parser)]
#[command(name = "animate")]
struct AnimateArgs {
    /// The stage (its camera must have a `look_at` point).
    #[arg(value_parser = PossibleValuesParser::new(stage_names(7)))]
    stage: String,
    /// Number of frames.
    #[arg(long, default_value = "24")]
    frames: NonZeroU32,
    /// Plunge angle of the first frame, degrees.
    #[arg(long, default_value_t = 0.0)]
    from: Real,
    /// Plunge angle of the last frame, degrees.
    #[arg(long, default_value_t = 30.0)]
    to: Real,
    #[command(flatten)]
    options: RenderArgs,
}

/// The command line of `animate`: its own arguments and the render options, whose
/// `--out` is here a GIF, or the first of numbered PNG frames.
fn command() -> clap::Command {
    <AnimateArgs as clap::CommandFactory>::command().mut_arg("out", |out| {
        out.help("Output GIF (default: out/<stage>.gif), or numbered PNG frames if it ends in .png")
    })
}

/// The `animate` command (session 7: the aimed camera).
pub const VERB: Verb = Verb {
    rank: 5,
    command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = AnimateArgs::from_arg_matches(matches)?;
    animate(
        &args.stage,
        args.frames.get(),
        (args.from, args.to),
        &args.options,
    )
}

/// The plunge angle of frame `k` of `frames`, from `angles.0` to `angles.1`.
fn angle(k: u32, frames: u32, angles: (Real, Real)) -> Real {
    let step = if frames > 1 {
        k as Real / (frames - 1) as Real
    } else {
        0.0
    };
    angles.0 + (angles.1 - angles.0) * step
}

/// Renders `frames` frames of stage `name` with the plunge angle going from
/// `angles.0` to `angles.1`, into a looping GIF or numbered PNG files.
fn animate(
    name: &str,
    frames: u32,
    angles: (Real, Real),
    options: &RenderArgs,
) -> Result<(), Failure> {
    let stage = find_stage(7, name).expect("clap only accepts stages of session 7");
    let out = options
        .out
        .clone()
        .unwrap_or_else(|| Path::new("out").join(format!("{name}.gif")));
    let as_png = out.extension().is_some_and(|e| e == "png");
    let mut gif = Vec::new();
    let mut encoder = (!as_png).then(|| GifEncoder::new_with_speed(&mut gif, 10));
    if let Some(encoder) = encoder.as_mut() {
        encoder.set_repeat(Repeat::Infinite).map_err(gif_failure)?;
    }
    let start = Instant::now();
    for k in 0..frames {
        let png = frame(stage, (k, frames), angles, options)?;
        match encoder.as_mut() {
            Some(encoder) => add_to_gif(encoder, &png)?,
            None => {
                let stem = out.file_stem().unwrap_or_default().to_string_lossy();
                write(&out.with_file_name(format!("{stem}-{k:03}.png")), &png)?;
            }
        }
    }
    let animated = encoder.is_some();
    drop(encoder);
    if animated {
        write(&out, &gif)?;
    }
    let done = [
        ("name", name.into()),
        ("frames", frames.into()),
        ("from", shortest(angles.0)),
        ("to", shortest(angles.1)),
        ("seconds", start.elapsed().as_secs_f64().into()),
        ("out", out.display().to_string().into()),
    ];
    println!("{}", say(options.language(), "animate-done", &done));
    Ok(())
}

/// Renders frame `k` of `frames` of `stage`, its plunge angle `k / (frames - 1)` of
/// the way through `angles`, and says how long it took (unless quiet); returns the
/// frame as a PNG.
fn frame(
    stage: &Stage,
    (k, frames): (u32, u32),
    angles: (Real, Real),
    options: &RenderArgs,
) -> Result<Vec<u8>, Failure> {
    let language = options.language();
    let overrides = Overrides {
        plunge: Some(angle(k, frames, angles)),
        ..options.overrides()
    };
    let job = Job::of_stage(stage, &overrides, options)?;
    let frame = [
        ("name", stage.name.into()),
        ("frame", (k + 1).into()),
        ("frames", frames.into()),
    ];
    let label = say(language, "animate-frame-label", &frame);
    let timed = timed_render(&label, &job, options)?;
    if !options.work.quiet {
        let seconds = [
            ("label", label.as_str().into()),
            ("seconds", timed.seconds.into()),
        ];
        eprintln!("{}", say(language, "animate-frame", &seconds));
    }
    Ok(encode_png(&timed.result.film, job.scene.settings.gamma))
}

/// Adds the frame `png` to the GIF, shown for a tenth of a second.
fn add_to_gif(encoder: &mut GifEncoder<&mut Vec<u8>>, png: &[u8]) -> Result<(), Failure> {
    let rgb = image::load_from_memory(png).expect("the PNG was just encoded");
    let delay = Delay::from_numer_denom_ms(100, 1);
    let frame = Frame::from_parts(RgbaImage::from(rgb.to_rgba8()), 0, 0, delay);
    encoder.encode_frame(frame).map_err(gif_failure)
}

/// An angle as the command line gave it, whatever the precision of `Real`.
fn shortest(angle: Real) -> Argument<'static> {
    angle.to_string().parse::<f64>().unwrap_or(f64::NAN).into()
}

/// The failure of a GIF that could not be encoded.
fn gif_failure(error: image::ImageError) -> Failure {
    Failure::Broke(Said::new("animate-cannot-encode").with("why", error.to_string()))
}
