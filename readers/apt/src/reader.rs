//! [`AptReader`]: the streaming reader. It pulls records from the lexer,
//! parses statements with the grammar, hands them to the state machine and
//! gives out the events it makes, one at a time, with the span of the record
//! each came from. Memory stays flat: one line buffer, one record buffer,
//! one item vector and a small window of held events are reused for the
//! whole file.

use std::io::BufRead;

use chumsky::Parser;
use chumsky::inspector::TruncateState;
use postc_ir::diagnostic::{Diagnostic, FileId, Span};
use postc_ir::event::{Event, EventSource};
use postc_ir::limits::{RangeCheck, Verdict};

use crate::detect::{Content, binary_kind, sniff};
use crate::diagnostics as diag;
use crate::grammar::{self, ItemKind, Items, Shape};
use crate::lexer::{LexNote, Lexer, RawKind, TextWord};
use crate::lines::Lines;
use crate::state::{Core, Flow};
use crate::words::{Major, Rec, SpanMap, classify, upper};

/// Where the reader is in the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// The head of the file has not been looked at.
    Start,
    Reading,
    /// No more events.
    Done,
}

/// Reads an APT CL file as a stream of toolpath events.
///
/// ```
/// use postc_reader_apt::AptReader;
/// use postc_ir::{EventSource, SourceMap};
///
/// let text = "UNITS/MM\nLOADTL/1\nRAPID\nGOTO/0,0,5\nFEDRAT/300,MMPM\nGOTO/10,0,5\nFINI\n";
/// let mut sources = SourceMap::new();
/// let file = sources.add("part.cl", text);
/// let mut reader = AptReader::new(text.as_bytes(), file);
/// let mut diagnostics = Vec::new();
/// let mut names = Vec::new();
/// while let Some((event, _span)) = reader.next_event(&mut diagnostics) {
///     names.push(event.name());
/// }
/// assert_eq!(names, ["Job", "Tool", "ToolpathStart", "Rapid", "FeedRate", "Feed", "ToolpathEnd", "End"]);
/// assert!(diagnostics.is_empty());
/// ```
pub struct AptReader<R: BufRead> {
    lexer: Lexer<R>,
    items: Items,
    core: Core,
    phase: Phase,
    warned_after_fini: bool,
    part_program: bool,
    ranges: RangeCheck,
}

/// The text of a text record, from the bytes after its word.
fn record_text(word: TextWord, record: &[u8], text_at: usize) -> String {
    let rest = record.get(text_at..).unwrap_or_default();
    let body = match word {
        // INSERT is verbatim from column 7; `INSERT/text` drops the slash.
        TextWord::Insert => match rest.iter().position(|b| *b != b' ' && *b != b'\t') {
            Some(i) if rest[i] == b'/' => rest[i + 1..].trim_ascii_start(),
            _ => rest,
        },
        _ => {
            let rest = rest.trim_ascii_start();
            rest.strip_prefix(b"/").unwrap_or(rest).trim_ascii()
        }
    };
    decode(body)
}

/// Text bytes as a string: UTF-8 when they are, else Windows-1252/Latin-1.
pub(crate) fn decode(bytes: &[u8]) -> String {
    match std::str::from_utf8(bytes) {
        Ok(s) => s.to_string(),
        Err(_) => bytes.iter().map(|&b| b as char).collect(),
    }
}

/// Whether a record starts `NAME =` or `NAME(n) =`, as APT source does.
fn starts_with_assignment(text: &[u8]) -> bool {
    let name = text.iter().take_while(|b| b.is_ascii_alphanumeric() || **b == b'_').count();
    let mut rest = text[name..].trim_ascii_start();
    if rest.first() == Some(&b'(') {
        let close = rest.iter().position(|&b| b == b')').map_or(rest.len(), |i| i + 1);
        rest = rest[close..].trim_ascii_start();
    }
    name > 0 && rest.first() == Some(&b'=')
}

