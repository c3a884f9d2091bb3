//! The native toolpath stream: one [`Event`] per line, as RON or as JSON
//! Lines, read from the same serde types.
//!
//! RON lines look like `Rapid(x: 0, y: 0, z: 5)` (newtype variants are
//! unwrapped and `Some` is implicit); JSON lines look like
//! `{"Rapid":{"x":0,"y":0,"z":5}}`. Blank lines and lines starting with `//`
//! (RON) are skipped. The reader holds one line at a time, so memory stays
//! flat whatever the file's length; each event carries the span of its line.

mod json_moves;

use postc_ir::codes;
use std::io::{BufRead, BufReader};

use postc_ir::source::SourceReader;
use std::path::Path;

use postc_ir::limits::{RangeCheck, Verdict};
use postc_ir::{Diagnostic, Event, EventSource, FileId, SourceMap, Span};

/// Native stream syntaxes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Syntax {
    Ron,
    JsonLines,
}

/// Reads native events from a buffered reader.
pub struct NativeReader<R> {
    input: R,
    syntax: Option<Syntax>,
    file: FileId,
    line: Vec<u8>,
    offset: usize,
    done: bool,
    ron: ron::Options,
    checks: StreamChecks,
}

/// What every native event stream checks, whatever gives the events (a
/// file here, a Python iterable in the `postc` Python package): each
/// event's ranges (TP004) and that the stream ends with `End` (TP005).
#[derive(Default)]
pub struct StreamChecks {
    ranges: RangeCheck,
    /// An `End` event was read.
    ended: bool,
    /// The end of the stream was reported.
    finished: bool,
}

/// Opens a native toolpath file; the syntax comes from the extension
/// (`.ron`, `.jsonl`, `.json`) or, failing that, from the first line.
pub fn open(path: &Path, sources: &mut SourceMap) -> Result<NativeReader<BufReader<SourceReader>>, Diagnostic> {
    let file = sources
        .loader()
        .open(path)
        .map_err(|e| Diagnostic::error(codes::IO001, format!("cannot open toolpath `{}`: {e}", path.display())))?;
    let id = sources.add_streamed(path.display().to_string());
    let syntax = match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("ron") => Some(Syntax::Ron),
        Some("jsonl") | Some("json") | Some("ndjson") => Some(Syntax::JsonLines),
        _ => None,
    };
    Ok(NativeReader::new(BufReader::with_capacity(1 << 16, file), syntax, id))
}

impl<R: BufRead> NativeReader<R> {
    pub fn new(input: R, syntax: Option<Syntax>, file: FileId) -> NativeReader<R> {
        let ron = ron::Options::default().with_default_extension(
            ron::extensions::Extensions::IMPLICIT_SOME | ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES,
        );
        NativeReader {
            input,
            syntax,
            file,
            line: Vec::new(),
            offset: 0,
            done: false,
            ron,
            checks: StreamChecks::default(),
        }
    }

    fn parse_line(&mut self, start: usize, text: &str) -> Result<Event, Diagnostic> {
        let syntax = *self.syntax.get_or_insert(if text.starts_with('{') { Syntax::JsonLines } else { Syntax::Ron });
        let line_span = Span::new(self.file, start, start + text.len());
        match syntax {
            Syntax::Ron => self.ron.from_str::<Event>(text).map_err(|e| {
                let col = e.span.start.col.saturating_sub(1).min(text.len());
                let at = Span::new(self.file, start + col, (start + col + 1).min(start + text.len()));
                Diagnostic::error(codes::TP001, format!("this toolpath line is not a valid event: {}", e.code))
                    .at(at, "here")
                    .also(line_span, "in this event")
                    .help("events look like `Feed(x: 10, y: 5, z: -1)`; docs/toolpath-format.md lists every event and field")
            }),
            Syntax::JsonLines => serde_json::from_str::<Event>(text).map_err(|e| {
                let col = e.column().saturating_sub(1).min(text.len());
                let at = Span::new(self.file, start + col, (start + col + 1).min(start + text.len()));
                Diagnostic::error(codes::TP002, format!("this JSON line is not a valid event: {e}"))
                    .at(at, "here")
                    .also(line_span, "in this event")
                    .help("events look like {\"Feed\":{\"x\":10,\"y\":5,\"z\":-1}}; docs/toolpath-format.md lists every event and field")
            }),
        }
    }
}

