//! The CSV dialect of probe-cycle tables: one row per line, fields split at
//! commas, with quoting, and each field optionally named (`NAME=VALUE`).
//!
//! ```text
//! row    = field { "," field }
//! field  = blanks [ name blanks "=" blanks ] value blanks
//! value  = quoted | bare
//! quoted = '"' { any character but '"' | '""' } '"'
//! bare   = { any character but ',' and '"' }
//! name   = letter { letter | digit | "_" }
//! ```
//!
//! - Blanks (spaces and tabs) around a field, its name, its `=` and its
//!   value are not part of it.
//! - A quoted value may hold commas, `=` and blanks; `""` in it is one `"`.
//!   Quoting also says "this is text": `"12"` is the text 12, `12` the number.
//! - A `"` inside a bare value, text after a closing quote, or a quote that
//!   is not closed on its line is an error: a row never spans two lines.
//! - `NAME=` is only a name when NAME is a valid name; `a b=1` is a bare
//!   value (and an error later, as it is not a number).
//!
//! Every position is a byte offset in the table file, so diagnostics point
//! at the cell.

use postc_ir::codes;
use postc_ir::{Diagnostic, FileId, Span};

/// Code of a row that does not split into fields.
pub const BAD_QUOTE: &str = codes::PT001.code;

/// One field of a row.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// `NAME` of `NAME=VALUE`, and where it is.
    pub name: Option<(String, Span)>,
    /// The value, unquoted.
    pub value: String,
    /// Whether the value was quoted (so it is text).
    pub quoted: bool,
    /// The value (quotes included), or where it would be when empty.
    pub value_span: Span,
    /// The whole field, blanks left out.
    pub span: Span,
}

impl Field {
    /// Nothing in it: no name and an empty bare value.
    pub fn is_empty(&self) -> bool {
        self.name.is_none() && !self.quoted && self.value.is_empty()
    }
}

/// Splits one line (without its line ending) that starts at byte `base` of
/// the file. Trailing empty fields are dropped (spreadsheets pad rows).
pub fn split(line: &str, base: usize, file: FileId) -> Result<Vec<Field>, Diagnostic> {
    let bytes = line.as_bytes();
    let span = |a: usize, b: usize| Span::new(file, base + a, base + b);
    let mut fields = Vec::new();
    let mut i = 0;
    loop {
        i = skip_blanks(bytes, i);
        let start = i;
        let mut name = None;
        let name_end = scan_name(bytes, i);
        if name_end > i {
            let after = skip_blanks(bytes, name_end);
            if bytes.get(after) == Some(&b'=') {
                name = Some((line[i..name_end].to_string(), span(i, name_end)));
                i = skip_blanks(bytes, after + 1);
            }
        }
        let value_start = i;
        let (value, quoted) = if bytes.get(i) == Some(&b'"') {
            let mut text = String::new();
            let mut j = i + 1;
            loop {
                match bytes.get(j) {
                    None => {
                        return Err(Diagnostic::error(BAD_QUOTE, "this quote is not closed on its line")
                            .at(span(i, i + 1), "opened here")
                            .help("a row is one line; close the quote, and write \"\" for a quote inside it"));
                    }
                    Some(b'"') if bytes.get(j + 1) == Some(&b'"') => {
                        text.push('"');
                        j += 2;
                    }
                    Some(b'"') => {
                        j += 1;
                        break;
                    }
                    Some(_) => {
                        let ch = line[j..].chars().next().unwrap_or('\u{FFFD}');
                        text.push(ch);
                        j += ch.len_utf8().max(1);
                    }
                }
            }
            i = j;
            (text, true)
        } else {
            let end = bytes[i..].iter().position(|&b| b == b',' || b == b'"').map_or(bytes.len(), |k| i + k);
            if bytes.get(end) == Some(&b'"') {
                return Err(Diagnostic::error(BAD_QUOTE, "a quote inside a value that does not start with one")
                    .at(span(end, end + 1), "unexpected quote")
                    .help("quote the whole value: \"a \"\"b\"\" c\""));
            }
            let text = line[i..end].trim_end_matches([' ', '\t']);
            i += text.len();
            (text.to_string(), false)
        };
        let value_end = i;
        i = skip_blanks(bytes, i);
        match bytes.get(i) {
            None | Some(b',') => {}
            Some(_) => {
                return Err(Diagnostic::error(BAD_QUOTE, "text after a closing quote")
                    .at(span(i, i + 1), "expected `,` or the end of the row")
                    .help("put the whole value inside the quotes"));
            }
        }
        fields.push(Field {
            name,
            value,
            quoted,
            value_span: span(value_start, value_end),
            span: span(start, value_end),
        });
        if i >= bytes.len() {
            break;
        }
        i += 1;
    }
    while fields.last().is_some_and(Field::is_empty) {
        fields.pop();
    }
    Ok(fields)
}

fn skip_blanks(bytes: &[u8], mut i: usize) -> usize {
    while matches!(bytes.get(i), Some(b' ' | b'\t')) {
        i += 1;
    }
    i
}

/// End of a name starting at `i` (= `i` when there is none).
fn scan_name(bytes: &[u8], i: usize) -> usize {
    if !bytes.get(i).is_some_and(u8::is_ascii_alphabetic) {
        return i;
    }
    let mut j = i + 1;
    while bytes.get(j).is_some_and(|b| b.is_ascii_alphanumeric() || *b == b'_') {
        j += 1;
    }
    j
}

/// Quotes a cell for writing when it needs it.
pub fn quote(cell: &str) -> String {
    if cell.contains([',', '"']) || cell.starts_with([' ', '\t']) || cell.ends_with([' ', '\t']) {
        format!("\"{}\"", cell.replace('"', "\"\""))
    } else {
        cell.to_string()
    }
}
