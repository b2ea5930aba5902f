//! Writing a description back with some links' `<inertial>` replaced, changing nothing else:
//! each new element takes the old one's bytes (or, where a link had none, goes in as its first
//! child), indented as its neighbours; every other byte of the file is kept.

use crate::model::Robot;

/// A link's new `<inertial>` (and whatever comment goes with it), as text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Replacement {
    /// The link, an index into [`Robot::links`].
    pub link: usize,
    /// The element's text, lines separated by `\n`, not indented.
    pub text: String,
}

/// Why a fix cannot be written.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FixError {
    /// The link is written in a file that the description includes.
    #[error(
        "link \"{link}\" is written in {file}, which the description includes; audit that file \
         on its own or copy the body into the model"
    )]
    InIncludedFile {
        /// The link's name.
        link: String,
        /// The included file.
        file: String,
    },
    /// The link's start tag does not end (the reader would have refused such a file).
    #[error("link \"{link}\": its start tag has no end")]
    Unterminated {
        /// The link's name.
        link: String,
    },
}

/// The description's main file with `replacements` made.
pub fn splice(robot: &Robot, replacements: &[Replacement]) -> Result<String, FixError> {
    let text = &robot.sources[0].text;
    let mut edits: Vec<(std::ops::Range<usize>, String)> = Vec::new();
    for r in replacements {
        let link = &robot.links[r.link];
        let in_file = |file: usize| {
            if file == 0 {
                Ok(())
            } else {
                Err(FixError::InIncludedFile {
                    link: link.name.clone(),
                    file: robot.sources[file].path.display().to_string(),
                })
            }
        };
        // The element to replace: the stated inertial, or one that lacks its mass or inertia.
        let old = link
            .stated
            .as_ref()
            .map(|s| &s.span)
            .or(link.incomplete_inertial.as_ref().map(|i| &i.span));
        match old {
            Some(span) => {
                in_file(span.file)?;
                let range = span.range.clone();
                let indent = indentation(text, range.start);
                edits.push((range, indented(r.text.trim_end(), &indent)));
            }
            None => {
                in_file(link.element.file)?;
                let start = link.element.range.start;
                let end = start_tag_end(text, start).ok_or_else(|| FixError::Unterminated {
                    link: link.name.clone(),
                })?;
                let indent = indentation(text, start);
                let child = format!("{indent}  ");
                let body = indented(r.text.trim_end(), &child);
                if text[..end].ends_with("/>") {
                    let tag = element_name(&text[start..]);
                    edits.push((end - 2..end, format!(">\n{child}{body}\n{indent}</{tag}>")));
                } else {
                    edits.push((end..end, format!("\n{child}{body}")));
                }
            }
        }
    }
    edits.sort_by_key(|(range, _)| std::cmp::Reverse(range.start));
    let mut out = text.clone();
    for (range, new) in edits {
        out.replace_range(range, &new);
    }
    Ok(out)
}

/// The white space before `at` on its line (what an element there is indented by).
fn indentation(text: &str, at: usize) -> String {
    let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    text[line_start..at]
        .chars()
        .take_while(|c| c.is_whitespace())
        .collect()
}

/// `text` with every line after the first indented by `indent`.
fn indented(text: &str, indent: &str) -> String {
    text.lines()
        .enumerate()
        .map(|(i, l)| {
            if i == 0 || l.is_empty() {
                l.to_owned()
            } else {
                format!("{indent}{l}")
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The byte after the `>` that ends the start tag beginning at `start`.
fn start_tag_end(text: &str, start: usize) -> Option<usize> {
    let mut quote: Option<u8> = None;
    for (i, &b) in text.as_bytes()[start..].iter().enumerate() {
        match (quote, b) {
            (Some(q), _) if b == q => quote = None,
            (Some(_), _) => {}
            (None, b'"' | b'\'') => quote = Some(b),
            (None, b'>') => return Some(start + i + 1),
            _ => {}
        }
    }
    None
}

/// The element name at the start of `tag` (`<link name=…` → `link`).
fn element_name(tag: &str) -> &str {
    let rest = tag.trim_start_matches('<');
    let end = rest
        .find(|c: char| c.is_whitespace() || c == '/' || c == '>')
        .unwrap_or(rest.len());
    &rest[..end]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn start_tags_end_outside_quotes() {
        let t = r#"<link name="a>b" x='>'>"#;
        assert_eq!(start_tag_end(t, 0), Some(t.len()));
        assert_eq!(element_name("<body name='x'/>"), "body");
        assert_eq!(indentation("a\n    <x/>", 6), "    ");
    }
}
