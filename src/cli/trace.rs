//! `postc post --trace TRACE.jsonl` and `postc explain TRACE.jsonl LINE`:
//! which post statement wrote each NC line, for which toolpath event
//! (docs/trace.md).
//!
//! While the post runs, the runtime hands each block's provenance to a
//! sink that writes it, with raw byte offsets, to a temporary file. When
//! the run succeeds, each record's offsets become file, line and column
//! (the source map knows the post's files and the toolpath) and the trace
//! is written whole beside its target, or not at all.

use postc_ir::codes;
use postc_report::Render as _;
use std::cell::RefCell;
use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::rc::Rc;

use postc_ir::{Diagnostic, HandlerKey, Label, Post, Severity, SourceMap, Span};
use postc_runtime::trace::{TraceLine, TraceSink};

use super::outputs::{Batch, Temp};
use serde::{Deserialize, Serialize};

/// A span as byte offsets, while the run goes on.
#[derive(Serialize, Deserialize, Clone, Copy)]
struct RawSpan(u32, usize, usize);

impl RawSpan {
    fn of(span: Span) -> RawSpan {
        RawSpan(span.file.0, span.start, span.end)
    }

    fn span(self) -> Span {
        Span::new(postc_ir::FileId(self.0), self.1, self.2)
    }
}

/// One record as the run writes it.
#[derive(Serialize, Deserialize)]
struct RawLine {
    part: usize,
    line: u64,
    span: Option<RawSpan>,
    calls: Vec<(u16, Option<RawSpan>)>,
    handler: Option<String>,
    handler_span: Option<RawSpan>,
    event: Option<u64>,
    event_span: Option<RawSpan>,
}

/// A place in a file, as the trace file gives it.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct Place {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
}

/// A post function on the chain of calls.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct Call {
    pub function: String,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub at: Option<Place>,
}

/// The input event a line was written for.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct EventPlace {
    /// Counted from 0 in the toolpath's event stream.
    pub index: u64,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub at: Option<Place>,
}

/// One line of the trace file: one NC line and where it came from.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct Record {
    /// The NC file the line is in (a tape-split part has its own).
    pub output: String,
    /// The line's number in that file, from 1.
    pub line: u64,
    /// The post statement that wrote it.
    pub post: Option<Place>,
    /// The section or APT word whose handler was running.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub handler: Option<String>,
    /// Post functions running, outermost first.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub calls: Vec<Call>,
    /// The toolpath event; absent for lines written before the first
    /// event or after the last (the program's start and end).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub event: Option<EventPlace>,
}

/// Collects a run's trace in a scratch file, to be written beside its
/// target when the run succeeds.
pub struct Recorder {
    target: PathBuf,
    raw: Rc<RefCell<Option<BufWriter<File>>>>,
    raw_file: Temp,
    out: Temp,
    failed: Rc<RefCell<Option<io::Error>>>,
}

impl Recorder {
    /// A recorder for a trace to be written at `target`; the trace's
    /// temporary file is created now, so a folder that cannot take it
    /// fails before the run.
    pub fn new(target: &Path) -> io::Result<Recorder> {
        let out = Temp::beside(target)?;
        let raw_file = Temp::scratch()?;
        let writer = BufWriter::new(raw_file.file()?.try_clone()?);
        Ok(Recorder {
            target: target.to_path_buf(),
            raw: Rc::new(RefCell::new(Some(writer))),
            raw_file,
            out,
            failed: Rc::new(RefCell::new(None)),
        })
    }

