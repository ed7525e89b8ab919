//! Running the checklist: each line `name ... ok` or `FAILED` with the reason, an
//! exercise whose check stops at an earlier exercise's stub told so, and a closing
//! line that says how far the session is.

use std::collections::HashMap;
use std::panic::{self, AssertUnwindSafe};
use std::process::ExitCode;
use std::sync::Mutex;

use raycourse::stages;

use crate::images;
use crate::isolation;
use crate::known::Outcome;
use crate::marker::{MarkerLine, parse_marker};
use crate::say;
use crate::words::{message, text};

/// One exercise, as the checklist runs it.
pub struct Exercise {
    /// Its number, such as `s1.2`: the marker in the doc comment of its function
    /// gives the same number, what it computes and the book's section.
    pub id: &'static str,
    /// Its line in the checklist: the number and the function, such as
    /// `s1_2_sphere_intersect`.
    pub name: &'static str,
    /// The stage whose image first shows it: when that stage, or a later one of the
    /// session, differs while every known answer passes, the checklist names it.
    pub shown_by: &'static str,
    /// The exercises of its session whose functions its check calls besides its own.
    pub needs: &'static [&'static str],
    /// The check: known answers.
    pub check: fn() -> Outcome,
}

/// A line's verdict.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    Passed,
    /// Wrong, with what went wrong.
    Failed(String),
    /// Stopped at the stub of this exercise (its own or an earlier one).
    Stub(String),
}

/// Runs the exercises of `sessions` and their stages' images whose names contain
/// one of `filters` (all when there is none); success when every line passed.
pub fn run(sessions: &[&[Exercise]], filters: &[&str]) -> ExitCode {
    let markers = markers();
    let unmarked = unmarked(sessions, &markers);
    let markers = in_language(markers, sessions);
    let chosen = |name: &str| filters.is_empty() || filters.iter().any(|f| name.contains(f));
    // Every exercise's known answers first: a later session's code renders the
    // earlier sessions' stages too, so a stage's line must know whether an exercise
    // further down fails before it blames those above it.
    let all: HashMap<&str, Verdict> = sessions
        .iter()
        .flat_map(|exercises| exercises.iter())
        .filter(|e| chosen(e.name))
        .map(|e| (e.id, isolation::verdict_of(e.name)))
        .collect();
    let mut verdicts: HashMap<&str, Verdict> = HashMap::new();
    let (mut passed, mut failed) = (0, 0);
    let current = sessions.len() as u32;
    let mut next: Option<String> = None;
    let mut stage_next: Option<String> = None;
    let mut done = 0;
    for (index, exercises) in sessions.iter().enumerate() {
        let session = index as u32 + 1;
        for exercise in exercises.iter().filter(|e| chosen(e.name)) {
            let verdict = all[exercise.id].clone();
            let ok = verdict == Verdict::Passed;
            report(exercise.name, &verdict, Some(exercise), &markers, &verdicts);
            if session == current {
                if ok {
                    done += 1;
                } else if next.is_none() {
                    next = Some(describe(exercise.id, &markers));
                }
            }
            if ok {
                passed += 1
            } else {
                failed += 1
            }
            verdicts.insert(exercise.id, verdict);
        }
        let below = failing_below(&all, &verdicts);
        let (stages_passed, stages_failed, differing) =
            check_stages(session, exercises, &chosen, &markers, (&verdicts, &below));
        (passed, failed) = (passed + stages_passed, failed + stages_failed);
        if session == current {
            stage_next = stage_next.or(differing);
        }
    }
    let (mistakes_passed, mistakes_failed) = check_mistakes(sessions.len() as u32, &chosen);
    (passed, failed) = (passed + mistakes_passed, failed + mistakes_failed);
    if !unmarked.is_empty() {
        println!("markers ... FAILED\n    {unmarked}");
        failed += 1;
    }
    println!(
        "\n{}",
        say!(
            "checklist-checklist-passed-failed",
            passed = passed,
            failed = failed
        )
    );
    let last = sessions.last().copied().unwrap_or_default();
    let chosen_here = last.iter().filter(|e| chosen(e.name)).count();
    let progress = Progress {
        session: current,
        total: last.len(),
        chosen: (!filters.is_empty()).then_some(chosen_here),
        done,
    };
    progress.print(next.or(stage_next));
    if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(101)
    }
}

/// The exercises of `all` further down than those in `so_far` whose known answers
/// fail (not those still `todo!()`, which a stage would have stopped at), in the
/// course's order.
fn failing_below<'a>(
    all: &HashMap<&'a str, Verdict>,
    so_far: &HashMap<&str, Verdict>,
) -> Vec<&'a str> {
    let mut below: Vec<&str> = all
        .iter()
        .filter(|(id, v)| !so_far.contains_key(*id) && matches!(v, Verdict::Failed(_)))
        .map(|(id, _)| *id)
        .collect();
    below.sort_by_key(|id| order(id));
    below
}

