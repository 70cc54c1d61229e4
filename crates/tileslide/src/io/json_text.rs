//! Where in a text file an error is: line and column in characters, from a byte offset or
//! from serde_json's line and byte column; and the load error for a JSON syntax error.

use std::path::Path;

use super::{LoadError, LoadErrorKind, Location};

/// The 1-based line and column (in characters) of a byte offset of `text`.
pub(crate) fn line_column(text: &str, offset: usize) -> Location {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    Location::LineColumn {
        line: before.matches('\n').count() as u32 + 1,
        column: before[line_start..].chars().count() as u32 + 1,
    }
}

/// Where serde_json's error `e` is in `text`, its byte column converted to characters; at
/// the end of a truncated file, just past its last character (as XML errors say).
pub(crate) fn json_location(text: &str, e: &serde_json::Error) -> Location {
    let (line, byte_column) = (e.line(), e.column());
    if e.is_eof() {
        return line_column(text, text.len());
    }
    if line == 0 {
        return Location::File;
    }
    let column = text
        .lines()
        .nth(line.saturating_sub(1))
        .map(|l| {
            let mut end = byte_column.saturating_sub(1).min(l.len());
            while !l.is_char_boundary(end) {
                end -= 1;
            }
            l[..end].chars().count() + 1
        })
        .unwrap_or(byte_column);
    Location::LineColumn {
        line: line as u32,
        column: column as u32,
    }
}

/// serde_json's message for `e` without the " at line L column C" it appends: the error's
/// location says it.
pub(crate) fn json_message(e: &serde_json::Error) -> String {
    let message = e.to_string();
    message
        .split(" at line ")
        .next()
        .unwrap_or(&message)
        .to_owned()
}

/// A JSON syntax or shape error at serde_json's line and column (converted to characters).
pub(crate) fn json_error(text: &str, path: &Path, e: serde_json::Error) -> LoadError {
    let location = json_location(text, &e);
    let message = json_message(&e);
    let message = if e.is_eof() {
        format!("truncated JSON: {message}")
    } else {
        format!("malformed JSON: {message}")
    };
    let kind = LoadErrorKind::Syntax {
        format: "JSON",
        truncated: e.is_eof(),
        message,
        source: Some(Box::new(e)),
    };
    LoadError::new(path, location, kind)
}
