//! The XML of a description as a plain tree of owned elements, each with its file, line, column
//! and byte range (so a reader can name any element, and the fix can replace one in place),
//! parsed by `roxmltree`. Numbers are read here, so every bad value is reported the same way.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::error::{Location, RobotError};

/// A file of the description: its path and text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SourceFile {
    /// The path it was read from.
    pub path: PathBuf,
    /// Its text.
    pub text: String,
    /// What strict XML refuses in it that MuJoCo (TinyXML2) and urdfdom accept, and which was
    /// therefore read as they read it: each place and fault.
    pub read_leniently: Vec<Leniency>,
}

/// A fault of a file's XML that the engines read past, read past here too.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Leniency {
    /// Where strict parsing stopped.
    pub at: Location,
    /// The fault, and how it was read.
    pub what: String,
}

/// One element: name, attributes in file order, child elements, and where it is.
#[derive(Debug, Clone)]
pub struct Element {
    /// Local name (no namespace prefix).
    pub name: String,
    /// The namespace of the name, when it has one (`xacro:macro` → xacro's URI).
    pub namespace: Option<String>,
    /// Attributes, local names.
    pub attributes: Vec<(String, String)>,
    /// Child elements.
    pub children: Vec<Element>,
    /// Its own text (not its children's), as written: SDFormat's values are element text.
    pub text: String,
    /// Where its start tag is.
    pub at: Location,
    /// Which source file (an index into the reader's list).
    pub file: usize,
    /// Its bytes in that file, start tag to end tag.
    pub range: Range<usize>,
}

/// Reads `path` as text.
pub fn read_file(path: &Path) -> Result<String, RobotError> {
    std::fs::read_to_string(path).map_err(|e| RobotError::Io {
        path: path.to_owned(),
        source: Arc::new(e),
    })
}

/// Parses `text` (file number `file`, at `path`) into its root element.
pub fn parse(text: &str, path: &Path, file: usize) -> Result<(Element, Vec<Leniency>), RobotError> {
    let options = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let at = |pos: roxmltree::TextPos| Location {
        file: path.to_owned(),
        line: pos.row,
        column: pos.col,
    };
    // Each fault the engines read past is mended in a copy, and parsing starts again. Mends keep
    // the length, except a space put between two attributes: those places are kept, so every
    // byte range still points into the file as written (for the fix).
    let mut mended = std::borrow::Cow::Borrowed(text);
    let mut leniencies = Vec::new();
    let mut inserted: Vec<usize> = Vec::new();
    loop {
        match roxmltree::Document::parse_with_options(&mended, options) {
            Ok(doc) => {
                let places = Places::new(text, inserted);
                let root = convert(doc.root_element(), path, file, &places);
                return Ok((root, leniencies));
            }
            Err(e) => {
                let Some(Mend {
                    text: next,
                    what,
                    space_at,
                }) = mend(&mended, &e)
                else {
                    return Err(RobotError::Xml {
                        at: Box::new(at(e.pos())),
                        message: e.to_string(),
                    });
                };
                // A fault mended twice in one place would loop: the text must change.
                if next == *mended || leniencies.len() > 1000 {
                    return Err(RobotError::Xml {
                        at: Box::new(at(e.pos())),
                        message: e.to_string(),
                    });
                }
                if let Some(p) = space_at {
                    for q in &mut inserted {
                        if *q >= p {
                            *q += 1;
                        }
                    }
                    inserted.push(p);
                }
                leniencies.push(Leniency {
                    at: at(e.pos()),
                    what,
                });
                mended = std::borrow::Cow::Owned(next);
            }
        }
    }
}

/// Places in the file as written, from places in its mended copy.
struct Places<'a> {
    text: &'a str,
    /// The byte where each line starts.
    line_starts: Vec<usize>,
    /// Where the mended copy has a byte the file lacks, sorted.
    inserted: Vec<usize>,
}

impl<'a> Places<'a> {
    fn new(text: &'a str, mut inserted: Vec<usize>) -> Self {
        inserted.sort_unstable();
        let line_starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Places {
            text,
            line_starts,
            inserted,
        }
    }

    /// The byte of the file that byte `at` of the mended copy stands for.
    fn original(&self, at: usize) -> usize {
        at - self.inserted.partition_point(|&q| q < at)
    }

    /// One-based line and column (in characters) of byte `at` of the file.
    fn line_column(&self, at: usize) -> (u32, u32) {
        let line = self.line_starts.partition_point(|&s| s <= at);
        let start = self.line_starts[line - 1];
        let column = self
            .text
            .get(start..at)
            .map_or(at - start, |s| s.chars().count())
            + 1;
        (
            u32::try_from(line).unwrap_or(u32::MAX),
            u32::try_from(column).unwrap_or(u32::MAX),
        )
    }
}

/// A fault mended: the new text, what was done, and where a space was put in (the one mend
/// that changes the length).
struct Mend {
    text: String,
    what: String,
    space_at: Option<usize>,
}

impl Mend {
    fn same_length(text: String, what: impl Into<String>) -> Option<Self> {
        Some(Mend {
            text,
            what: what.into(),
            space_at: None,
        })
    }
}