/// Renders each stage of `session` that `chosen` keeps and compares it with its
/// reference, printing its line: how many passed and failed, and the first that
/// differs although every exercise passes (what to do next), with the exercises of
/// the session, `exercises`, that its image relies on. `verdicts` holds those of
/// the exercises so far, and `below` those further down that fail: a stage that
/// differs names them rather than blame the exercises so far.
fn check_stages(
    session: u32,
    exercises: &[Exercise],
    chosen: &dyn Fn(&str) -> bool,
    markers: &HashMap<String, MarkerLine>,
    (verdicts, below): (&HashMap<&str, Verdict>, &[&str]),
) -> (u32, u32, Option<String>) {
    let (mut passed, mut failed, mut differing) = (0, 0, None);
    let mut shown: Vec<&str> = vec![];
    for stage in stages().filter(|s| s.session == session) {
        shown.push(stage.name);
        let name = images::check_name(stage);
        if !chosen(&name) {
            continue;
        }
        let verdict = isolation::verdict_of(&name);
        report(&name, &verdict, None, markers, verdicts);
        if verdict == Verdict::Passed {
            passed += 1;
            continue;
        }
        failed += 1;
        if matches!(verdict, Verdict::Failed(_)) && !below.is_empty() {
            for id in below {
                let exercise = describe(id, markers);
                println!(
                    "    {}",
                    say!(
                        "checklist-exercise-further-down-fails-its-known",
                        exercise = exercise
                    )
                );
            }
            continue;
        }
        let used = used_by(exercises, &shown);
        if let Some(look) = look_again(&verdict, verdicts, &used, markers) {
            println!("    {look}");
            let name = stage.name;
            differing = differing.or(Some(say!("checklist-the-stage", name = name, look = look)));
        }
    }
    (passed, failed, differing)
}

/// The exercises of `exercises` whose stage is one of `shown` (the session's stages
/// so far): those a stage's image relies on.
fn used_by(exercises: &[Exercise], shown: &[&str]) -> Vec<&'static str> {
    exercises
        .iter()
        .filter(|e| shown.contains(&e.shown_by))
        .map(|e| e.id)
        .collect()
}

/// For a stage that differs while every exercise so far passes its known answers
/// (their tests cannot see everything an image needs): the exercises to look at
/// again. `None` when an exercise fails, a stub stopped the stage, or the stage's
/// failure was traced to the call that differs, which its line already names.
fn look_again(
    verdict: &Verdict,
    earlier: &HashMap<&str, Verdict>,
    used: &[&str],
    markers: &HashMap<String, MarkerLine>,
) -> Option<String> {
    let all_pass = earlier.values().all(|v| *v == Verdict::Passed);
    let Verdict::Failed(why) = verdict else {
        return None;
    };
    if !all_pass || used.is_empty() || crate::trace::names_the_call(why) {
        return None;
    }
    let names: Vec<String> = used.iter().map(|id| describe(id, markers)).collect();
    let exercises = names.join(&say!("checklist-exercise-separator"));
    Some(say!("checklist-look-again", exercises = exercises))
}

/// Where the last session stands, for the closing line.
struct Progress {
    session: u32,
    /// Its exercises.
    total: usize,
    /// How many of them a name filter chose, if the checklist was given one.
    chosen: Option<usize>,
    /// How many of those checked pass.
    done: usize,
}

impl Progress {
    /// The closing line: how many of the last session's exercises pass, and which is
    /// next (an exercise, or a stage that differs although its exercises pass). With
    /// a name filter it counts only the exercises chosen, and says so: the others
    /// were not checked, so the session is not called done.
    fn print(&self, next: Option<String>) {
        let Progress {
            session,
            total,
            done,
            ..
        } = *self;
        let line = match (self.chosen, next) {
            (Some(chosen), next) => {
                let next = next
                    .map(|next| say!("checklist-next", next = next))
                    .unwrap_or_default();
                say!(
                    "checklist-progress-session-exercises-the-name-filter",
                    session = session,
                    chosen = chosen,
                    total = total,
                    done = done,
                    next = next
                )
            }
            (None, Some(next)) => say!(
                "checklist-progress-session-of-exercises-done-next",
                session = session,
                done = done,
                total = total,
                next = next
            ),
            (None, None) => say!(
                "checklist-progress-session-all-exercises-done",
                session = session,
                total = total
            ),
        };
        println!("{line}");
    }
}