impl StreamChecks {
    /// Checks the next event of the stream (`None`: the stream ended at
    /// `end`, where TP005 points).
    ///
    /// Events are checked against the ranges of `postc_ir::limits` (TP004:
    /// an event out of range is an error, so the toolpath is refused; the
    /// event is still given out, so that the stream keeps its order), and a
    /// stream that ends without its `End` event is said to be perhaps cut
    /// short (TP005).
    #[inline(always)]
    pub fn check(&mut self, next: Option<&(Event, Span)>, end: Span, diagnostics: &mut Vec<Diagnostic>) {
        let Some((event, span)) = next else {
            if !self.ended && !self.finished {
                self.finished = true;
                diagnostics.push(
                    Diagnostic::warning(
                        codes::TP005,
                        "the toolpath ends without an End event: it may be cut short, and the program would end early",
                    )
                    .at(end, "the toolpath ends here")
                    .help("post the whole toolpath; if it is whole, end it with `End`"),
                );
            }
            return;
        };
        if let Verdict::Refuse(bad) = self.ranges.check(event) {
            diagnostics.push(
                Diagnostic::error(codes::TP004, format!("{}; the toolpath is refused", bad.message(event.name())))
                    .at(*span, "this event")
                    .note("postc refuses numbers no machine can reach, so that no program carries a word no controller reads (docs/toolpath-format.md, \"Ranges\")")
                    .help("correct the event; check the toolpath's units"),
            );
        }
        self.ended |= matches!(event, Event::End);
    }
}

/// Events are checked as every native stream is ([`StreamChecks`]).
impl<R: BufRead> EventSource for NativeReader<R> {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        // The event is looked at where it was read and returned as it
        // is: moving it out and back costs two copies an event.
        let next = self.next_read(diagnostics);
        let end = Span::new(self.file, self.offset, self.offset);
        self.checks.check(next.as_ref(), end, diagnostics);
        next
    }
}

impl<R: BufRead> NativeReader<R> {
    /// The next event as read, before its ranges are checked.
    #[inline(always)]
    #[doc(hidden)]
    pub fn next_read(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        while !self.done {
            // A move line whole in the input's buffer is read where it is,
            // not copied out first.
            if self.syntax != Some(Syntax::Ron)
                && let Ok(buf) = self.input.fill_buf()
                && let Some(end) = memchr::memchr(b'\n', buf)
                && let Some(found) = move_line(&buf[..end], self.offset, self.file)
            {
                self.syntax = Some(Syntax::JsonLines);
                self.input.consume(end + 1);
                self.offset += end + 1;
                return Some(found);
            }
            self.line.clear();
            let start = self.offset;
            match self.input.read_until(b'\n', &mut self.line) {
                Ok(0) => self.done = true,
                Ok(n) => {
                    self.offset += n;
                    let line = std::mem::take(&mut self.line);
                    let result = self.line_event(start, &line);
                    self.line = line;
                    match result {
                        Some(Ok(found)) => return Some(found),
                        Some(Err(d)) => diagnostics.push(d),
                        None => {}
                    }
                }
                Err(e) => {
                    self.done = true;
                    diagnostics.push(Diagnostic::error(codes::IO002, format!("cannot read the toolpath: {e}")));
                }
            }
        }
        None
    }
}

impl<R: BufRead> NativeReader<R> {
    /// The event of the line read from byte `start`: `None` for a blank or
    /// comment line. A move line of JSON Lines goes through the fast path
    /// ([`json_moves`]) before it is even checked to be UTF-8 (a line it
    /// reads is ASCII); every other line is text read by serde.
    fn line_event(&mut self, start: usize, line: &[u8]) -> Option<Result<(Event, Span), Diagnostic>> {
        if self.syntax != Some(Syntax::Ron)
            && let Some(found) = move_line(line, start, self.file)
        {
            self.syntax = Some(Syntax::JsonLines);
            return Some(Ok(found));
        }
        let Ok(line) = std::str::from_utf8(line) else {
            self.done = true;
            return Some(Err(Diagnostic::error(codes::TP003, "the toolpath is not text (it is not valid UTF-8)")
                .at(Span::new(self.file, start, start + 1), "from here on")));
        };
        let trimmed_start = line.len() - line.trim_start().len();
        let text = line.trim();
        if text.is_empty() || text.starts_with("//") || text.starts_with('#') {
            return None;
        }
        let span = Span::new(self.file, start + trimmed_start, start + trimmed_start + text.len());
        Some(self.parse_line(start + trimmed_start, text).map(|event| (event, span)))
    }
}

/// The move event of a JSON line read from byte `start`, with the span of
/// its text, when the fast path ([`json_moves`]) reads it.
fn move_line(line: &[u8], start: usize, file: FileId) -> Option<(Event, Span)> {
    let text = line.trim_ascii();
    let event = json_moves::read_move(text)?;
    let at = start + (line.len() - line.trim_ascii_start().len());
    Some((event, Span::new(file, at, at + text.len())))
}

/// Writes events as native lines in the given syntax.
pub fn write_event(event: &Event, syntax: Syntax, out: &mut String) {
    match syntax {
        Syntax::Ron => {
            let options = ron::Options::default().with_default_extension(
                ron::extensions::Extensions::IMPLICIT_SOME | ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES,
            );
            out.push_str(&options.to_string(event).unwrap_or_default());
        }
        Syntax::JsonLines => out.push_str(&serde_json::to_string(event).unwrap_or_default()),
    }
    out.push('\n');
}

/// What the tests of this crate's modules (the root suite's
/// `tests/modules/readers/native/`) reach that is not its interface: nothing
/// else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod json_moves {
        pub use crate::json_moves::read_move;
    }
}