/// `text` with the fault `e` mended as MuJoCo's TinyXML2 and urdfdom read it, in the same number
/// of bytes, and what was done; `None` for a fault they refuse too.
fn mend(text: &str, e: &roxmltree::Error) -> Option<Mend> {
    match e {
        // `name="a"type="b"`: TinyXML2 and urdfdom read the second attribute all the same.
        roxmltree::Error::InvalidChar2("a whitespace", _, pos) => {
            let at = byte_at(text, *pos)?;
            if !matches!(text.as_bytes().get(at.checked_sub(1)?), Some(b'"' | b'\'')) {
                return None;
            }
            let mut out = String::with_capacity(text.len() + 1);
            out.push_str(&text[..at]);
            out.push(' ');
            out.push_str(&text[at..]);
            Some(Mend {
                text: out,
                what: "no space between two attributes: read as two attributes".to_owned(),
                space_at: Some(at),
            })
        }
        // `drake:acceleration="…"` without xmlns:drake (airo-models' UR5e): the prefix is part
        // of the name, as for a parser without namespaces.
        roxmltree::Error::UnknownNamespace(prefix, _) => {
            let written = format!("{prefix}:");
            let read = format!("{prefix}_");
            let bytes = text.as_bytes();
            let mut out = String::with_capacity(text.len());
            let mut rest = 0;
            for (i, _) in text.match_indices(&written) {
                let before = i.checked_sub(1).map(|k| bytes[k]);
                let in_a_name = matches!(before, Some(b'<' | b'/' | b' ' | b'\t' | b'\n' | b'\r'));
                if in_a_name {
                    out.push_str(&text[rest..i]);
                    out.push_str(&read);
                    rest = i + written.len();
                }
            }
            out.push_str(&text[rest..]);
            Mend::same_length(
                out,
                format!(
                    "the namespace prefix {prefix}: is not declared: read as part of the names"
                ),
            )
        }
        // `--` inside a comment: TinyXML2 reads the comment to its `-->`.
        roxmltree::Error::InvalidComment(_) => {
            let mut out = String::with_capacity(text.len());
            let mut rest = text;
            while let Some(start) = rest.find("<!--") {
                out.push_str(&rest[..start + 4]);
                let body = &rest[start + 4..];
                let end = body.find("-->").unwrap_or(body.len());
                // Every hyphen of the comment's own text becomes a space.
                out.extend(body[..end].chars().map(|c| if c == '-' { ' ' } else { c }));
                rest = &body[end..];
            }
            out.push_str(rest);
            Mend::same_length(out, "a comment holds \"--\": read to its \"-->\"")
        }
        // `<?xml …?>` after blank lines: the declaration is read past.
        roxmltree::Error::UnexpectedDeclaration(_) => {
            let start = text.find("<?xml")?;
            let end = start + text[start..].find("?>")? + 2;
            if !text[..start].trim().is_empty() {
                return None;
            }
            let mut out = text[..start].to_owned();
            out.extend(std::iter::repeat_n(' ', end - start));
            out.push_str(&text[end..]);
            Mend::same_length(out, "the XML declaration comes after blank text: read past")
        }
        // NUL bytes after the root element (pybullet's humanoid.urdf ends with one): TinyXML
        // stops at a NUL, as C strings do.
        roxmltree::Error::UnknownToken(_) => {
            let content = text.trim_end_matches(|c: char| c == '\0' || c.is_whitespace());
            let tail = &text[content.len()..];
            if !tail.contains('\0') {
                return None;
            }
            let mut out = content.to_owned();
            out.extend(tail.chars().map(|c| if c == '\0' { ' ' } else { c }));
            Mend::same_length(out, "NUL bytes after the root element: read past")
        }
        _ => None,
    }
}

/// The byte of `text` at a parser's line and column (in characters).
fn byte_at(text: &str, pos: roxmltree::TextPos) -> Option<usize> {
    let line_start = if pos.row <= 1 {
        0
    } else {
        text.match_indices('\n').nth(pos.row as usize - 2)?.0 + 1
    };
    let column = pos.col.checked_sub(1)? as usize;
    match text[line_start..].char_indices().nth(column) {
        Some((i, _)) => Some(line_start + i),
        None => Some(text.len()),
    }
}

fn convert(
    node: roxmltree::Node<'_, '_>,
    path: &Path,
    file: usize,
    places: &Places<'_>,
) -> Element {
    let range = places.original(node.range().start)..places.original(node.range().end);
    let (line, column) = places.line_column(range.start);
    let tag = node.tag_name();
    Element {
        name: tag.name().to_owned(),
        namespace: tag.namespace().map(str::to_owned),
        attributes: node
            .attributes()
            .map(|a| (a.name().to_owned(), a.value().to_owned()))
            .collect(),
        children: node
            .children()
            .filter(roxmltree::Node::is_element)
            .map(|c| convert(c, path, file, places))
            .collect(),
        text: node
            .children()
            .filter(roxmltree::Node::is_text)
            .filter_map(|t| t.text())
            .collect(),
        at: Location {
            file: path.to_owned(),
            line,
            column,
        },
        file,
        range,
    }
}

