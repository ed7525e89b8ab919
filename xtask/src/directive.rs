//! The book's own directives, `{{#NAME ARGUMENTS}}`, found in a chapter's text and
//! replaced by what the preprocessor makes of them.

/// `content` with each `{{#NAME ARGUMENTS}}` replaced by `fill(ARGUMENTS)`, the
/// arguments trimmed; an error if a directive is not closed by `}}`, or if `fill`
/// fails.
pub fn replace(
    content: &str,
    name: &str,
    mut fill: impl FnMut(&str) -> Result<String, String>,
) -> Result<String, String> {
    let opening = format!("{{{{#{name} ");
    let mut out = String::new();
    let mut rest = content;
    while let Some(start) = rest.find(&opening) {
        let end = rest[start..]
            .find("}}")
            .ok_or_else(|| format!("a {opening}...}}}} is not closed"))?;
        out += &rest[..start];
        out += &fill(rest[start + opening.len()..start + end].trim())?;
        rest = &rest[start + end + 2..];
    }
    Ok(out + rest)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each directive of the name is replaced, others and the text around are kept,
    /// and one left open is an error.
    #[test]
    fn directives_of_one_name_are_replaced() {
        let text = "a {{#twice x}} b {{#other y}} c {{#twice  z }}";
        let out = replace(text, "twice", |arg| Ok(arg.repeat(2)));
        assert_eq!(out.unwrap(), "a xx b {{#other y}} c zz");
        assert!(replace("{{#twice x", "twice", |a| Ok(a.into())).is_err());
    }
}
