//! The lexer: turns physical lines into records.
//!
//! It owns the line-level rules of CL text: blank lines, `$$` comments
//! (whole-line and trailing), `$` continuation (also at the end of a `$$`
//! comment line, as Creo writes its `$$-> CSYS` echoes), CRLF and trailing
//! blanks, text records (`PPRINT`, `PARTNO`, `INSERT`, `REMARK`,
//! `OPFEATSTART`, `OPFEATEND`) that are never continued, and lines made only
//! of numbers. A line of numbers right after a record whose last line has no
//! `$` is joined to that record (with a warning unless the record ended with
//! a comma); a line of numbers with no record before it is reported.
//!
//! The assembled record is kept in one buffer that is reused for every
//! record; `segments` map offsets in it back to byte offsets in the file so
//! that diagnostics point at the right column of the right line.

use std::io::{self, BufRead};

use crate::lines::{LineInfo, Lines, MAX_LINE};

/// What the lexer found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)]
pub enum RawKind {
    /// A statement: major word(s), optional `/` and arguments.
    Statement,
    /// A text record; the text follows the word at [`Lexer::text_at`].
    Text(TextWord),
    /// A `$$` comment, without the `$$`.
    Comment,
    /// A line of numbers that continues no record.
    Orphan,
    /// A line, or a record continued over lines, longer than [`MAX_LINE`].
    TooLong,
}

/// The words whose records are free text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)]
pub enum TextWord {
    Pprint,
    Partno,
    Insert,
    Remark,
    OpFeatStart,
    OpFeatEnd,
}

impl TextWord {
    pub fn name(self) -> &'static str {
        match self {
            TextWord::Pprint => "PPRINT",
            TextWord::Partno => "PARTNO",
            TextWord::Insert => "INSERT",
            TextWord::Remark => "REMARK",
            TextWord::OpFeatStart => "OPFEATSTART",
            TextWord::OpFeatEnd => "OPFEATEND",
        }
    }

    const ALL: [TextWord; 6] = [
        TextWord::Pprint,
        TextWord::Partno,
        TextWord::Insert,
        TextWord::Remark,
        TextWord::OpFeatStart,
        TextWord::OpFeatEnd,
    ];
}

/// Something the lexer noticed about the record it just returned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)]
pub enum LexNote {
    /// A line of numbers (file bytes `start..end`) was joined to the record
    /// although the line before it had no `$`.
    JoinedWithoutDollar { start: usize, end: usize },
    /// The file ended after a `$`.
    EofInContinuation { at: usize },
}

/// How one trimmed physical line starts.
enum LineClass {
    Comment,
    Numbers,
    Text(TextWord),
    Statement,
}

/// Assembles records from physical lines.
#[doc(hidden)]
pub struct Lexer<R> {
    lines: Lines<R>,
    line: Vec<u8>,
    line_info: LineInfo,
    /// `line` holds a line read ahead that the next call must use.
    held: bool,
    record: Vec<u8>,
    /// Where the record starts in `record` (a one-line statement keeps the
    /// line's buffer, with its leading blanks, instead of being copied).
    record_start: usize,
    /// The record grew past [`MAX_LINE`].
    overflow: bool,
    segments: Vec<(usize, usize)>,
    span: (usize, usize),
    text_at: usize,
    notes: Vec<LexNote>,
}

fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | 0x0c | 0x1a)
}

/// The non-blank range of a line.
fn trim(line: &[u8]) -> (usize, usize) {
    let start = line.iter().position(|&b| !is_blank(b)).unwrap_or(line.len());
    let end = line.iter().rposition(|&b| !is_blank(b)).map_or(start, |p| p + 1);
    (start, end.max(start))
}

/// Whether a trimmed comment or statement line asks for continuation: it
/// ends with one `$` (a trailing `$$` opens an empty comment instead).
fn ends_with_single_dollar(t: &[u8]) -> bool {
    t.ends_with(b"$") && !t.ends_with(b"$$")
}

fn classify(t: &[u8]) -> LineClass {
    match t[0] {
        b'$' if t.get(1) == Some(&b'$') => LineClass::Comment,
        b'0'..=b'9' | b'+' | b'-' | b'.' => LineClass::Numbers,
        b'P' | b'p' | b'I' | b'i' | b'R' | b'r' | b'O' | b'o' => {
            for word in TextWord::ALL {
                let name = word.name().as_bytes();
                if t.len() >= name.len()
                    && t[..name.len()].eq_ignore_ascii_case(name)
                    && t.get(name.len()).is_none_or(|&b| b == b'/' || is_blank(b))
                {
                    return LineClass::Text(word);
                }
            }
            LineClass::Statement
        }
        _ => LineClass::Statement,
    }
}

/// Position of a `$$` that starts a trailing comment.
fn trailing_comment(t: &[u8]) -> Option<usize> {
    let mut from = 0;
    while let Some(i) = crate::lines::find_byte(&t[from..], b'$') {
        let at = from + i;
        if t.get(at + 1) == Some(&b'$') {
            return Some(at);
        }
        from = at + 1;
    }
    None
}

impl<R: BufRead> Lexer<R> {
    pub fn new(lines: Lines<R>) -> Lexer<R> {
        Lexer {
            lines,
            line: Vec::with_capacity(256),
            line_info: LineInfo::default(),
            held: false,
            record: Vec::with_capacity(256),
            record_start: 0,
            overflow: false,
            segments: Vec::with_capacity(4),
            span: (0, 0),
            text_at: 0,
            notes: Vec::new(),
        }
    }

    pub fn lines_mut(&mut self) -> &mut Lines<R> {
        &mut self.lines
    }