/// Runs the line `name` alone, in this process, and prints its verdict for
/// [`isolation::verdict_of`], which started the process.
pub fn run_line(sessions: &[&[Exercise]], name: &str) -> ExitCode {
    quiet_panics();
    let exercise = sessions
        .iter()
        .flat_map(|s| s.iter())
        .find(|e| e.name == name);
    let verdict = match exercise {
        Some(exercise) => caught(exercise.check),
        None => match stages().find(|s| images::check_name(s) == name) {
            Some(stage) => caught(|| images::check(stage)),
            None => match mistakes_verdict(name) {
                Some(verdict) => verdict,
                None => return ExitCode::from(2),
            },
        },
    };
    println!("{}", isolation::encode(&verdict));
    ExitCode::SUCCESS
}

/// The session of a line `mistakes_sN`.
#[cfg(not(course_answers))]
fn mistakes_session(name: &str) -> Option<u32> {
    name.strip_prefix("mistakes_s")?.parse().ok()
}

/// The verdict of the line `mistakes_sN`, if `name` is one.
#[cfg(not(course_answers))]
fn mistakes_verdict(name: &str) -> Option<Verdict> {
    let session = mistakes_session(name)?;
    Some(caught(|| crate::mistakes::check_session(session)))
}

/// An exercise crate has no line `mistakes_sN`.
#[cfg(course_answers)]
fn mistakes_verdict(_: &str) -> Option<Verdict> {
    None
}

/// In the course's crate (not in a student's, whose course is a crate of its own):
/// the lines `mistakes_sN`, one for each of the `sessions` that `chosen` keeps,
/// which prove that each catalogued mistake fails its generated check and names its
/// rule. How many passed and failed.
#[cfg(not(course_answers))]
fn check_mistakes(sessions: u32, chosen: &dyn Fn(&str) -> bool) -> (u32, u32) {
    let (mut passed, mut failed) = (0, 0);
    let no_markers = HashMap::new();
    for session in 1..=sessions {
        let name = format!("mistakes_s{session}");
        if crate::mistakes::catalogue(session).is_empty() || !chosen(&name) {
            continue;
        }
        let verdict = isolation::verdict_of(&name);
        report(&name, &verdict, None, &no_markers, &HashMap::new());
        if verdict == Verdict::Passed {
            passed += 1
        } else {
            failed += 1
        }
    }
    (passed, failed)
}

/// An exercise crate runs no line `mistakes_sN`: none passed, none failed.
#[cfg(course_answers)]
fn check_mistakes(_: u32, _: &dyn Fn(&str) -> bool) -> (u32, u32) {
    (0, 0)
}

/// The verdict of `run`: a panic with a stub's message names the stub's exercise.
fn caught(run: impl FnOnce() -> Outcome) -> Verdict {
    match panic::catch_unwind(AssertUnwindSafe(run)) {
        Ok(Ok(())) => Verdict::Passed,
        Ok(Err(why)) => Verdict::Failed(why),
        Err(payload) => {
            let message = payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                .unwrap_or_default();
            let place = PANIC_PLACE.lock().map(|p| p.clone()).unwrap_or_default();
            match stub_of(&message) {
                Some(stub) => Verdict::Stub(stub.to_owned()),
                None => Verdict::Failed(crate::panics::explain(&message, &place)),
            }
        }
    }
}

/// The course's order of an exercise number: session, then number.
fn order(id: &str) -> (u32, u32) {
    let mut parts = id[1..].split('.').map(|p| p.parse().unwrap_or(0));
    (parts.next().unwrap_or(0), parts.next().unwrap_or(0))
}

/// The exercise whose stub panicked with `message`, if it was one.
fn stub_of(message: &str) -> Option<&str> {
    let rest = message.strip_prefix("not yet implemented: exercise ")?;
    rest.split(',').next()
}

