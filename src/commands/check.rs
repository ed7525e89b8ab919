//! `raycourse check <stage> <image>`: is a student's image of a stage right, and if
//! not, what differs, where, and which classic mistake explains it;
//! `raycourse check --all DIR` grades a folder of them.

use std::path::{Path, PathBuf};

use clap::builder::PossibleValuesParser;
use clap::{ArgMatches, FromArgMatches, Parser};
use image::RgbImage;
use indicatif::{ProgressBar, ProgressStyle};
use raycourse::check::expected::{Renderer, Source};
use raycourse::check::grading::{
    Grade, ON_DISK, any_stage_image_among, class_sheet, decode, folder_lines, folder_sheet,
    grade_folder, image_of_any_stage, lossy, student_line, students,
};
use raycourse::check::report::{Report, Verdict, check};
use raycourse::messages::language::Language;
use raycourse::messages::{Argument, say};
use raycourse::render::cache::Folder;
use raycourse::{Stage, stages};

use crate::commands::Verb;
use crate::commands::failure::Failure;
use crate::commands::options::WorkArgs;
use crate::commands::output::write;

/// Check an image of a stage made by your own renderer, in any language: render
/// the stage's reference at the image's size (cached), compare, and say what
/// differs, where, and the likely mistake. Exit code 0: it matches (with `--all`,
/// every image found matches); 1: it differs (with `--all`, one differs or cannot
/// be read); 2: bad input.
#[derive(Parser)]
#[command(name = "check")]
struct CheckArgs {
    /// The stage (see `list`); required without `--all`.
    #[arg(required_unless_present = "all", value_parser = PossibleValuesParser::new(stages().map(|s| s.name)))]
    stage: Option<String>,
    /// Your image of it (PNG, JPEG or PPM, any size); required without `--all`.
    #[arg(required_unless_present = "all")]
    image: Option<PathBuf>,
    /// Grade a folder of images named after the stages (`glass.png`, `glass.jpg`,
    /// `glass.jpeg` or `glass.ppm`, ...): a table, and a CSV grading sheet; or a class, a folder of such folders (one per
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
    let image = read_image(path, args.language())?;
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

/// The image at `path`, as 8-bit RGB; a bad input otherwise, said in `language`.
fn read_image(path: &Path, language: Language) -> Result<RgbImage, Failure> {
    let bytes = std::fs::read(path).map_err(|e| {
        refused(
            path,
            language,
            "check-cannot-read",
            &[("error", e.to_string().into())],
        )
    })?;
    decode(path, &bytes, language).map_err(Failure::Input)
}

/// A bad input: the file or folder `path`, then the message `id` in `language`
/// with its `arguments`.
fn refused(path: &Path, language: Language, id: &str, arguments: &[(&str, Argument)]) -> Failure {
    let why = say(language, id, arguments);
    Failure::Input(format!("{}: {why}", path.display()))
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
        cache: &Folder(&args.cache),
        files: &raycourse::Disk,
        progress: &progress,
        renderer: RENDERER,
    };
    let report = pool.install(|| check(&source, image, lossy(path)));
    bar.finish_and_clear();
    Ok(report?)
}

/// What renders the references: the fast engine where this build has it, which
/// gives the course's images in less time.
#[cfg(feature = "beyond")]
const RENDERER: &dyn Renderer = &raycourse::engines::Fast;
/// What renders the references: the course's code.
#[cfg(not(feature = "beyond"))]
const RENDERER: &dyn Renderer = &raycourse::check::expected::Course;

/// Grades the images of the folder `dir`: one row per stage of the build; or, for a
/// class (a folder of students' folders and no stage image of its own), one row per
/// student.
fn grade(args: &CheckArgs, dir: &Path) -> Result<(), Failure> {
    let language = args.language();
    if !dir.is_dir() {
        return Err(refused(dir, language, "check-not-a-folder", &[]));
    }
    let students = students(dir).map_err(|e| Failure::Input(format!("{}: {e}", dir.display())))?;
    if image_of_any_stage(dir, ON_DISK).is_none() {
        if !any_stage_image_among(&students, ON_DISK) {
            return Err(refused(dir, language, "check-no-stage-command", &[]));
        }
        return grade_class(args, dir, &students);
    }
    let grades = grade_folder(dir, ON_DISK, |stage, path| check_image(args, stage, path))?;
    for line in folder_lines(&grades, language) {
        println!("{line}");
    }
    write_sheet(args, dir, &folder_sheet(&grades, language))?;
    finish(grades.iter().all(|(_, grade)| grade.passes()))
}

/// Grades every student's folder of the class in `dir`: a line per student on the
/// terminal, and the class's grading sheet.
fn grade_class(args: &CheckArgs, dir: &Path, students: &[PathBuf]) -> Result<(), Failure> {
    let mut class = vec![];
    for folder in students {
        let name = folder.file_name().unwrap_or_default().to_string_lossy();
        let grades = grade_folder(folder, ON_DISK, |stage, path| {
            check_image(args, stage, path)
        })?;
        println!("{}", student_line(&name, &grades));
        class.push((name.into_owned(), grades));
    }
    write_sheet(args, dir, &class_sheet(&class, args.language()))?;
    finish(
        class
            .iter()
            .flat_map(|(_, g)| g)
            .all(|(_, grade)| grade.passes()),
    )
}

/// The grade of the image at `path` of `stage`: unreadable, or checked.
fn check_image(args: &CheckArgs, stage: &Stage, path: &Path) -> Result<Grade, Failure> {
    match read_image(path, args.language()) {
        Err(failure) => Ok(Grade::Unreadable(failure.to_string())),
        Ok(image) => Ok(Grade::Checked(Box::new(check_one(
            args, stage, &image, path,
        )?))),
    }
}

/// Writes the grading sheet `csv` (`--csv`, or `grades.csv` in `dir`) and says where.
fn write_sheet(args: &CheckArgs, dir: &Path, csv: &str) -> Result<(), Failure> {
    let sheet = args.csv.clone().unwrap_or_else(|| dir.join("grades.csv"));
    write(&sheet, csv.as_bytes())?;
    let path = sheet.display().to_string().into();
    println!(
        "{}",
        say(args.language(), "check-sheet-written", &[("path", path)])
    );
    Ok(())
}

/// Success when every image passed; exit code 1 otherwise.
fn finish(all_pass: bool) -> Result<(), Failure> {
    if all_pass {
        Ok(())
    } else {
        Err(Failure::Differs)
    }
}