impl<R: BufRead> AptReader<R> {
    /// A reader over `inner`, whose spans point into `file`.
    pub fn new(inner: R, file: FileId) -> AptReader<R> {
        AptReader {
            lexer: Lexer::new(Lines::new(inner)),
            items: TruncateState(Vec::with_capacity(16)),
            core: Core::new(file),
            phase: Phase::Start,
            warned_after_fini: false,
            part_program: false,
            ranges: RangeCheck::new(),
        }
    }

    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.core.file, start, end)
    }

    /// Looks at the head of the file: binary files and part programs are
    /// refused with one error.
    fn start(&mut self, diags: &mut Vec<Diagnostic>) {
        self.phase = Phase::Reading;
        let lines = self.lexer.lines_mut();
        let head = match lines.inner_mut().fill_buf() {
            Ok(head) => head,
            Err(e) => {
                diags.push(diag::io(Span::new(self.core.file, 0, 0), &e));
                self.phase = Phase::Done;
                return;
            }
        };
        if let Some(kind) = binary_kind(head) {
            let at = head.iter().position(|&b| b == 0).unwrap_or(0);
            diags.push(diag::binary(Span::new(self.core.file, at, at + 1), kind));
            self.phase = Phase::Done;
            return;
        }
        if let Content::PartProgram(a, b) = sniff(head) {
            diags
                .push(diag::part_program(Span::new(self.core.file, a, b), "a geometry definition: CL files have none"));
            self.phase = Phase::Done;
            return;
        }
        if head.starts_with(b"\xEF\xBB\xBF") {
            lines.skip_start(3);
        }
    }

    /// Reads one record.
    fn step(&mut self, diags: &mut Vec<Diagnostic>) {
        let kind = match self.lexer.next() {
            Ok(Some(kind)) => kind,
            Ok(None) => {
                if !self.core.ended {
                    let end = self.lexer.lines_mut().offset();
                    self.core.finish(None, self.span(end, end), diags);
                    if !self.part_program && !self.core.closed_at_end {
                        diags.push(diag::no_fini(self.span(end, end)));
                    }
                }
                self.core.flush();
                self.phase = Phase::Done;
                return;
            }
            Err(e) => {
                let (_, end) = self.lexer.span();
                diags.push(diag::io(self.span(end, end), &e));
                self.core.finish(None, self.span(end, end), diags);
                self.core.flush();
                self.phase = Phase::Done;
                return;
            }
        };
        let (start, end) = self.lexer.span();
        let span = self.span(start, end);
        if self.core.ended {
            if !self.warned_after_fini && kind != RawKind::Comment {
                self.warned_after_fini = true;
                diags.push(diag::after_fini(span));
            }
            return;
        }
        for note in self.lexer.notes() {
            match *note {
                LexNote::JoinedWithoutDollar { start, end } => diags.push(diag::joined_line(self.span(start, end))),
                LexNote::EofInContinuation { at } => diags.push(diag::eof_continuation(self.span(start, at))),
            }
        }
        if kind != RawKind::Comment {
            self.core.closed_at_end = false;
        }
        match kind {
            RawKind::Statement => self.statement(span, diags),
            RawKind::Text(word) => {
                let text = record_text(word, self.lexer.record(), self.lexer.text_at());
                self.core.text_record(word, text, span, diags);
            }
            RawKind::Comment => self.comment(span),
            RawKind::Orphan => diags.push(diag::orphan_numbers(span)),
            RawKind::TooLong => diags.push(diag::long_line(self.span(start, start + 1))),
        }
    }

    /// `$$` comments: Creo's `$$*` product line and `$$-> CUTTER / d` echo.
    fn comment(&mut self, span: Span) {
        let body = self.lexer.record();
        if let Some(product) = body.strip_prefix(b"*") {
            let text = decode(product);
            self.core.product(&text);
        } else if let Some(echo) = body.strip_prefix(b"->") {
            let echo = echo.trim_ascii();
            if echo.len() >= 6 && echo[..6].eq_ignore_ascii_case(b"CUTTER") {
                self.items.0.clear();
                let parsed = grammar::record().parse_with_state(echo, &mut self.items);
                if !parsed.has_errors() {
                    let map = SpanMap { file: self.core.file, segments: &[], record: span };
                    let rec = Rec { text: echo, items: &self.items.0, heads: 1, map };
                    self.core.echoed_cutter(&rec);
                }
            }
        }
    }

    fn statement(&mut self, span: Span, diags: &mut Vec<Diagnostic>) {
        let text = self.lexer.record();
        self.items.0.clear();
        let parsed = grammar::record().parse_with_state(text, &mut self.items);
        let map = SpanMap { file: self.core.file, segments: self.lexer.segments(), record: span };
        let shape = match parsed.into_result() {
            Ok(shape) => shape,
            Err(errors) => {
                if starts_with_assignment(text) {
                    return self.part_program(span, "an assignment: CL files have none", diags);
                }
                let at = errors.first().map_or(0, |e| e.span().start);
                let (message, help) = match text.get(at) {
                    None => (
                        "this record ends where a value is expected".to_string(),
                        "a comma must be followed by a value; end a line with `$` when the record goes on at the next line",
                    ),
                    Some(b'$') => (
                        "a `$` continues a record only at the end of a line".to_string(),
                        "move the rest of the record to the next line, or remove the `$`",
                    ),
                    Some(&b) => (
                        format!("unexpected `{}` in this record", decode(&[b])),
                        "a CL record is WORD or WORD/value,value,...: values are numbers or words, separated by commas",
                    ),
                };
                diags.push(diag::syntax(map.span(at, at + 1), message, help));
                return;
            }
        };
        if shape == Shape::Assignment {
            return self.part_program(span, "an assignment: CL files have none", diags);
        }
        if self.items.0.iter().any(|i| i.kind == ItemKind::MissingComma) {
            for item in self.items.0.iter().filter(|i| i.kind == ItemKind::MissingComma) {
                diags.push(diag::missing_comma(map.span(item.start as usize, item.end as usize)));
            }
            self.items.0.retain(|i| i.kind != ItemKind::MissingComma);
        }
        let items = &self.items.0;
        let heads = items.iter().take_while(|i| i.kind == ItemKind::Head).count();
        let head = |n: usize| {
            items.get(n).filter(|_| n < heads).map_or(&b"?"[..], |i| &text[i.start as usize..i.end as usize])
        };
        let major = if heads == 1 && head(0).eq_ignore_ascii_case(b"GOTO") {
            Major::Goto
        } else {
            let (mut a, mut b) = ([0u8; 48], [0u8; 48]);
            let first = upper(head(0), &mut a).unwrap_or("?");
            let second = if heads > 1 { Some(upper(head(1), &mut b).unwrap_or("?")) } else { None };
            classify(first, second)
        };
        let rec = Rec { text, items, heads, map };
        if let Flow::PartProgram(why, at) = self.core.dispatch(major, &rec, diags) {
            self.part_program(at, why, diags);
        }
    }

    fn part_program(&mut self, span: Span, why: &str, diags: &mut Vec<Diagnostic>) {
        if !self.part_program {
            self.part_program = true;
            diags.push(diag::part_program(span, why));
        }
        self.core.window = Default::default();
        self.phase = Phase::Done;
    }
}

impl<R: BufRead> EventSource for AptReader<R> {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        loop {
            if let Some((event, span)) = self.core.out.front() {
                if let Verdict::Refuse(bad) = self.ranges.check(event) {
                    diagnostics.push(diag::out_of_range(*span, &bad, event.name()));
                }
                return self.core.out.pop_front();
            }
            match self.phase {
                Phase::Start => self.start(diagnostics),
                Phase::Reading => self.step(diagnostics),
                Phase::Done => return None,
            }
        }
    }
}
