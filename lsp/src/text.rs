//! Positions and small scanners over a document's text.
//!
//! LSP positions are a 0-based line and a character offset counted in
//! UTF-16 code units; postc spans are byte offsets into the UTF-8 text.
//! Lines end at `\n` (a `\r` before it stays in the line, after every
//! character a position can name).

use lsp_types::{Position, Range};

/// The LSP position of a byte offset (clamped to the text and to a
/// character boundary).
pub fn position(text: &str, offset: usize) -> Position {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let line = before.bytes().filter(|&b| b == b'\n').count();
    let character = before[line_start..].encode_utf16().count();
    Position::new(line as u32, character as u32)
}

/// The byte offset of an LSP position; a character past the end of its
/// line is the end of the line, a line past the end is the end of the text.
pub fn offset(text: &str, pos: Position) -> usize {
    let mut start = 0;
    for _ in 0..pos.line {
        match text[start..].find('\n') {
            Some(i) => start += i + 1,
            None => return text.len(),
        }
    }
    let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    let mut units = 0u32;
    for (i, c) in text[start..line_end].char_indices() {
        if units >= pos.character {
            return start + i;
        }
        units += c.len_utf16() as u32;
    }
    line_end
}

/// The LSP range of a byte range.
pub fn range(text: &str, start: usize, end: usize) -> Range {
    Range::new(position(text, start), position(text, end))
}

/// Whether a byte can be part of a name.
pub fn is_name_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_' || b == b'$'
}

/// The name (letters, digits, `_`) under or just before a byte offset.
pub fn word_at(text: &str, offset: usize) -> Option<(usize, usize)> {
    let bytes = text.as_bytes();
    let offset = offset.min(bytes.len());
    let mut start = offset;
    while start > 0 && is_name_byte(bytes[start - 1]) {
        start -= 1;
    }
    let mut end = offset;
    while end < bytes.len() && is_name_byte(bytes[end]) {
        end += 1;
    }
    (start < end).then_some((start, end))
}

/// The byte range of the line holding `offset`, without its line ending.
pub fn line_around(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let end = text[offset..].find('\n').map_or(text.len(), |i| offset + i);
    let end = if text[start..end].ends_with('\r') { end - 1 } else { end };
    (start, end)
}

/// Every line with its byte offset, without line endings.
pub fn lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let mut start = 0;
    text.split('\n').map(move |l| {
        let at = start;
        start += l.len() + 1;
        (at, l.strip_suffix('\r').unwrap_or(l))
    })
}

/// `s` without a leading keyword (any case) and the blanks after it.
pub fn strip_keyword<'a>(s: &'a str, keyword: &str) -> Option<&'a str> {
    let head = s.get(..keyword.len())?;
    if !head.eq_ignore_ascii_case(keyword) {
        return None;
    }
    let rest = &s[keyword.len()..];
    if rest.starts_with([' ', '\t']) { Some(rest.trim_start()) } else { None }
}

/// The leading name of `s` (possibly empty).
pub fn leading_name(s: &str) -> &str {
    let n = s.bytes().take_while(|&b| is_name_byte(b)).count();
    &s[..n]
}

/// Levenshtein distance of two ASCII-case-folded strings.
pub fn edit_distance(a: &str, b: &str) -> usize {
    strsim::levenshtein(&a.to_ascii_uppercase(), &b.to_ascii_uppercase())
}