    /// The sink the runtime reports to.
    pub fn sink(&self) -> TraceSink {
        let raw = Rc::clone(&self.raw);
        let failed = Rc::clone(&self.failed);
        Box::new(move |t: &TraceLine<'_>| {
            let record = RawLine {
                part: t.part,
                line: t.line,
                span: t.span.map(RawSpan::of),
                calls: t.calls.iter().map(|(f, s)| (f.raw(), s.map(RawSpan::of))).collect(),
                handler: t.handler.map(handler_name),
                handler_span: t.handler_span.map(RawSpan::of),
                event: t.event,
                event_span: t.event_span.filter(|s| *s != Span::default()).map(RawSpan::of),
            };
            if let Some(w) = raw.borrow_mut().as_mut() {
                let result =
                    serde_json::to_writer(&mut *w, &record).map_err(io::Error::from).and_then(|()| w.write_all(b"\n"));
                if let Err(e) = result {
                    failed.borrow_mut().get_or_insert(e);
                }
            }
        })
    }

    /// Writes the trace: each record with places for offsets, and the
    /// names of the NC files (`outputs`, one per tape-split part), into
    /// its temporary file, which joins `batch` to be committed with the
    /// program. Returns where the temporary file is, to be read before
    /// the commit.
    pub fn finish(
        self,
        sources: &SourceMap,
        post: &Post,
        outputs: &[PathBuf],
        batch: &Batch,
    ) -> Result<PathBuf, Diagnostic> {
        let io_error = |e: io::Error| {
            Diagnostic::error(codes::IO003, format!("cannot write the trace `{}`: {e}", self.target.display()))
        };
        if let Some(mut w) = self.raw.borrow_mut().take() {
            w.flush().map_err(io_error)?;
        }
        if let Some(e) = self.failed.borrow_mut().take() {
            return Err(io_error(e));
        }
        let place = |s: RawSpan| place(sources, s.span());
        {
            let mut w = BufWriter::new(self.out.file().map_err(io_error)?);
            let raw = BufReader::new(File::open(self.raw_file.path().map_err(io_error)?).map_err(io_error)?);
            for line in raw.lines() {
                let line = line.map_err(io_error)?;
                let Ok(r) = serde_json::from_str::<RawLine>(&line) else { continue };
                let record = Record {
                    output: outputs.get(r.part).map_or_else(|| "-".to_string(), |p| p.display().to_string()),
                    line: r.line,
                    post: r.span.and_then(place),
                    handler: r.handler,
                    calls: r
                        .calls
                        .iter()
                        .map(|(f, s)| Call {
                            function: post.functions.get(usize::from(*f)).map_or_else(String::new, |f| f.name.clone()),
                            at: s.and_then(place),
                        })
                        .collect(),
                    event: r.event.map(|index| EventPlace { index, at: r.event_span.and_then(place) }),
                };
                serde_json::to_writer(&mut w, &record).map_err(|e| io_error(e.into()))?;
                w.write_all(b"\n").map_err(io_error)?;
            }
            w.flush().map_err(io_error)?;
        }
        let staged = self.out.path().map_err(io_error)?.to_path_buf();
        batch.stage(self.out, self.target);
        Ok(staged)
    }
}

/// A handler's name as the trace shows it: the Vectric section name or the
/// APT word.
fn handler_name(key: &HandlerKey) -> String {
    match key {
        HandlerKey::Section(s) => s.name().to_string(),
        HandlerKey::Word(w) => w.clone(),
    }
}

/// File, line and column of a span's start and end.
fn place(sources: &SourceMap, span: Span) -> Option<Place> {
    let (line, column) = sources.line_column(span.file, span.start)?;
    let (end_line, end_column) = sources.line_column(span.file, span.end)?;
    Some(Place { file: sources.name(span.file).to_string(), line, column, end_line, end_column })
}

/// Why one NC line exists, as text: the line, and the post statement and
/// toolpath event behind it with their source lines.
pub fn explain(trace: &Path, line: u64, output: Option<&str>, sources: &mut SourceMap) -> Result<String, Diagnostic> {
    let file = File::open(trace)
        .map_err(|e| Diagnostic::error(codes::IO001, format!("cannot read the trace `{}`: {e}", trace.display())))?;
    let mut found = None;
    let mut outputs = Vec::new();
    for (i, text) in BufReader::new(file).lines().enumerate() {
        let text =
            text.map_err(|e| Diagnostic::error(codes::IO001, format!("cannot read `{}`: {e}", trace.display())))?;
        let record: Record = serde_json::from_str(&text).map_err(|e| {
            Diagnostic::error(
                codes::IO010,
                format!("`{}` line {} is not a postc trace record: {e}", trace.display(), i + 1),
            )
            .help("write a trace with `postc post POST TOOLPATH -o OUT --trace OUT.trace.jsonl`")
        })?;
        if !outputs.contains(&record.output) {
            outputs.push(record.output.clone());
        }
        if record.line == line && output.is_none_or(|o| record.output == o || record.output.ends_with(o)) {
            found = Some(record);
            break;
        }
    }
    let Some(record) = found else {
        let help = match outputs.len() {
            0 => "the trace is empty".to_string(),
            1 => format!("the trace covers {}", outputs[0]),
            _ => format!("the trace covers {}; choose one with --output", outputs.join(", ")),
        };
        return Err(Diagnostic::error(codes::IO011, format!("line {line} is not in the trace `{}`", trace.display()))
            .help(help));
    };
    let mut text = String::new();
    let nc = read_line(Path::new(&record.output), record.line).unwrap_or_default();
    text.push_str(&format!("{}:{}: {}\n", record.output, record.line, nc.trim_end()));
    let mut labels = Vec::new();
    let mut notes = Vec::new();
    match &record.post {
        Some(p) => match span_of_place(sources, p) {
            Some(s) => labels.push(Label { span: s, message: "this wrote the line".into(), primary: true }),
            None => notes.push(format!("written by {}:{}:{}", p.file, p.line, p.column)),
        },
        None => notes.push("no post statement is known for this line (a line the runtime wrote itself)".into()),
    }
    if let Some(h) = &record.handler {
        notes.push(format!("while the post handled {h}"));
    }
    for c in &record.calls {
        match &c.at {
            Some(p) => notes.push(format!("in `{}` ({}:{}:{})", c.function, p.file, p.line, p.column)),
            None => notes.push(format!("in `{}`", c.function)),
        }
    }
    match &record.event {
        Some(e) => match e.at.as_ref().and_then(|p| span_of_place(sources, p).map(|s| (p, s))) {
            Some((_, s)) => {
                labels.push(Label { span: s, message: format!("for toolpath event {}", e.index), primary: false })
            }
            None => notes.push(format!("for toolpath event {}", e.index)),
        },
        None => notes.push("before the first toolpath event or after the last (the program's start or end)".into()),
    }
    let d = Diagnostic {
        severity: Severity::Note,
        code: "TRACE",
        message: format!("why line {} of {} exists", record.line, record.output),
        labels,
        notes,
        help: None,
    };
    text.push_str(&sources.render(&[d], false));
    Ok(text)
}

