//! `raycourse check <stage> <image>`: is a student's image of a stage right, and if
//! not, what differs, where, and which classic mistake explains it;
//! `raycourse check --all DIR` grades a folder of them.

use std::path::{Path, PathBuf};

use clap::builder::PossibleValuesParser;
use clap::{ArgMatches, FromArgMatches, Parser};
use image::RgbImage;
use indicatif::{ProgressBar, ProgressStyle};
use raycourse::check::expected::Source;
use raycourse::check::language::Language;
use raycourse::check::report::{Report, Verdict, check};
use raycourse::{Stage, stages};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::options::WorkArgs;
use crate::commands::output::write;

/// Check an image of a stage made by your own renderer, in any language: render
/// the stage's reference at the image's size (cached), compare, and say what
/// differs, where, and the likely mistake. Exit code 0: it matches; 1: it differs;
/// 2: bad input.
#[derive(Parser)]
#[command(name = "check")]
struct CheckArgs {
    /// The stage (see `list`).
    #[arg(required_unless_present = "all", value_parser = PossibleValuesParser::new(stages().map(|s| s.name)))]
    stage: Option<String>,
    /// Your image of it (PNG or JPEG, any size).
    #[arg(required_unless_present = "all")]
    image: Option<PathBuf>,
    /// Grade a folder of images named after the stages (`glass.png`, ...): a table,
    /// and a CSV grading sheet; or a class, a folder of such folders (one per
    /// student): a row per student and a column per stage.
    #[arg(long, conflicts_with_all = ["stage", "image"])]
    all: Option<PathBuf>,
    /// Write a picture of the differences (differing pixels or blocks in red).
    #[arg(long)]
    diff: Option<PathBuf>,
    /// The grading sheet of `--all` (default: `grades.csv` in the folder).
    #[arg(long)]
    csv: Option<PathBuf>,
    /// Folder of cached reference images.
    #[arg(long, default_value = "out/reference")]
    cache: PathBuf,
    #[command(flatten)]
    work: WorkArgs,
    /// The report's language, `en` or `fr` (default: the locale's, from `LC_ALL`,
    /// `LC_MESSAGES` or `LANG`; English unless it is French).
    #[arg(long, value_parser = ["en", "fr"])]
    lang: Option<String>,
}

impl CheckArgs {
    /// The language of the report: `--lang`, or the environment's.
    fn language(&self) -> Language {
        self.lang
            .as_deref()
            .map_or_else(Language::from_environment, Language::from_locale)
    }
}

/// The `check` command (the whole course: session 7).
pub const VERB: Verb = Verb {
    rank: 9,
    command: <CheckArgs as clap::CommandFactory>::command,
    run,
};

inventory::submit! { VERB }

fn run(matches: &ArgMatches) -> Result<(), Failure> {
    let args = CheckArgs::from_arg_matches(matches)?;
    if let Some(dir) = &args.all {
        return grade(&args, dir);
    }
    let name = args
        .stage
        .as_deref()
        .expect("clap requires a stage without --all");
    let stage = stages()
        .find(|s| s.name == name)
        .expect("clap only accepts this build's stages");
    let path = args
        .image
        .as_deref()
        .expect("clap requires an image without --all");
    let image = read_image(path)?;
    let report = check_one(&args, stage, &image, path)?;
    for line in report.lines(stage, args.language()) {
        println!("{line}");
    }
    if let Some(diff) = &args.diff {
        let picture = report.difference_image(&image);
        let png = raycourse::render::png::encode_rgb8(
            picture.as_raw(),
            picture.width(),
            picture.height(),
        );
        write(diff, &png)?;
    }
    match report.verdict {
        Verdict::Matches => Ok(()),
        Verdict::Differs => Err(Failure::Differs),
    }
}

/// The image at `path`, as 8-bit RGB; a bad input otherwise.
fn read_image(path: &Path) -> Result<RgbImage, Failure> {
    let image = image::open(path).map_err(|e| {
        Failure::Input(format!(
            "{}: not a PNG or JPEG image that can be read: {e}",
            path.display()
        ))
    })?;
    Ok(image.to_rgb8())
}

