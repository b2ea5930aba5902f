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
pub fn parse(text: &str, path: &Path, file: usize) -> Result<Element, RobotError> {
    let options = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let doc = roxmltree::Document::parse_with_options(text, options).map_err(|e| {
        let pos = e.pos();
        RobotError::Xml {
            at: Box::new(Location {
                file: path.to_owned(),
                line: pos.row,
                column: pos.col,
            }),
            message: e.to_string(),
        }
    })?;
    Ok(convert(&doc, doc.root_element(), path, file))
}

fn convert(
    doc: &roxmltree::Document<'_>,
    node: roxmltree::Node<'_, '_>,
    path: &Path,
    file: usize,
) -> Element {
    let pos = doc.text_pos_at(node.range().start);
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
            .map(|c| convert(doc, c, path, file))
            .collect(),
        at: Location {
            file: path.to_owned(),
            line: pos.row,
            column: pos.col,
        },
        file,
        range: node.range(),
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
        if let Some((k, v)) = self
            .attributes
            .iter()
            .find(|(_, v)| v.contains("${") || v.contains("$("))
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
