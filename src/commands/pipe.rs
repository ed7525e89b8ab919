//! A reader that closes the standard output early (`raycourse list | head -1`) ends
//! the command quietly, as a filter of a pipeline should, rather than with Rust's
//! panic "failed printing to stdout: Broken pipe".

use std::any::Any;
use std::panic::{self, AssertUnwindSafe};

/// Runs `command`: `None`, with nothing printed, if it wrote to a standard output
/// that its reader had closed; any other panic goes on as it would have.
pub fn quiet_when_closed<T>(command: impl FnOnce() -> T) -> Option<T> {
    let default = panic::take_hook();
    panic::set_hook(Box::new(move |info| {
        if !message(info.payload()).is_some_and(closed) {
            default(info)
        }
    }));
    match panic::catch_unwind(AssertUnwindSafe(command)) {
        Ok(value) => Some(value),
        Err(payload) if message(&*payload).is_some_and(closed) => None,
        Err(payload) => panic::resume_unwind(payload),
    }
}

/// The text of a panic's payload, if it has one.
fn message(payload: &(dyn Any + Send)) -> Option<&str> {
    payload
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| payload.downcast_ref::<&str>().copied())
}

/// Whether a panic's message is the standard library's for a closed standard output.
fn closed(message: &str) -> bool {
    message.starts_with("failed printing to stdout") && message.contains("Broken pipe")
}
