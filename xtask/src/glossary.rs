//! `{{#sorted}}` ... `{{#sorted-end}}`: the paragraphs between the two lines, each
//! a glossary entry that opens with its term in bold, put in the alphabetical order
//! of their terms. The English glossary is written in order; a translated one keeps
//! the English order of its messages, and is sorted here by its own terms.

/// `content` with the paragraphs of each sorted block in the order of their terms
/// ([`order_key`]); the directive lines removed.
pub fn sorted(content: &str) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = content;
    while let Some(start) = rest.find("{{#sorted}}") {
        let end = rest[start..]
            .find("{{#sorted-end}}")
            .ok_or("a {{#sorted}} block is not closed by {{#sorted-end}}")?;
        out += &rest[..start];
        let block = &rest[start + "{{#sorted}}".len()..start + end];
        let mut entries: Vec<&str> = block
            .split("\n\n")
            .map(str::trim)
            .filter(|p| !p.is_empty())
            .collect();
        entries.sort_by_cached_key(|entry| order_key(entry));
        out += &entries.join("\n\n");
        rest = &rest[start + end + "{{#sorted-end}}".len()..];
    }
    Ok(out + rest)
}

/// The key an entry is sorted by: its bold term, in lower case, its accents and
/// ligatures folded (`É` as `e`, `œ` as `oe`) and everything but letters and digits
/// left out, as a dictionary orders words.
fn order_key(entry: &str) -> String {
    let term = entry
        .strip_prefix("**")
        .and_then(|rest| rest.split("**").next())
        .unwrap_or(entry);
    term.to_lowercase()
        .chars()
        .map(|c| match c {
            'à' | 'â' | 'ä' => "a".to_owned(),
            'ç' => "c".to_owned(),
            'é' | 'è' | 'ê' | 'ë' => "e".to_owned(),
            'î' | 'ï' => "i".to_owned(),
            'ô' | 'ö' => "o".to_owned(),
            'ù' | 'û' | 'ü' => "u".to_owned(),
            'œ' => "oe".to_owned(),
            'æ' => "ae".to_owned(),
            c if c.is_alphanumeric() => c.to_string(),
            _ => String::new(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Entries are ordered by their terms, accents and case aside, and the text
    /// around the block is kept.
    #[test]
    fn entries_are_put_in_the_order_of_their_terms() {
        let text = "# Glossaire\n\n{{#sorted}}\n\n**Rebond.** Un.\n\n**Écart type** (`$\\sigma$`). Deux,\nsur deux lignes.\n\n**Albédo.** Trois.\n\n{{#sorted-end}}\n\nFin.\n";
        assert_eq!(
            sorted(text).unwrap(),
            "# Glossaire\n\n**Albédo.** Trois.\n\n**Écart type** (`$\\sigma$`). Deux,\nsur deux lignes.\n\n**Rebond.** Un.\n\nFin.\n"
        );
    }

    #[test]
    fn a_block_left_open_is_an_error() {
        assert!(sorted("{{#sorted}}\n**A.** a\n").is_err());
    }
}
