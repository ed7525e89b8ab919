//! `raycourse check --all` in a page: a teacher gives the check page a class folder
//! (a folder of students' folders, each holding images named after their stages) or
//! one student's folder, and gets the command's verdicts and its grading sheet, to
//! the byte. Each stage's reference is rendered once, at each size the students'
//! images have, and kept in memory for the whole class. Nothing leaves the page.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use raycourse::Stage;
use raycourse::check::expected::Source;
use raycourse::check::grading::{
    Grade, any_stage_image_among, class_sheet, decode, folder_lines, folder_sheet, grade_folder,
    image_of_any_stage, lossy, student_line, students_among,
};
use raycourse::check::report::check;
use raycourse::messages::language::Language;
use raycourse::render::cache::InMemory;
use wasm_bindgen::prelude::*;

use crate::assets;

/// A class, or one student's folder, being graded: the files given, by the path
/// relative to the folder chosen (`class/alice/glass.png`, as the command names
/// them when run beside the folder), the references rendered so far, and the
/// grades given so far.
#[wasm_bindgen]
pub struct Class {
    files: BTreeMap<PathBuf, Vec<u8>>,
    language: Language,
    references: InMemory,
    graded: Vec<(String, Vec<(&'static Stage, Grade)>)>,
    folders: Option<Vec<PathBuf>>,
    /// Told how many rows of the reference being rendered are done.
    progress: fn(u64),
}

#[wasm_bindgen]
impl Class {
    /// An empty class, graded in `language` (`en` or `fr`), telling the worker's
    /// `raycourseProgress(rows)` the rows of each reference as it renders.
    #[wasm_bindgen(constructor)]
    pub fn new(language: &str) -> Class {
        Class::telling(language, |rows| {
            crate::checking::report_progress(rows as f64)
        })
    }

    /// Adds the file at `path` (relative to the folder chosen, `/` between names).
    pub fn add(&mut self, path: &str, bytes: Vec<u8>) {
        self.files.insert(PathBuf::from(path), bytes);
        self.folders = None;
    }

    /// How many folders there are to grade: the students' (a class), or 1 (a
    /// student's own folder).
    pub fn folders(&mut self) -> usize {
        self.layout().len()
    }

    /// Whether the files are one student's folder rather than a class.
    #[wasm_bindgen(js_name = isOneFolder)]
    pub fn is_one_folder(&self) -> bool {
        image_of_any_stage(&self.root(), &|p| self.files.contains_key(p)).is_some()
    }

    /// Grades the next folder and returns its lines, as the command prints them;
    /// `None` once every folder is graded. `raycourseProgress(rows)` is told the
    /// rows of each reference as it renders.
    #[wasm_bindgen(js_name = gradeNext)]
    pub fn grade_next(&mut self) -> Result<Option<String>, JsError> {
        let next = self.graded.len();
        let Some(folder) = self.layout().get(next).cloned() else {
            return Ok(None);
        };
        let grades = grade_folder(&folder, &|p| self.files.contains_key(p), |stage, path| {
            self.grade(stage, path)
        })
        .map_err(|e| JsError::new(&e))?;
        let name = folder.file_name().unwrap_or_default().to_string_lossy();
        let lines = match self.is_one_folder() {
            true => folder_lines(&grades, self.language).join("\n"),
            false => student_line(&name, &grades),
        };
        self.graded.push((name.into_owned(), grades));
        Ok(Some(lines))
    }

    /// The grading sheet, as `check --all` writes it to `grades.csv`.
    pub fn sheet(&self) -> String {
        match (self.is_one_folder(), self.graded.first()) {
            (true, Some((_, grades))) => folder_sheet(grades, self.language),
            _ => class_sheet(&self.graded, self.language),
        }
    }

    /// Whether every image graded matches its stage (or is missing).
    pub fn passes(&self) -> bool {
        self.graded
            .iter()
            .flat_map(|(_, grades)| grades)
            .all(|(_, grade)| grade.passes())
    }
}

impl Class {
    /// An empty class, graded in `language`, telling `progress` the rows of each
    /// reference as it renders.
    pub fn telling(language: &str, progress: fn(u64)) -> Class {
        Class {
            files: BTreeMap::new(),
            language: Language::from_locale(language),
            references: InMemory::default(),
            graded: vec![],
            folders: None,
            progress,
        }
    }

    /// The folder chosen: the first name that every file's path shares, if they all
    /// share one (a folder chosen whole), else none (files chosen one by one).
    fn root(&self) -> PathBuf {
        let first = |p: &PathBuf| p.components().next().map(|c| c.as_os_str().to_owned());
        let mut firsts = self
            .files
            .keys()
            .filter(|p| p.components().count() > 1)
            .map(first);
        match firsts.next() {
            Some(Some(name)) if self.files.keys().all(|p| first(p).as_ref() == Some(&name)) => {
                PathBuf::from(name)
            }
            _ => PathBuf::new(),
        }
    }

    /// The folders to grade: the chosen one if it holds a stage's image, else the
    /// students' folders inside it, none if no student's folder holds one either
    /// (as `check --all` refuses such a folder).
    fn layout(&mut self) -> &Vec<PathBuf> {
        if self.folders.is_none() {
            let root = self.root();
            let folders = if self.is_one_folder() {
                vec![root.clone()]
            } else {
                let inside = self.files.keys().filter_map(|p| {
                    let rest = p.strip_prefix(&root).ok()?;
                    let first = rest.iter().next()?;
                    (rest.components().count() > 1).then(|| root.join(first))
                });
                let students = students_among(inside.collect::<Vec<_>>());
                let exists = |p: &Path| self.files.contains_key(p);
                if any_stage_image_among(&students, &exists) {
                    students
                } else {
                    vec![]
                }
            };
            self.folders = Some(folders);
        }
        self.folders.as_ref().expect("just laid out")
    }

    /// The grade of the image at `path` of `stage`: unreadable, or checked against
    /// the stage's reference, rendered once per size for the whole class.
    fn grade(&self, stage: &'static Stage, path: &Path) -> Result<Grade, String> {
        let bytes = &self.files[path];
        let image = match decode(path, bytes, self.language) {
            Ok(image) => image,
            Err(why) => return Ok(Grade::Unreadable(why)),
        };
        let rows = AtomicU64::new(0);
        let progress = |_| (self.progress)(rows.fetch_add(1, Ordering::Relaxed) + 1);
        let source = Source {
            stage,
            size: image.dimensions(),
            cache: &self.references,
            files: assets::stage_files(),
            progress: &progress,
            renderer: &raycourse::engines::Fast,
        };
        let report = check(&source, &image, lossy(path)).map_err(|e| e.to_string())?;
        Ok(Grade::Checked(Box::new(report)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::command_line::command_line_render;
    use raycourse::maths::Real;
    use raycourse::render::png::encode_rgb8;

    /// The stage `name`'s image at `size` x `size` as a PNG file, displayed with
    /// `gamma` (the stage's own where `None`).
    fn png(name: &str, size: u32, gamma: Option<Real>) -> Vec<u8> {
        encode_rgb8(&command_line_render(name, size, gamma), size, size)
    }

    /// Every folder of `class` graded, with the lines each gave.
    fn graded(class: &mut Class) -> Vec<String> {
        std::iter::from_fn(|| class.grade_next().ok().flatten()).collect()
    }

    #[test]
    fn a_class_is_graded_student_by_student_with_one_reference_per_stage_and_size() {
        let mut class = Class::telling("en", |_| {});
        class.add("class/alice/glass.png", png("glass", 24, None));
        class.add("class/alice/white-disk.png", png("white-disk", 24, None));
        class.add("class/bob/glass.png", png("glass", 24, Some(1.0)));
        class.add("class/bob/white-disk.png", png("white-disk", 24, None));
        class.add("class/carol/white-disk.png", b"not a picture".to_vec());
        class.add("class/reference/0123.ref", vec![0]);
        class.add("class/notes.txt", b"a teacher's notes".to_vec());
        assert!(!class.is_one_folder());
        assert_eq!(class.folders(), 3);
        let lines = graded(&mut class);
        assert_eq!(lines.len(), 3, "{lines:?}");
        assert!(
            lines[0].starts_with("alice") && lines[0].ends_with("differ: none"),
            "{lines:?}"
        );
        assert!(
            lines[1].starts_with("bob") && lines[1].ends_with("differ: glass"),
            "{lines:?}"
        );
        assert!(lines[2].ends_with("differ: white-disk"), "{lines:?}");
        assert!(!class.passes());
        let sheet = class.sheet();
        let rows: Vec<&str> = sheet.lines().collect();
        assert!(rows[0].starts_with("student,"), "{sheet}");
        assert!(
            rows[1].starts_with("alice,") && rows[2].starts_with("bob,"),
            "{sheet}"
        );
        assert!(
            rows[3].contains("class/carol/white-disk.png: not a PNG, JPEG or PPM image"),
            "{sheet}"
        );
        // The references of glass and white-disk at 24 x 24 (and of the mistakes the
        // checker tries on bob's glass) are rendered once: dave's glass finds them.
        let rendered = class.references.len();
        assert!(rendered >= 2, "{rendered} references");
        class.add("class/dave/glass.png", png("glass", 24, None));
        graded(&mut class);
        assert_eq!(
            class.references.len(),
            rendered,
            "dave's glass rendered again"
        );
    }

    #[test]
    fn one_student_s_folder_is_graded_stage_by_stage_as_the_command_does() {
        let mut class = Class::telling("en", |_| {});
        class.add("glass.png", png("glass", 24, Some(1.0)));
        assert!(class.is_one_folder());
        assert_eq!(class.folders(), 1);
        let lines = graded(&mut class);
        assert!(lines[0].starts_with("stage"), "{lines:?}");
        assert!(
            lines[0].contains("\nglass             differs"),
            "{lines:?}"
        );
        let sheet = class.sheet();
        assert!(
            sheet.starts_with("stage,session,figure,verdict,"),
            "{sheet}"
        );
        assert!(sheet.contains("\nglass,2,"), "{sheet}");
    }

    #[test]
    fn a_class_whose_folders_hold_no_stage_s_image_has_nothing_to_grade() {
        let mut class = Class::telling("en", |_| {});
        class.add("class/alice/notes.png", b"not a picture".to_vec());
        class.add("class/bob/glass-old.png", png("glass", 24, None));
        assert!(!class.is_one_folder());
        assert_eq!(class.folders(), 0);
        class.add("class/carol/glass.png", png("glass", 24, None));
        assert_eq!(
            class.folders(),
            3,
            "a class with one stage's image grades all"
        );
    }
}