impl Element {
    /// The first element, this one or below, that only xacro understands (an element in
    /// xacro's namespace, or a `${…}`/`$(…)` substitution in an attribute), and what it is.
    /// Comments are not elements, so markup commented out does not count.
    pub fn xacro(&self) -> Option<(&Element, String)> {
        if self
            .namespace
            .as_deref()
            .is_some_and(|n| n.contains("xacro"))
        {
            return Some((self, format!("the xacro element <xacro:{}>", self.name)));
        }
        // A mesh's file name is only a name: a substitution left in it makes that one mesh
        // missing (named in its finding), not the whole description unreadable.
        let file_name = |k: &str| self.name == "mesh" && (k == "filename" || k == "file");
        if let Some((k, v)) = self
            .attributes
            .iter()
            .find(|(k, v)| unexpanded_substitution(v).is_some() && !file_name(k))
        {
            return Some((self, format!("the substitution {k}=\"{v}\"")));
        }
        self.children.iter().find_map(Element::xacro)
    }

    /// An attribute's value.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }

    /// The child elements called `name`.
    pub fn children_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Element> + 'a {
        self.children.iter().filter(move |c| c.name == name)
    }

    /// The first child element called `name`.
    pub fn child(&self, name: &str) -> Option<&Element> {
        self.children.iter().find(|c| c.name == name)
    }

    /// An error about attribute `name` of this element.
    pub fn bad(&self, name: &str, value: &str, problem: impl Into<String>) -> RobotError {
        RobotError::Attribute {
            at: Box::new(self.at.clone()),
            element: self.name.clone(),
            attribute: name.to_owned(),
            value: value.to_owned(),
            problem: problem.into(),
        }
    }

    /// An error about this element as a whole.
    pub fn wrong(&self, problem: impl Into<String>) -> RobotError {
        RobotError::Element {
            at: Box::new(self.at.clone()),
            element: self.name.clone(),
            problem: problem.into(),
        }
    }

    /// Attribute `name` as `N` finite numbers separated by white space, if present.
    pub fn numbers<const N: usize>(&self, name: &str) -> Result<Option<[f64; N]>, RobotError> {
        self.get(name)
            .map(|v| {
                numbers(v)
                    .and_then(|xs| {
                        <[f64; N]>::try_from(xs)
                            .map_err(|xs| format!("expected {N} number(s), found {}", xs.len()))
                    })
                    .map_err(|problem| self.bad(name, v, problem))
            })
            .transpose()
    }

    /// Attribute `name` as one finite number, if present.
    pub fn number(&self, name: &str) -> Result<Option<f64>, RobotError> {
        Ok(self.numbers::<1>(name)?.map(|[x]| x))
    }

    /// Attribute `name` as one finite number, which must be present.
    pub fn required_number(&self, name: &str) -> Result<f64, RobotError> {
        self.number(name)?
            .ok_or_else(|| self.wrong(format!("the attribute {name} is missing")))
    }

    /// The text of child `name` as `N` finite numbers separated by white space, if present.
    pub fn child_numbers<const N: usize>(
        &self,
        name: &str,
    ) -> Result<Option<[f64; N]>, RobotError> {
        self.child(name)
            .map(|c| {
                numbers(&c.text)
                    .and_then(|xs| {
                        <[f64; N]>::try_from(xs)
                            .map_err(|xs| format!("expected {N} number(s), found {}", xs.len()))
                    })
                    .map_err(|problem| c.wrong(format!("\"{}\": {problem}", c.text.trim())))
            })
            .transpose()
    }

    /// The text of child `name` as one finite number, if present.
    pub fn child_number(&self, name: &str) -> Result<Option<f64>, RobotError> {
        Ok(self.child_numbers::<1>(name)?.map(|[x]| x))
    }

    /// The trimmed text of child `name`, if present.
    pub fn child_text(&self, name: &str) -> Option<&str> {
        self.child(name).map(|c| c.text.trim())
    }

    /// Attribute `name` as any count of finite numbers, if present.
    pub fn number_list(&self, name: &str) -> Result<Option<Vec<f64>>, RobotError> {
        self.get(name)
            .map(|v| numbers(v).map_err(|problem| self.bad(name, v, problem)))
            .transpose()
    }
}

/// White-space separated finite numbers.
fn numbers(text: &str) -> Result<Vec<f64>, String> {
    text.split_whitespace()
        .map(|t| match t.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            Ok(_) => Err(format!("{t} is not a finite number")),
            Err(_) => Err(format!("{t} is not a number")),
        })
        .collect()
}

/// The first substitution of xacro's (`${…}` or `$(…)`) left in `text`, if any.
pub fn unexpanded_substitution(text: &str) -> Option<&str> {
    let start = text.find("${").or_else(|| text.find("$("))?;
    let close = if text[start + 1..].starts_with('{') {
        '}'
    } else {
        ')'
    };
    let end = text[start..]
        .find(close)
        .map_or(text.len(), |e| start + e + 1);
    Some(&text[start..end])
}
