//! What every book preprocessor of this crate shares: mdBook's input, read from
//! standard input as `[context, book]`.

use std::io::Read;

use serde_json::Value;

/// mdBook's context (the configuration, the renderer, the book's root) and the book.
pub fn read() -> Result<(Value, Value), String> {
    let mut input = String::new();
    std::io::stdin()
        .read_to_string(&mut input)
        .map_err(|e| e.to_string())?;
    let [context, book]: [Value; 2] =
        serde_json::from_str(&input).map_err(|e| format!("mdBook's input: {e}"))?;
    Ok((context, book))
}
