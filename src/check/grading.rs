//! Grading a student's folder of images, or a class of students' folders: a grade
//! for each stage of the build, and the grading sheet a teacher opens in a
//! spreadsheet. The folders are on disk for the command (`check --all`), or files
//! given to the book's check page; both find, read and grade the images alike.

use std::path::{Path, PathBuf};

use image::RgbImage;

use crate::check::report::{Report, Verdict};
use crate::messages::language::Language;
use crate::messages::say;
use crate::scene_file::{Stage, stages};

/// A stage's grade in a student's folder.
#[derive(Clone, Debug)]
pub enum Grade {
    /// No image of the stage in the folder: it does not count against the student.
    Missing,
    /// An image that cannot be read, and why.
    Unreadable(String),
    /// An image the checker compared with the stage's, and its report.
    Checked(Box<Report>),
}

impl Grade {
    /// Its word in the sheet: `missing`, `unreadable`, `matches` or `differs`.
    pub fn word(&self) -> &'static str {
        match self {
            Grade::Missing => "missing",
            Grade::Unreadable(_) => "unreadable",
            Grade::Checked(report) if report.verdict == Verdict::Matches => "matches",
            Grade::Checked(_) => "differs",
        }
    }

    /// Whether it does not count against the student: a matching image, or none.
    pub fn passes(&self) -> bool {
        matches!(self, Grade::Missing) || self.word() == "matches"
    }

    /// The hint: the likely mistake, named in `language`, or why the image cannot be
    /// read; empty when there is none.
    pub fn hint(&self, language: Language) -> String {
        match self {
            Grade::Missing => String::new(),
            Grade::Unreadable(why) => why.clone(),
            Grade::Checked(report) => report
                .hint
                .map_or(String::new(), |m| m.words(language)[0].clone()),
        }
    }

    /// The sheet's figures of a checked image: the share that differs, the
    /// brightness over the stage's per channel and the noise; empty cells otherwise.
    fn figures(&self) -> [String; 5] {
        let Grade::Checked(report) = self else {
            return Default::default();
        };
        let [r, g, b] = report.ratio.map(|c| format!("{c:.4}"));
        let noise = report
            .noise
            .map_or(String::new(), |(n, _)| format!("{n:.3}"));
        [format!("{:.4}", report.outcome.share()), r, g, b, noise]
    }
}

/// Which files there are: the disk's (`Path::exists`), or those given to a page.
pub type Exists<'a> = &'a dyn Fn(&Path) -> bool;

/// The files on disk.
pub const ON_DISK: Exists = &|path| path.exists();

/// The image of `stage` in `dir`: `glass.png`, `glass.jpg`, `glass.jpeg` or
/// `glass.ppm`, the first that `exists`.
pub fn image_of(dir: &Path, stage: &Stage, exists: Exists) -> Option<PathBuf> {
    ["png", "jpg", "jpeg", "ppm"]
        .iter()
        .map(|e| dir.join(format!("{}.{e}", stage.name)))
        .find(|p| exists(p))
}

/// The image of any stage of the build in `dir`, if there is one.
pub fn image_of_any_stage(dir: &Path, exists: Exists) -> Option<PathBuf> {
    stages().find_map(|stage| image_of(dir, stage, exists))
}

/// Whether any of the students' `folders` holds an image of a stage: a class
/// whose folders hold none has nothing to grade, and is refused.
pub fn any_stage_image_among(folders: &[PathBuf], exists: Exists) -> bool {
    folders
        .iter()
        .any(|f| image_of_any_stage(f, exists).is_some())
}

/// The image in `bytes`, the file `path`, read as its extension says (PNG, JPEG or
/// PPM), in 8-bit RGB; or why it cannot be read, naming the file, in `language`.
pub fn decode(path: &Path, bytes: &[u8], language: Language) -> Result<RgbImage, String> {
    let mut reader = image::ImageReader::new(std::io::Cursor::new(bytes));
    if let Ok(format) = image::ImageFormat::from_path(path) {
        reader.set_format(format);
    }
    let image = reader.decode().map_err(|e| {
        let error = e.to_string().into();
        let why = say(language, "check-unreadable", &[("error", error)]);
        format!("{}: {why}", path.display())
    })?;
    Ok(image.to_rgb8())
}

/// Whether the file `path` is a JPEG, whose compression blurs edges a little.
pub fn lossy(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("jpg") || e.eq_ignore_ascii_case("jpeg"))
}

/// The students' folders of a class folder, sorted by name (a `reference` folder
/// of cached references aside).
pub fn students(dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    let folders = std::fs::read_dir(dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir());
    Ok(students_among(folders))
}

/// The students' folders among `folders`, sorted by name, without duplicates and
/// without the `reference` folder of cached references.
pub fn students_among(folders: impl IntoIterator<Item = PathBuf>) -> Vec<PathBuf> {
    let mut folders: Vec<PathBuf> = folders
        .into_iter()
        .filter(|p| p.file_name().is_some_and(|n| n != "reference"))
        .collect();
    folders.sort();
    folders.dedup();
    folders
}