    /// The bytes of the record last returned (for comments and text records,
    /// the trimmed line; for statements, the assembled text).
    pub fn record(&self) -> &[u8] {
        self.record.get(self.record_start..).unwrap_or_default()
    }

    /// File byte range of the record last returned.
    pub fn span(&self) -> (usize, usize) {
        self.span
    }

    /// For a text record: where the text after the word begins in [`Self::record`].
    pub fn text_at(&self) -> usize {
        self.text_at
    }

    /// What the lexer noticed about the record last returned.
    pub fn notes(&self) -> &[LexNote] {
        &self.notes
    }

    /// (offset in the record, offset in the file) of each piece of the record.
    pub fn segments(&self) -> &[(usize, usize)] {
        &self.segments
    }

    fn next_line(&mut self) -> io::Result<bool> {
        if self.held {
            self.held = false;
            return Ok(true);
        }
        match self.lines.read(&mut self.line)? {
            Some(info) => {
                self.line_info = info;
                Ok(true)
            }
            None => Ok(false),
        }
    }

    /// Appends `line[from..to]` to the record; a record that grows past
    /// [`MAX_LINE`] keeps its first mebibyte only and is reported.
    fn append(&mut self, from: usize, to: usize) {
        if self.record.len() - self.record_start + (to - from) > MAX_LINE {
            self.overflow = true;
            return;
        }
        self.segments.push((self.record.len() - self.record_start, self.line_info.start + from));
        self.record.extend_from_slice(&self.line[from..to]);
    }

    /// The next record, `None` at the end of the file.
    // Reading can fail (`io::Result<Option<_>>`), which `Iterator::next` cannot say.
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> io::Result<Option<RawKind>> {
        self.record.clear();
        self.record_start = 0;
        self.overflow = false;
        self.segments.clear();
        self.notes.clear();
        loop {
            if !self.next_line()? {
                return Ok(None);
            }
            let line_start = self.line_info.start;
            if self.line_info.too_long {
                self.span = (line_start, line_start + self.line.len());
                return Ok(Some(RawKind::TooLong));
            }
            let (a, b) = trim(&self.line);
            if a == b {
                continue;
            }
            self.span = (line_start + a, line_start + b);
            return match classify(&self.line[a..b]) {
                LineClass::Comment => self.comment(a, b).map(|k| Some(self.checked(k))),
                LineClass::Numbers => {
                    self.append(a, b);
                    Ok(Some(RawKind::Orphan))
                }
                LineClass::Text(word) => {
                    self.append(a, b);
                    self.text_at = word.name().len();
                    Ok(Some(RawKind::Text(word)))
                }
                LineClass::Statement => self.statement(a, b).map(|k| Some(self.checked(k))),
            };
        }
    }

    /// A record that overflowed is reported as too long.
    fn checked(&self, kind: RawKind) -> RawKind {
        if self.overflow { RawKind::TooLong } else { kind }
    }

    fn comment(&mut self, a: usize, b: usize) -> io::Result<RawKind> {
        self.append(a + 2, b);
        let mut continued = b - a > 2 && ends_with_single_dollar(&self.line[a..b]);
        while continued {
            self.record.pop();
            if !self.next_line()? {
                break;
            }
            let (a, b) = trim(&self.line);
            if self.line_info.too_long || a == b {
                self.held = true;
                break;
            }
            self.record.push(b' ');
            self.append(a, b);
            self.span.1 = self.line_info.start + b;
            continued = ends_with_single_dollar(&self.line[a..b]);
        }
        Ok(RawKind::Comment)
    }

    fn statement(&mut self, mut a: usize, mut b: usize) -> io::Result<RawKind> {
        loop {
            if let Some(p) = trailing_comment(&self.line[a..b]) {
                b = a + trim(&self.line[a..a + p]).1;
            }
            let continued = b > a && self.line[b - 1] == b'$';
            if b > a {
                let end = if continued { b - 1 } else { b };
                if self.segments.is_empty() {
                    // The first line: keep its buffer rather than copy it.
                    std::mem::swap(&mut self.line, &mut self.record);
                    self.record.truncate(end);
                    self.record_start = a;
                    self.segments.push((0, self.line_info.start + a));
                } else {
                    self.append(a, end);
                }
                self.span.1 = self.line_info.start + b;
            }
            if continued {
                // The record goes on at the next line that is neither blank
                // nor a comment.
                loop {
                    if !self.next_line()? {
                        self.notes.push(LexNote::EofInContinuation { at: self.span.1 });
                        return Ok(RawKind::Statement);
                    }
                    if self.line_info.too_long {
                        self.held = true;
                        return Ok(RawKind::Statement);
                    }
                    let (na, nb) = trim(&self.line);
                    if na == nb || self.line[na..nb].starts_with(b"$$") {
                        continue;
                    }
                    (a, b) = (na, nb);
                    break;
                }
                self.record.push(b' ');
                continue;
            }
            // Look ahead: a line of numbers continues this record.
            if !self.next_line()? {
                return Ok(RawKind::Statement);
            }
            let (na, nb) = trim(&self.line);
            let numbers =
                !self.line_info.too_long && na < nb && matches!(self.line[na], b'0'..=b'9' | b'+' | b'-' | b'.');
            if !numbers {
                self.held = true;
                return Ok(RawKind::Statement);
            }
            if self.record.last() != Some(&b',') {
                let start = self.line_info.start + na;
                self.notes.push(LexNote::JoinedWithoutDollar { start, end: self.line_info.start + nb });
                self.record.push(b',');
            }
            (a, b) = (na, nb);
        }
    }
}