/// Checks `image` (read from `path`) against `stage`, rendering on the options'
/// threads with a progress bar.
fn check_one(
    args: &CheckArgs,
    stage: &Stage,
    image: &RgbImage,
    path: &Path,
) -> Result<Report, Failure> {
    let pool = args.work.pool()?;
    let bar = if args.work.quiet {
        ProgressBar::hidden()
    } else {
        let style = ProgressStyle::with_template("{msg} {spinner} {pos} rows")
            .expect("the template is valid");
        ProgressBar::new_spinner()
            .with_style(style)
            .with_message(format!("{}: reference", stage.name))
    };
    let progress = |_| bar.inc(1);
    let source = Source {
        stage,
        size: image.dimensions(),
        cache: &args.cache,
        files: &raycourse::Disk,
        progress: &progress,
    };
    let lossy = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("jpg") || e.eq_ignore_ascii_case("jpeg"));
    let report = pool.install(|| check(&source, image, lossy));
    bar.finish_and_clear();
    Ok(report?)
}

/// Grades the images of the folder `dir`: one row per stage of the build; or, for a
/// class (a folder of students' folders and no stage image of its own), one row per
/// student.
fn grade(args: &CheckArgs, dir: &Path) -> Result<(), Failure> {
    if !dir.is_dir() {
        return Err(Failure::Input(format!("{}: not a folder", dir.display())));
    }
    let students = students(dir)?;
    if image_of_any_stage(dir).is_none() {
        if students.iter().all(|s| image_of_any_stage(s).is_none()) {
            return Err(Failure::Input(format!(
                "{}: no image of a stage here, nor in a student's folder: name each image after \
                 its stage, such as glass.png (`raycourse list` gives the stages)",
                dir.display()
            )));
        }
        return grade_class(args, dir, &students);
    }
    let rows = grade_folder(args, dir)?;
    let mut csv =
        String::from("stage,session,figure,verdict,differing,red,green,blue,noise,hint\n");
    println!("{:<17} {:<10} hint", "stage", "verdict");
    for (stage, row) in &rows {
        println!("{:<17} {:<10} {}", stage.name, row.verdict, row.hint);
        csv += &format!(
            "{},{},{},{},{}\n",
            stage.name,
            stage.session,
            stage.figure.map_or(String::new(), |f| f.to_string()),
            row.verdict,
            row.figures
        );
    }
    let sheet = args.csv.clone().unwrap_or_else(|| dir.join("grades.csv"));
    write(&sheet, csv.as_bytes())?;
    println!("grading sheet -> {}", sheet.display());
    finish(rows.iter().all(|(_, row)| row.passes()))
}

/// Grades every student's folder of the class in `dir`: a table of verdicts on the
/// terminal, and one CSV row per student with, for each stage, the verdict and the
/// hint.
fn grade_class(args: &CheckArgs, dir: &Path, students: &[PathBuf]) -> Result<(), Failure> {
    let mut csv = String::from("student");
    for stage in stages() {
        csv += &format!(",{0},{0} hint", stage.name);
    }
    csv += "\n";
    let mut all_pass = true;
    for folder in students {
        let name = folder.file_name().unwrap_or_default().to_string_lossy();
        let rows = grade_folder(args, folder)?;
        let matching = rows.iter().filter(|(_, r)| r.verdict == "matches").count();
        let differing: Vec<&str> = rows
            .iter()
            .filter(|(_, r)| !r.passes())
            .map(|(s, _)| s.name)
            .collect();
        println!(
            "{name:<20} {matching:>2} of {} match; differ: {}",
            rows.len(),
            if differing.is_empty() {
                "none".to_owned()
            } else {
                differing.join(", ")
            }
        );
        csv += &quoted(&name);
        for (_, row) in &rows {
            csv += &format!(",{},{}", row.verdict, quoted(&row.hint));
        }
        csv += "\n";
        all_pass &= rows.iter().all(|(_, row)| row.passes());
    }
    let sheet = args.csv.clone().unwrap_or_else(|| dir.join("grades.csv"));
    write(&sheet, csv.as_bytes())?;
    println!("grading sheet -> {}", sheet.display());
    finish(all_pass)
}

