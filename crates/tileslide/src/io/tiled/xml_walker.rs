//! XML events with their positions, for the first pass over `.tmx`, `.tsx` and `.tx`
//! files: every error names the file, line and column.

use std::path::Path;

use quick_xml::Reader;
use quick_xml::events::{BytesStart, Event};

use super::line_column;
use crate::io::{LoadError, LoadErrorKind, Location};
use crate::tiles::MAX_CELLS;

/// An element's name, attributes (unescaped) and byte offset.
pub(super) struct Element {
    pub name: String,
    pub attributes: Vec<(String, String)>,
    pub offset: usize,
}

/// One XML event: an element opened or closed, its text, or the end of the file.
pub(super) enum Item {
    Open(Element),
    Close(String),
    Text {
        text: String,
        offset: usize,
        /// True when the text is the file's bytes as they are (no entity was expanded), so
        /// offsets in it are offsets in the file.
        verbatim: bool,
    },
    End,
}

/// Reads XML events with their positions; errors name the file, line and column.
pub(super) struct Walker<'a> {
    pub text: &'a str,
    pub path: &'a Path,
    reader: Reader<&'a [u8]>,
    /// Open elements: name and offset.
    open: Vec<(String, usize)>,
    /// Most cells a grid the walk reads may hold ([`MAX_CELLS`] unless the caller lowers it).
    pub max_cells: u64,
}

impl<'a> Walker<'a> {
    pub fn new(text: &'a str, path: &'a Path) -> Self {
        let mut reader = Reader::from_str(text);
        reader.expand_empty_elements(true).check_end_names(true);
        Self {
            text,
            path,
            reader,
            open: Vec::new(),
            max_cells: MAX_CELLS,
        }
    }

    /// The error `kind` at byte `offset` of the text.
    pub fn fail(&self, offset: usize, kind: impl Into<LoadErrorKind>) -> LoadError {
        LoadError::new(self.path, line_column(self.text, offset), kind.into())
    }

    /// XML that quick-xml (`source`, when it gave an error) refuses, at byte `offset`.
    fn syntax(
        &self,
        offset: usize,
        truncated: bool,
        message: String,
        source: Option<quick_xml::Error>,
    ) -> LoadError {
        self.fail(
            offset,
            LoadErrorKind::Syntax {
                format: "XML",
                truncated,
                message,
                source: source.map(|e| Box::new(e) as _),
            },
        )
    }

    pub fn size_error(
        &self,
        offset: usize,
        field: &'static str,
        value: i64,
        reason: String,
    ) -> LoadError {
        LoadError::new(
            self.path,
            line_column(self.text, offset),
            LoadErrorKind::BadSize {
                field,
                value,
                reason,
            },
        )
    }

    /// The name of the element holding the one just opened.
    pub fn parent(&self) -> Option<&str> {
        let n = self.open.len();
        (n >= 2).then(|| self.open[n - 2].0.as_str())
    }

    pub fn next(&mut self) -> Result<Item, LoadError> {
        loop {
            let offset = self.reader.buffer_position();
            let event = self.reader.read_event().map_err(|e| match &e {
                // A file cut inside a tag or comment: say so, at the end of the file.
                quick_xml::Error::UnexpectedEof(what) => {
                    let what = match what.as_str() {
                        "Element" => "a tag".to_string(),
                        "Comment" => "a comment".to_string(),
                        "CData" => "a CDATA section".to_string(),
                        other => format!("`{other}`"),
                    };
                    let message = match line_column(self.text, offset) {
                        Location::LineColumn { line, column } => format!(
                            "the file ends inside {what} (started at {line}:{column}): truncated XML"
                        ),
                        _ => "truncated XML".to_string(),
                    };
                    self.syntax(self.text.len(), true, message, Some(e))
                }
                // Named at the start of the markup that is wrong.
                _ => self.syntax(offset, false, format!("malformed XML: {e}"), Some(e)),
            })?;
            match event {
                Event::Start(start) => {
                    let element = self.element(&start, offset)?;
                    self.open.push((element.name.clone(), offset));
                    return Ok(Item::Open(element));
                }
                Event::End(end) => {
                    self.open.pop();
                    let name = String::from_utf8_lossy(end.local_name().as_ref()).into_owned();
                    return Ok(Item::Close(name));
                }
                Event::Text(text) => {
                    let raw = text.len();
                    let unescaped = text.unescape().map_err(|e| {
                        let message = format!("malformed XML text: {e}");
                        self.syntax(offset, false, message, Some(e))
                    })?;
                    return Ok(Item::Text {
                        verbatim: unescaped.len() == raw,
                        text: unescaped.into_owned(),
                        offset,
                    });
                }
                Event::CData(data) => {
                    return Ok(Item::Text {
                        text: String::from_utf8_lossy(&data).into_owned(),
                        offset: offset + "<![CDATA[".len(),
                        verbatim: true,
                    });
                }
                Event::Eof => {
                    return match self.open.last() {
                        Some((name, at)) => {
                            let message = match line_column(self.text, *at) {
                                Location::LineColumn { line, column } => format!(
                                    "the file ends inside <{name}> (opened at {line}:{column}): \
                                     truncated XML"
                                ),
                                _ => "the file ends early".to_string(),
                            };
                            Err(self.syntax(self.text.len(), true, message, None))
                        }
                        None => Ok(Item::End),
                    };
                }
                _ => {}
            }
        }
    }

    pub fn element(&self, start: &BytesStart<'_>, offset: usize) -> Result<Element, LoadError> {
        let name = String::from_utf8_lossy(start.local_name().as_ref()).into_owned();
        let mut attributes = Vec::new();
        for attribute in start.attributes() {
            let malformed = |e: quick_xml::Error| {
                let message = format!("malformed XML attribute: {e}");
                self.syntax(offset, false, message, Some(e))
            };
            let attribute = attribute.map_err(|e| malformed(e.into()))?;
            let key = String::from_utf8_lossy(attribute.key.local_name().as_ref()).into_owned();
            let value = attribute.unescape_value().map_err(malformed)?.into_owned();
            attributes.push((key, value));
        }
        Ok(Element {
            name,
            attributes,
            offset,
        })
    }

    pub fn attribute<'e>(&self, element: &'e Element, name: &str) -> Option<&'e str> {
        element
            .attributes
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }

    /// A numeric attribute, `None` when absent; a value that does not parse is an error.
    pub fn number<T: std::str::FromStr>(
        &self,
        element: &Element,
        name: &'static str,
        what: &'static str,
    ) -> Result<Option<T>, LoadError> {
        self.attribute(element, name)
            .map(|v| {
                v.trim().parse::<T>().map_err(|_| {
                    self.fail(
                        element.offset,
                        LoadErrorKind::BadValue {
                            owner: format!("<{}>", element.name),
                            field: name,
                            found: format!("{v:?}"),
                            expected: what,
                        },
                    )
                })
            })
            .transpose()
    }

    pub fn required<T: std::str::FromStr>(
        &self,
        element: &Element,
        name: &'static str,
        what: &'static str,
    ) -> Result<T, LoadError> {
        self.number(element, name, what)?
            .ok_or_else(|| self.missing(element, name))
    }

    /// The error for `element` without the attribute `name`.
    pub fn missing(&self, element: &Element, name: &str) -> LoadError {
        self.fail(
            element.offset,
            LoadErrorKind::Missing {
                owner: format!("<{}>", element.name),
                field: name.to_owned(),
            },
        )
    }
}
