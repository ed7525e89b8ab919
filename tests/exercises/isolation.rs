//! Each line of the checklist runs in a process of its own: this same program, asked
//! for that one line (`--line NAME`). Code that never ends, such as a recursion
//! that never reaches its last level, a hierarchy that never stops splitting, or a
//! loop that never stops, then fails its own line with a hint, and the checklist
//! goes on to the next.

use std::alloc::{GlobalAlloc, Layout, System};
use std::io::Read;
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use crate::checklist::Verdict;
use crate::say;

/// The argument that asks this program for one line.
pub const LINE: &str = "--line";

/// The most memory one line may use: far more than any right answer needs.
const MEMORY: usize = 2 << 30;

/// The longest one line may take: far longer than any right answer takes.
const TIME: Duration = Duration::from_secs(120);

/// The first line of a line's answer on its standard output; the verdict follows.
const ANSWER: &str = "checklist line verdict:";

/// The verdict of the checklist's line `name`, run in a process of its own.
pub fn verdict_of(name: &str) -> Verdict {
    let mut command = Command::new(std::env::current_exe().expect("the checklist's program"));
    let language = if crate::words::french() { "fr" } else { "en" };
    command.args([LINE, name, "--lang", language]);
    command.stdout(Stdio::piped()).stderr(Stdio::piped());
    let mut child = match command.spawn() {
        Ok(child) => child,
        Err(e) => return Verdict::Failed(format!("cannot start the check: {e}")),
    };
    // Read as the line runs, so that a line that prints much is not held up.
    let out = reader(child.stdout.take());
    let err = reader(child.stderr.take());
    let start = Instant::now();
    let finished = loop {
        match child.try_wait() {
            Ok(Some(_)) => break true,
            Ok(None) if start.elapsed() < TIME => std::thread::sleep(Duration::from_millis(5)),
            _ => break false,
        }
    };
    if !finished {
        let _ = child.kill();
        let _ = child.wait();
        let seconds = TIME.as_secs();
        return Verdict::Failed(say!("isolation-it-did-not-end-within-s", seconds = seconds));
    }
    let (out, err) = (
        out.join().unwrap_or_default(),
        err.join().unwrap_or_default(),
    );
    decode(&out).unwrap_or_else(|| Verdict::Failed(why_it_stopped(&err)))
}

/// A thread that reads all of `stream`, lossily as text.
fn reader(stream: Option<impl Read + Send + 'static>) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut bytes = vec![];
        if let Some(mut stream) = stream {
            let _ = stream.read_to_end(&mut bytes);
        }
        String::from_utf8_lossy(&bytes).into_owned()
    })
}

/// A line's verdict, as its process prints it for [`verdict_of`].
pub fn encode(verdict: &Verdict) -> String {
    match verdict {
        Verdict::Passed => format!("{ANSWER} passed"),
        Verdict::Stub(id) => format!("{ANSWER} stub {id}"),
        Verdict::Failed(why) => format!("{ANSWER} failed\n{why}"),
    }
}

/// The verdict in a line's output, if it printed one.
fn decode(out: &str) -> Option<Verdict> {
    let (_, answer) = out.split_once(ANSWER)?;
    let answer = answer.trim_start_matches(' ');
    if answer.starts_with("passed") {
        Some(Verdict::Passed)
    } else if let Some(id) = answer.strip_prefix("stub ") {
        Some(Verdict::Stub(id.trim().to_owned()))
    } else {
        let why = answer.strip_prefix("failed\n")?;
        Some(Verdict::Failed(why.trim_end_matches('\n').to_owned()))
    }
}

/// Why a line's process stopped without a verdict, from what it printed on its
/// standard error: a stack that overflowed, memory that ran out, or the last line.
fn why_it_stopped(err: &str) -> String {
    if err.contains("has overflowed its stack") {
        say!("isolation-it-never-ended-the-stack-overflowed")
    } else if err.contains("memory allocation of") {
        let gib = MEMORY >> 30;
        say!("isolation-it-asked-for-more-than-gib", gib = gib)
    } else {
        let last = err
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("");
        say!("isolation-it-stopped", last = last)
    }
}

/// The memory allocated so far, in bytes.
static ALLOCATED: AtomicUsize = AtomicUsize::new(0);

/// The system's allocator, refusing to hand out more than [`MEMORY`] in all: a line
/// whose code allocates for ever then ends with "memory allocation failed" rather
/// than take the machine's memory.
pub struct Capped;

// SAFETY: every call goes to the system's allocator with the caller's own layout and
// pointer; the count only decides whether to refuse (a null pointer, which
// `GlobalAlloc` allows) before the system is asked.
unsafe impl GlobalAlloc for Capped {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if ALLOCATED.fetch_add(layout.size(), Ordering::Relaxed) + layout.size() > MEMORY {
            ALLOCATED.fetch_sub(layout.size(), Ordering::Relaxed);
            return std::ptr::null_mut();
        }
        // SAFETY: the caller's layout, as `GlobalAlloc::alloc` requires.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        ALLOCATED.fetch_sub(layout.size(), Ordering::Relaxed);
        // SAFETY: `ptr` came from `alloc` above with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
}