/// Each stage of the build with its grade in `dir`: [`Grade::Missing`] where the
/// folder has no image of it, otherwise what `grade` says of the image's path.
pub fn grade_folder<E>(
    dir: &Path,
    exists: Exists,
    mut grade: impl FnMut(&'static Stage, &Path) -> Result<Grade, E>,
) -> Result<Vec<(&'static Stage, Grade)>, E> {
    stages()
        .map(|stage| match image_of(dir, stage, exists) {
            None => Ok((stage, Grade::Missing)),
            Some(path) => grade(stage, &path).map(|g| (stage, g)),
        })
        .collect()
}

/// A student's line of a class's grading: how many stages match, and which differ
/// or cannot be read.
pub fn student_line(name: &str, grades: &[(&Stage, Grade)]) -> String {
    let matching = grades.iter().filter(|(_, g)| g.word() == "matches").count();
    let differing: Vec<&str> = grades
        .iter()
        .filter(|(_, g)| !g.passes())
        .map(|(s, _)| s.name)
        .collect();
    let differing = match differing.is_empty() {
        true => "none".to_owned(),
        false => differing.join(", "),
    };
    format!(
        "{name:<20} {matching:>2} of {} match; differ: {differing}",
        grades.len()
    )
}

/// The lines of a folder's grading: a header, then each stage's verdict and hint.
pub fn folder_lines(grades: &[(&Stage, Grade)], language: Language) -> Vec<String> {
    let mut lines = vec![format!("{:<17} {:<10} hint", "stage", "verdict")];
    for (stage, grade) in grades {
        lines.push(format!(
            "{:<17} {:<10} {}",
            stage.name,
            grade.word(),
            grade.hint(language)
        ));
    }
    lines
}

/// The grading sheet of one folder: a row per stage with its session, figure,
/// verdict, figures and hint. Its column names stay English in every language, as
/// its verdicts and its numbers do: the sheet is read by programs (a spreadsheet's
/// formulas, a teacher's script, the check page), which find a column by its name,
/// whatever the language of the report; only the hints, read by people, follow
/// `--lang`.
pub fn folder_sheet(grades: &[(&Stage, Grade)], language: Language) -> String {
    let mut csv =
        String::from("stage,session,figure,verdict,differing,red,green,blue,noise,hint\n");
    for (stage, grade) in grades {
        let figure = stage.figure.map_or(String::new(), |f| f.to_string());
        let mut cells = vec![stage.name.to_owned(), stage.session.to_string(), figure];
        cells.push(grade.word().to_owned());
        cells.extend(grade.figures());
        cells.push(grade.hint(language));
        csv += &row(&cells);
    }
    csv
}

/// The grading sheet of a class: a row per student (`class` holds each one's name
/// and grades), with each stage's verdict and hint. Its column names stay English,
/// as [`folder_sheet`]'s do, for the programs that read it.
pub fn class_sheet(class: &[(String, Vec<(&Stage, Grade)>)], language: Language) -> String {
    let mut header = vec!["student".to_owned()];
    for stage in stages() {
        header.extend([stage.name.to_owned(), format!("{} hint", stage.name)]);
    }
    let mut csv = row(&header);
    for (student, grades) in class {
        let mut cells = vec![student.clone()];
        for (_, grade) in grades {
            cells.extend([grade.word().to_owned(), grade.hint(language)]);
        }
        csv += &row(&cells);
    }
    csv
}

/// A line of CSV: the cells, each [`quoted`], separated by commas.
fn row(cells: &[String]) -> String {
    let cells: Vec<String> = cells.iter().map(|c| quoted(c)).collect();
    cells.join(",") + "\n"
}

/// A CSV field: in quotes when it holds a comma, a quote or a line break; and, when
/// it begins as a spreadsheet formula does (`=`, `+`, `-`, `@`, a tab or a carriage
/// return), after a `'`, so that a spreadsheet shows it as text rather than run it
/// (OWASP's advice against CSV injection): a student's folder may be named
/// `=HYPERLINK(...)`.
pub fn quoted(text: &str) -> String {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cell_is_quoted_where_it_must_be_and_a_formula_is_text() {
        assert_eq!(quoted("glass"), "glass");
        assert_eq!(quoted("a, b"), "\"a, b\"");
        assert_eq!(quoted("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(quoted("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
        assert_eq!(quoted("-1"), "'-1");
    }

    #[test]
    fn every_row_of_a_sheet_has_the_header_s_cells_whatever_its_hint() {
        let stage = stages().next().unwrap();
        let grades = [
            (stage, Grade::Missing),
            (
                stage,
                Grade::Unreadable("x.png: not an image, or a PNG, or a JPEG".into()),
            ),
        ];
        let sheet = folder_sheet(&grades, Language::English);
        let lines: Vec<&str> = sheet.lines().collect();
        assert_eq!(lines.len(), 3);
        assert_eq!(lines[1], format!("{},1,1,missing,,,,,,", stage.name));
        assert!(lines[2].ends_with(",\"x.png: not an image, or a PNG, or a JPEG\""));
        let class = [("=cmd".to_owned(), grades.to_vec())];
        let sheet = class_sheet(&class, Language::English);
        assert!(
            sheet
                .lines()
                .nth(1)
                .unwrap()
                .starts_with("'=cmd,missing,,unreadable,")
        );
        assert!(!grades[1].1.passes() && grades[0].1.passes());
    }
}