/// Prints a line of the checklist and, for a failure, why.
fn report(
    name: &str,
    verdict: &Verdict,
    exercise: Option<&Exercise>,
    markers: &HashMap<String, MarkerLine>,
    earlier: &HashMap<&str, Verdict>,
) {
    let failed_line = || println!("{name} ... {}", say!("checklist-failed"));
    let why = match verdict {
        Verdict::Passed => {
            println!("{name} ... ok");
            return;
        }
        Verdict::Failed(why) => why,
        Verdict::Stub(stub) => {
            failed_line();
            let own = exercise.is_some_and(|e| e.id == stub);
            let stub = describe(stub, markers);
            if own {
                println!(
                    "    {}",
                    say!("checklist-exercise-still-todo-write-it", stub = stub)
                );
            } else {
                println!(
                    "    {}",
                    say!("checklist-needs-exercise-first-it-is-still", stub = stub)
                );
            }
            return;
        }
    };
    failed_line();
    match exercise {
        Some(e) => {
            let exercise = describe(e.id, markers);
            println!(
                "    {}",
                say!("checklist-exercise", exercise = exercise, why = why)
            )
        }
        None => println!("    {why}"),
    }
    if exercise.is_none() {
        let mut failing: Vec<&&str> = earlier
            .iter()
            .filter(|(_, v)| **v != Verdict::Passed)
            .map(|(id, _)| id)
            .collect();
        failing.sort_by_key(|id| order(id));
        for id in failing {
            let exercise = describe(id, markers);
            println!(
                "    {}",
                say!(
                    "checklist-exercise-fails-the-image-needs-it",
                    exercise = exercise
                )
            );
        }
    }
    for need in exercise.map_or(&[][..], |e| e.needs) {
        if earlier.get(need).is_some_and(|v| *v != Verdict::Passed) {
            let need = describe(need, markers);
            println!(
                "    {}",
                say!("checklist-it-calls-exercise-which-fails-too", need = need)
            );
        }
    }
}

/// `s1.2, the ray-sphere distance (book session 1, "A white disk")`, or the number
/// alone where no marker names it (a function a later session replaced).
fn describe(id: &str, markers: &HashMap<String, MarkerLine>) -> String {
    match markers.get(id) {
        Some(m) => format!("{id}, {} ({})", m.title, m.book),
        None => id.to_owned(),
    }
}

/// The markers in the checklist's language: each exercise's title and book
/// section as the catalogue's `exercise-sN-K` gives them (in English, the marker's).
fn in_language(
    mut markers: HashMap<String, MarkerLine>,
    sessions: &[&[Exercise]],
) -> HashMap<String, MarkerLine> {
    for e in sessions.iter().flat_map(|s| s.iter()) {
        if let Some(marker) = markers.get_mut(e.id) {
            *marker = translated(marker);
        }
    }
    markers
}

/// A marker with its title and book section in the checklist's language.
pub fn translated(marker: &MarkerLine) -> MarkerLine {
    let id = format!("exercise-{}", marker.id.replace('.', "-"));
    let arguments = [
        ("title", text(&marker.title)),
        ("section", text(&marker.book)),
    ];
    MarkerLine {
        id: marker.id.clone(),
        title: message(&id, &arguments),
        book: message(&format!("{id}.section"), &arguments),
    }
}

/// Where the last panic happened: the checklist prints it beside the message.
static PANIC_PLACE: Mutex<String> = Mutex::new(String::new());

/// Panics print nothing by themselves: the checklist reports them on their line.
fn quiet_panics() {
    panic::set_hook(Box::new(|info| {
        if let (Ok(mut place), Some(at)) = (PANIC_PLACE.lock(), info.location()) {
            *place = format!("{}:{}", at.file(), at.line());
        }
    }));
}

/// The markers in the crate's sources, by exercise number, with the function each
/// marks (`Sphere::intersect`).
fn markers() -> HashMap<String, MarkerLine> {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    marker_lines(&folder)
        .into_iter()
        .map(|marker| (marker.id.clone(), marker))
        .collect()
}

/// Every marker line below `folder`.
fn marker_lines(folder: &std::path::Path) -> Vec<MarkerLine> {
    let mut found = vec![];
    for entry in std::fs::read_dir(folder).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.is_dir() {
            found.extend(marker_lines(&path));
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            found.extend(
                text.lines()
                    .filter_map(|line| parse_marker(line.trim().strip_prefix("///")?)),
            );
        }
    }
    found
}

/// What is wrong between the markers and the checklist: a marker without an
/// exercise here (a later session's marker aside: session 2's gamma is written in
/// session 2, on a function that exists from session 1), or an exercise named after
/// another number.
fn unmarked(sessions: &[&[Exercise]], markers: &HashMap<String, MarkerLine>) -> String {
    let mut wrong = vec![];
    let later = |id: &str| {
        let session: usize = id[1..]
            .split('.')
            .next()
            .and_then(|n| n.parse().ok())
            .unwrap_or(0);
        session > sessions.len()
    };
    for id in markers.keys().filter(|id| !later(id)) {
        if !sessions.iter().flat_map(|s| s.iter()).any(|e| e.id == id) {
            wrong.push(format!(
                "the marker of {id} has no exercise in the checklist"
            ));
        }
    }
    for e in sessions.iter().flat_map(|s| s.iter()) {
        if !e.name.starts_with(&format!("{}_", e.id.replace('.', "_"))) {
            wrong.push(format!(
                "{} is named after another exercise than {}",
                e.name, e.id
            ));
        }
    }
    wrong.sort();
    wrong.join("\n    ")
}
