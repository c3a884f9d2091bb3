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
            ranges: RangeCheck::new(),
            ended: false,
            finished: false,
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

/// Events are checked against the ranges of `postc_ir::limits` (TP004:
/// an event out of range is an error, so the toolpath is refused; the
/// event is still given out, so that the stream keeps its order), and a
/// stream that ends without its `End` event is said to be perhaps cut
/// short (TP005).
impl<R: BufRead> EventSource for NativeReader<R> {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        // The event is looked at where it was read and returned as it
        // is: moving it out and back costs two copies an event.
        let next = self.next_read(diagnostics);
        let Some((event, span)) = &next else {
            if !self.ended && !self.finished {
                self.finished = true;
                let end = Span::new(self.file, self.offset, self.offset);
                diagnostics.push(
                    Diagnostic::warning(
                        codes::TP005,
                        "the toolpath ends without an End event: it may be cut short, and the program would end early",
                    )
                    .at(end, "the toolpath ends here")
                    .help("post the whole toolpath; if it is whole, end it with `End`"),
                );
            }
            return None;
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
        next
    }
}

impl<R: BufRead> NativeReader<R> {
    /// The next event as read, before its ranges are checked.
    #[inline(always)]
    fn next_read(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use postc_ir::event::{FeedMove, Move};

    /// The events of `text` as read, before ranges and the end are checked:
    /// these tests read fragments of toolpaths, and doubles of any size.
    fn read(text: &str, syntax: Option<Syntax>) -> (Vec<Event>, Vec<Diagnostic>) {
        let mut sources = SourceMap::new();
        let id = sources.add("t", text);
        let mut reader = NativeReader::new(text.as_bytes(), syntax, id);
        let mut diags = Vec::new();
        let mut events = Vec::new();
        while let Some((e, _)) = reader.next_read(&mut diags) {
            events.push(e);
        }
        (events, diags)
    }

    /// The events of `text` as a reader gives them out, with their checks.
    fn read_checked(text: &str) -> (Vec<Event>, Vec<(&'static str, usize)>) {
        let mut reader = NativeReader::new(text.as_bytes(), None, FileId(0));
        let (mut events, mut diags) = (Vec::new(), Vec::new());
        while let Some((e, _)) = reader.next_event(&mut diags) {
            events.push(e);
        }
        let line = |d: &Diagnostic| {
            let at = d.primary_span().map_or(0, |s| s.start);
            text[..at].matches('\n').count() + 1
        };
        (events, diags.iter().map(|d| (d.code, line(d))).collect())
    }

    /// Coordinates, feeds and speeds no machine can reach are refused at
    /// their line (TP004), in the job's units, in both syntaxes; a feed
    /// repeated unchanged is reported once.
    #[test]
    fn values_out_of_range_are_refused_at_their_line() {
        let ron = "Job(units: Mm)\nRapid(x: 1e308, y: 5, z: 0)\nFeed(x: 1, y: 2, z: 3, feed: -1)\nFeed(x: 2, y: 2, z: 3, feed: -1)\nSpindleOn(speed: 2e6)\nRapid(x: 1, y: 2, z: 3)\nEnd\n";
        let (events, diags) = read_checked(ron);
        assert_eq!(diags, [("TP004", 2), ("TP004", 3), ("TP004", 5)]);
        assert_eq!(events.len(), 7, "the events keep their order; the errors refuse the toolpath");
        let json = "{\"Job\":{\"units\":\"Inch\"}}\n{\"Rapid\":{\"x\":39000,\"y\":0,\"z\":0}}\n{\"Rapid\":{\"x\":40000,\"y\":0,\"z\":0}}\n\"End\"\n";
        let (events, diags) = read_checked(json);
        assert_eq!(diags, [("TP004", 3)], "40,000 inches is over 1 km; 39,000 is not");
        assert_eq!(events.len(), 4);
    }

    /// A toolpath without its `End` may be cut short (TP005), at its end;
    /// one with it is whole.
    #[test]
    fn a_toolpath_without_end_may_be_cut_short() {
        let whole = "{\"Job\":{}}\n{\"Rapid\":{\"x\":0,\"y\":0,\"z\":5}}\n\"End\"\n";
        assert_eq!(read_checked(whole).1, []);
        let cut = "{\"Job\":{}}\n{\"Rapid\":{\"x\":0,\"y\":0,\"z\":5}}\n{\"Feed\":{\"x\":1,\"y\":0,\"z\":5}}\n";
        assert_eq!(read_checked(cut).1, [("TP005", 4)]);
        assert_eq!(read_checked("Job()\nRapid(x: 0, y: 0, z: 5)").1, [("TP005", 2)]);
    }

    #[test]
    fn ron_and_json_read_the_same_events() {
        let ron = "// a job\nJob(units: Inch)\n\nRapid(x: 1, y: 2, z: 3)\nFeed(x: 1, y: 2, z: -1, intent: Plunge, feed: 5)\nToolpathEnd\n";
        let json = "{\"Job\":{\"units\":\"Inch\"}}\n{\"Rapid\":{\"x\":1,\"y\":2,\"z\":3}}\n{\"Feed\":{\"x\":1,\"y\":2,\"z\":-1,\"intent\":\"Plunge\",\"feed\":5}}\n\"ToolpathEnd\"\n";
        let (a, da) = read(ron, None);
        let (b, db) = read(json, None);
        assert!(da.is_empty() && db.is_empty(), "{da:?} {db:?}");
        assert_eq!(a, b);
        assert_eq!(a[1], Event::Rapid(Move { x: 1.0, y: 2.0, z: 3.0, ..Move::default() }));
        assert!(matches!(a[2], Event::Feed(FeedMove { intent: postc_ir::event::Intent::Plunge, feed: Some(5.0), .. })));
    }

    /// Move lines read in the input's buffer or copied out of it (a line
    /// across the buffer's end, the last line without a newline) read the
    /// same events with the same spans.
    #[test]
    fn lines_across_the_buffer_read_the_same() {
        let text = "{\"Rapid\":{\"x\":1,\"y\":2,\"z\":3}}\r\n  {\"Feed\":{\"x\":1.5,\"y\":2,\"z\":-1,\"intent\":\"Plunge\"}}\n\n{\"Feed\":{\"x\":1,\"y\":2}}\n\"ToolpathEnd\"\n{\"Arc\":{\"dir\":\"Ccw\",\"x\":0,\"y\":0,\"z\":0,\"cx\":1,\"cy\":1}}";
        let read_with = |capacity: usize| {
            let mut reader = NativeReader::new(BufReader::with_capacity(capacity, text.as_bytes()), None, FileId(0));
            let (mut found, mut diags) = (Vec::new(), Vec::new());
            while let Some(e) = reader.next_read(&mut diags) {
                found.push(e);
            }
            (found, diags.iter().map(|d| (d.code, d.labels.first().map(|l| l.span))).collect::<Vec<_>>())
        };
        let whole = read_with(1 << 16);
        assert_eq!(whole.0.len(), 4, "{whole:?}");
        assert_eq!(whole.1.len(), 1, "{whole:?}");
        for capacity in [1, 7, 16, 40, 64] {
            assert_eq!(read_with(capacity), whole, "buffer of {capacity} bytes");
        }
    }

    #[test]
    fn bad_lines_are_reported_and_skipped() {
        let (events, diags) =
            read("Rapid(x: 1, y: 2, z: 3)\nRapid(x: 1, y: 2\nFeed(x: 1, y: 2, z: 0, speed: 3)\nEnd\n", None);
        assert_eq!(events.len(), 2);
        assert_eq!(diags.len(), 2);
        assert!(diags.iter().all(|d| d.code == "TP001"));
    }

    #[test]
    fn written_events_read_back() {
        let events =
            vec![Event::Rapid(Move { x: 1.5, y: -2.0, z: 3.0, a: Some(90.0), ..Move::default() }), Event::ToolpathEnd];
        for syntax in [Syntax::Ron, Syntax::JsonLines] {
            let mut text = String::new();
            for e in &events {
                write_event(e, syntax, &mut text);
            }
            let (back, diags) = read(&text, Some(syntax));
            assert!(diags.is_empty(), "{text}: {diags:?}");
            assert_eq!(back, events, "{text}");
        }
    }

    /// What a toolpath wrote: `FeedRate`, a placed `Coolant` and a
    /// `Tool`'s `load` read in both syntaxes, in the forms
    /// docs/toolpath-format.md gives, and write back the same; a bare
    /// `Coolant(Flood)` and a `Tool` without `load` write as they always did.
    #[test]
    fn written_feed_coolant_placement_and_tool_load() {
        use postc_ir::event::{Coolant, CoolantAt, CoolantChange, FeedRate, FeedUnit, Tool, ToolLoad};
        let ron = "FeedRate(value: 0.1, unit: Ipr)\nCoolant(coolant: Flood, at: Now)\nCoolant(Mist)\nTool(number: 3, load: (length_offset: 3))\n";
        let json = "{\"FeedRate\":{\"value\":0.1,\"unit\":\"Ipr\"}}\n{\"Coolant\":{\"coolant\":\"Flood\",\"at\":\"Now\"}}\n{\"Coolant\":\"Mist\"}\n{\"Tool\":{\"number\":3,\"load\":{\"length_offset\":3}}}\n";
        let expected = vec![
            Event::FeedRate(FeedRate { value: 0.1, unit: Some(FeedUnit::Ipr) }),
            Event::Coolant(CoolantChange { coolant: Coolant::Flood, at: Some(CoolantAt::Now) }),
            Event::Coolant(Coolant::Mist.into()),
            Event::Tool(Tool {
                number: 3,
                load: Some(Box::new(ToolLoad { length_offset: Some(3), diameter_offset: None })),
                ..Tool::default()
            }),
        ];
        for (text, syntax) in [(ron, Syntax::Ron), (json, Syntax::JsonLines)] {
            let (events, diags) = read(text, Some(syntax));
            assert!(diags.is_empty(), "{text}: {diags:?}");
            assert_eq!(events, expected, "{text}");
            let mut again = String::new();
            for e in &events {
                write_event(e, syntax, &mut again);
            }
            let (back, diags) = read(&again, Some(syntax));
            assert!(diags.is_empty(), "{again}: {diags:?}");
            assert_eq!(back, expected, "{again}");
        }
        let mut bare = String::new();
        write_event(&Event::Coolant(Coolant::Flood.into()), Syntax::JsonLines, &mut bare);
        write_event(&Event::Tool(Tool { number: 1, ..Tool::default() }), Syntax::JsonLines, &mut bare);
        assert!(bare.starts_with("{\"Coolant\":\"Flood\"}\n") && !bare.contains("load"), "{bare}");
    }

    /// A JSON number is read as the double nearest to
    /// its decimal text, as RON and Rust read it, not the next one.
    #[test]
    fn json_numbers_are_read_correctly_rounded() {
        let (json, dj) = read("{\"Rapid\":{\"x\":36.207499999999996,\"y\":0,\"z\":0}}\n", None);
        let (ron, dr) = read("Rapid(x: 36.207499999999996, y: 0, z: 0)\n", None);
        assert!(dj.is_empty() && dr.is_empty());
        let x = |e: &Event| match e {
            Event::Rapid(m) => m.x,
            _ => panic!("{e:?}"),
        };
        assert_eq!(x(&json[0]).to_bits(), 36.207499999999996f64.to_bits());
        assert_eq!(x(&json[0]).to_bits(), x(&ron[0]).to_bits());
        assert!(x(&json[0]) < 36.2075);
    }

    proptest::proptest! {
        /// Any finite double, written as JSON by the writer or as a long
        /// decimal or exponent text, reads back as the same bits as
        /// Rust's own correctly rounded parse of that text.
        #[test]
        fn json_doubles_read_back_exactly(bits in proptest::num::u64::ANY, digits in 0usize..30) {
            let x = f64::from_bits(bits);
            proptest::prop_assume!(x.is_finite());
            let event = Event::Rapid(Move { x, ..Move::default() });
            let mut line = String::new();
            write_event(&event, Syntax::JsonLines, &mut line);
            let (back, diags) = read(&line, Some(Syntax::JsonLines));
            proptest::prop_assert!(diags.is_empty(), "{line}: {diags:?}");
            proptest::prop_assert_eq!(back.len(), 1);
            match &back[0] {
                Event::Rapid(m) => proptest::prop_assert_eq!(m.x.to_bits(), x.to_bits(), "{}", line),
                e => proptest::prop_assert!(false, "{e:?}"),
            }
            for text in [format!("{x:.digits$e}"), format!("{:.digits$}", x.abs().clamp(1e-30, 1e30) * x.signum())] {
                let expected: f64 = text.parse().unwrap();
                let line = format!("{{\"Rapid\":{{\"x\":{text},\"y\":0,\"z\":0}}}}\n");
                let (back, diags) = read(&line, Some(Syntax::JsonLines));
                proptest::prop_assert!(diags.is_empty(), "{line}: {diags:?}");
                match &back[0] {
                    Event::Rapid(m) => proptest::prop_assert_eq!(m.x.to_bits(), expected.to_bits(), "{}", line),
                    e => proptest::prop_assert!(false, "{e:?}"),
                }
            }
        }
    }
}