/// Each stage of the build with the row of its image in `dir`.
fn grade_folder(args: &CheckArgs, dir: &Path) -> Result<Vec<(&'static Stage, Row)>, Failure> {
    let language = args.language();
    let mut rows = vec![];
    for stage in stages() {
        let row = match image_of(dir, stage) {
            None => Row::missing(),
            Some(path) => match read_image(&path) {
                Err(failure) => Row::unreadable(failure),
                Ok(image) => Row::of(&check_one(args, stage, &image, &path)?, language),
            },
        };
        rows.push((stage, row));
    }
    Ok(rows)
}

/// The image of `stage` in `dir`: `glass.png`, `glass.jpg` or `glass.jpeg`.
fn image_of(dir: &Path, stage: &Stage) -> Option<PathBuf> {
    ["png", "jpg", "jpeg"]
        .iter()
        .map(|e| dir.join(format!("{}.{e}", stage.name)))
        .find(|p| p.exists())
}

/// The image of any stage in `dir`, if there is one.
fn image_of_any_stage(dir: &Path) -> Option<PathBuf> {
    stages().find_map(|stage| image_of(dir, stage))
}

/// The students' folders of a class folder, sorted by name.
fn students(dir: &Path) -> Result<Vec<PathBuf>, Failure> {
    let entries =
        std::fs::read_dir(dir).map_err(|e| Failure::Input(format!("{}: {e}", dir.display())))?;
    let mut folders: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir() && p.file_name().is_some_and(|n| n != "reference"))
        .collect();
    folders.sort();
    Ok(folders)
}

/// A CSV field: in quotes when it holds a comma, a quote or a line break; and, when
/// it begins as a spreadsheet formula does (`=`, `+`, `-`, `@`, a tab or a carriage
/// return), after a `'`, so that a spreadsheet shows it as text rather than run it
/// (OWASP's advice against CSV injection): a student's folder may be named
/// `=HYPERLINK(...)`.
fn quoted(text: &str) -> String {
    let text = if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{text}")
    } else {
        text.to_owned()
    };
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text
    }
}

/// Success when every image passed; exit code 1 otherwise.
fn finish(all_pass: bool) -> Result<(), Failure> {
    if all_pass {
        Ok(())
    } else {
        Err(Failure::Differs)
    }
}

/// One row of the grading sheet.
struct Row {
    verdict: &'static str,
    hint: String,
    /// The CSV columns after the verdict.
    figures: String,
}

impl Row {
    /// Whether the row does not count against the student: a matching image, or none.
    fn passes(&self) -> bool {
        self.verdict == "matches" || self.verdict == "missing"
    }

    /// No image of the stage in the folder.
    fn missing() -> Row {
        Row {
            verdict: "missing",
            hint: String::new(),
            figures: ",,,,,".into(),
        }
    }

    /// An image that cannot be read.
    fn unreadable(failure: Failure) -> Row {
        let hint = failure.to_string();
        Row {
            verdict: "unreadable",
            figures: format!(",,,,,{}", quoted(&hint)),
            hint,
        }
    }

    /// The row of a checked image, its hint named in `language`.
    fn of(report: &Report, language: Language) -> Row {
        let verdict = match report.verdict {
            Verdict::Matches => "matches",
            Verdict::Differs => "differs",
        };
        let hint = report
            .hint
            .map_or(String::new(), |m| m.words(language)[0].to_owned());
        let [r, g, b] = report.ratio;
        let noise = report
            .noise
            .map_or(String::new(), |(n, _)| format!("{n:.3}"));
        let figures = format!(
            "{:.4},{r:.4},{g:.4},{b:.4},{noise},{hint}",
            report.outcome.share()
        );
        Row {
            verdict,
            hint,
            figures,
        }
    }
}