/// Adds to each finding about a line of `program` the post statement
/// that wrote the line and the toolpath event it was written for, from
/// the trace of the run that wrote the program.
pub fn annotate(
    trace: &Path,
    program: &Path,
    findings: &mut [Diagnostic],
    sources: &mut SourceMap,
) -> Result<(), Diagnostic> {
    let mut wanted: Vec<(u64, usize)> = Vec::new();
    for (i, d) in findings.iter().enumerate() {
        if let Some(span) = d.primary_span()
            && let Some((line, _)) = sources.line_column(span.file, span.start)
        {
            wanted.push((line as u64, i));
        }
    }
    let name = program.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let line_of =
        |r: &Record| Path::new(&r.output).file_name().is_some_and(|n| n.to_string_lossy() == name).then_some(r.line);
    annotate_lines(trace, wanted, &line_of, findings, sources)
}

/// [`annotate`] for findings at known program lines: `wanted` holds
/// (line, index of the finding), and `line_of` gives the line of the
/// program a trace record is about, in the same numbering (`None` for a
/// record about another program).
pub fn annotate_lines(
    trace: &Path,
    mut wanted: Vec<(u64, usize)>,
    line_of: &dyn Fn(&Record) -> Option<u64>,
    findings: &mut [Diagnostic],
    sources: &mut SourceMap,
) -> Result<(), Diagnostic> {
    let read_error = |e: &dyn std::fmt::Display| {
        Diagnostic::error(codes::IO001, format!("cannot read the trace `{}`: {e}", trace.display()))
    };
    if wanted.is_empty() {
        return Ok(());
    }
    wanted.sort_unstable();
    let file = File::open(trace).map_err(|e| read_error(&e))?;
    for text in BufReader::new(file).lines() {
        let text = text.map_err(|e| read_error(&e))?;
        let record: Record = serde_json::from_str(&text).map_err(|e| read_error(&e))?;
        let Some(line) = line_of(&record) else { continue };
        let from = wanted.partition_point(|w| w.0 < line);
        for &(_, i) in wanted[from..].iter().take_while(|w| w.0 == line) {
            let d = &mut findings[i];
            if let Some(p) = &record.post {
                match span_of_place(sources, p) {
                    Some(s) => d.labels.push(Label {
                        span: s,
                        message: "the post wrote this line here".into(),
                        primary: false,
                    }),
                    None => d.notes.push(format!("the post wrote this line at {}:{}:{}", p.file, p.line, p.column)),
                }
            }
            if let Some(h) = &record.handler {
                d.notes.push(format!("while the post handled {h}"));
            }
            if let Some(e) = &record.event {
                match e.at.as_ref().and_then(|p| span_of_place(sources, p)) {
                    Some(s) => {
                        d.labels.push(Label { span: s, message: format!("toolpath event {}", e.index), primary: false })
                    }
                    None => d.notes.push(format!("for toolpath event {}", e.index)),
                }
            }
        }
    }
    Ok(())
}

/// Line `n` (from 1) of a file.
fn read_line(path: &Path, n: u64) -> Option<String> {
    let file = File::open(path).ok()?;
    let mut reader = BufReader::new(file);
    let mut buf = Vec::new();
    for _ in 0..n {
        buf.clear();
        if reader.read_until(b'\n', &mut buf).ok()? == 0 {
            return None;
        }
    }
    Some(String::from_utf8_lossy(&buf).into_owned())
}

/// The span of a place, with its file loaded into the source map.
fn span_of_place(sources: &mut SourceMap, p: &Place) -> Option<Span> {
    let text = std::fs::read(&p.file).ok()?;
    let text = String::from_utf8_lossy(&text).into_owned();
    let start = offset_of(&text, p.line, p.column)?;
    let end = offset_of(&text, p.end_line, p.end_column).unwrap_or(start).max(start);
    let file = sources.add(p.file.clone(), text);
    Some(Span::new(file, start, end))
}

/// The byte offset of a 1-based line and column (in characters).
fn offset_of(text: &str, line: usize, column: usize) -> Option<usize> {
    let mut start = 0;
    for _ in 1..line {
        start += text[start..].find('\n')? + 1;
    }
    let rest = &text[start..];
    let col = rest.char_indices().nth(column.saturating_sub(1)).map_or(rest.len(), |(i, _)| i);
    Some(start + col)
}
