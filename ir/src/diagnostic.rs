//! The project-wide diagnostic: one type for every error and warning any
//! frontend, reader or the runtime reports, rendered with
//! codespan-reporting for people and as JSON for tools.
//!
//! Every diagnostic has a stable code (`PP012`), a severity, a message a
//! machinist understands, labels that point at byte spans of source files,
//! notes and an optional help line. Codes are grouped by where they come
//! from: `PP` Vectric posts, `JS` CIMCO posts, `VC` VcPost posts, `CL` APT CL
//! files, `TP` native toolpaths, `RT` the runtime, `IO` files and the
//! command line. `docs/diagnostics.md` lists them all.

use std::fmt;
use std::io::{self, Read, Seek, SeekFrom};
use std::path::Path;
use std::sync::OnceLock;

use codespan_reporting::diagnostic as cs;
use codespan_reporting::files::{self, Files};
use serde::{Deserialize, Serialize};

/// Identifies a file in a [`SourceMap`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct FileId(pub u32);

/// A byte range of a source file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Span {
    pub file: FileId,
    pub start: usize,
    pub end: usize,
}

impl Span {
    pub fn new(file: FileId, start: usize, end: usize) -> Span {
        Span { file, start, end: end.max(start) }
    }

    /// The smallest span that covers both.
    pub fn to(self, other: Span) -> Span {
        Span::new(self.file, self.start.min(other.start), self.end.max(other.end))
    }
}

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Note,
    Warning,
    Error,
}

impl fmt::Display for Severity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Severity::Note => "note",
            Severity::Warning => "warning",
            Severity::Error => "error",
        })
    }
}

/// A span with a message.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Label {
    pub span: Span,
    pub message: String,
    /// The primary label is where the problem is; secondary labels add context.
    pub primary: bool,
}

/// One error, warning or note.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Diagnostic {
    /// Stable code, such as `PP012`.
    pub code: &'static str,
    pub severity: Severity,
    pub message: String,
    pub labels: Vec<Label>,
    pub notes: Vec<String>,
    pub help: Option<String>,
}

impl Diagnostic {
    /// A diagnostic of `code`: a registry entry (`codes::PP012`) or its
    /// identifier. Debug builds check that the code is in the registry
    /// (`crate::codes`) with this severity.
    pub fn new(severity: Severity, code: impl Into<&'static str>, message: impl Into<String>) -> Diagnostic {
        let code = code.into();
        debug_assert!(
            crate::codes::severity_ok(code, severity),
            "diagnostic {code} reported as {severity}: not so in the registry (ir/src/codes.rs)"
        );
        Diagnostic { code, severity, message: message.into(), labels: Vec::new(), notes: Vec::new(), help: None }
    }

    pub fn error(code: impl Into<&'static str>, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Error, code, message)
    }

    pub fn warning(code: impl Into<&'static str>, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Warning, code, message)
    }

    /// Adds the primary label.
    pub fn at(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.labels.push(Label { span, message: message.into(), primary: true });
        self
    }

    /// Adds a secondary label.
    pub fn also(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.labels.push(Label { span, message: message.into(), primary: false });
        self
    }

    pub fn note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    pub fn help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// The primary label's span, if any.
    pub fn primary_span(&self) -> Option<Span> {
        self.labels.iter().find(|l| l.primary).or(self.labels.first()).map(|l| l.span)
    }
}

/// Whether any diagnostic in the list is an error.
pub fn has_errors(diagnostics: &[Diagnostic]) -> bool {
    diagnostics.iter().any(Diagnostic::is_error)
}

/// Files diagnostics point into.
#[derive(Debug, Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

/// One file: its name as shown, and its text when it is held in memory.
#[derive(Debug)]
struct SourceFile {
    name: String,
    /// The text spans index into. Streamed files (large toolpaths) are not
    /// held; their text is read back from `name` only to render a diagnostic.
    text: Option<String>,
    line_starts: Vec<usize>,
    /// The line index of a streamed file, built by one pass over it the
    /// first time a diagnostic's position in it is asked for, so that every
    /// position costs a binary search whatever its place in the file.
    streamed: OnceLock<Option<StreamIndex>>,
}

/// Where the lines of a streamed file start, and which lines hold bytes
/// outside ASCII (only there must a column be counted in characters by
/// reading the line back).
#[derive(Debug, Default)]
struct StreamIndex {
    line_starts: Vec<usize>,
    /// One bit per line: set when the line has a byte outside ASCII.
    non_ascii: Vec<u64>,
    len: usize,
}

impl StreamIndex {
    fn build(path: &str) -> io::Result<StreamIndex> {
        let mut file = io::BufReader::with_capacity(1 << 16, std::fs::File::open(Path::new(path))?);
        let mut index = StreamIndex { line_starts: vec![0], non_ascii: vec![0], len: 0 };
        let mut buf = [0u8; 1 << 16];
        loop {
            let n = match file.read(&mut buf) {
                Ok(0) => break,
                Ok(n) => n,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            };
            for (i, &b) in buf[..n].iter().enumerate() {
                if b == b'\n' {
                    index.line_starts.push(index.len + i + 1);
                    let line = index.line_starts.len() - 1;
                    if line / 64 >= index.non_ascii.len() {
                        index.non_ascii.push(0);
                    }
                } else if b >= 0x80 {
                    let line = index.line_starts.len() - 1;
                    index.non_ascii[line / 64] |= 1 << (line % 64);
                }
            }
            index.len += n;
        }
        Ok(index)
    }

    /// 1-based line and column (in characters) of a byte offset.
    fn line_column(&self, path: &str, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.len);
        let line = self.line_starts.partition_point(|&s| s <= offset).saturating_sub(1);
        let start = self.line_starts[line];
        let ascii = self.non_ascii[line / 64] & (1 << (line % 64)) == 0;
        let column = if ascii { offset - start } else { chars_between(path, start, offset).unwrap_or(offset - start) };
        (line + 1, column + 1)
    }
}

/// Characters between two byte offsets of one line of a file.
fn chars_between(path: &str, start: usize, end: usize) -> io::Result<usize> {
    let mut file = std::fs::File::open(Path::new(path))?;
    file.seek(SeekFrom::Start(start as u64))?;
    let mut bytes = Vec::with_capacity(end - start);
    file.take((end - start) as u64).read_to_end(&mut bytes)?;
    Ok(bytes.iter().filter(|&&b| b & 0xC0 != 0x80).count())
}

/// Files larger than this are not read back to render a snippet.
const MAX_RENDER_READ: u64 = 64 << 20;

impl SourceMap {
    pub fn new() -> SourceMap {
        SourceMap::default()
    }

    /// Adds a file whose text is held in memory.
    pub fn add(&mut self, name: impl Into<String>, text: impl Into<String>) -> FileId {
        let text = text.into();
        let line_starts = files::line_starts(&text).collect();
        self.files.push(SourceFile { name: name.into(), text: Some(text), line_starts, streamed: OnceLock::new() });
        FileId(self.files.len() as u32 - 1)
    }

    /// Adds a file that is streamed from disk and not held in memory.
    pub fn add_streamed(&mut self, path: impl Into<String>) -> FileId {
        self.files.push(SourceFile {
            name: path.into(),
            text: None,
            line_starts: Vec::new(),
            streamed: OnceLock::new(),
        });
        FileId(self.files.len() as u32 - 1)
    }

    pub fn name(&self, file: FileId) -> &str {
        self.files.get(file.0 as usize).map_or("<unknown>", |f| f.name.as_str())
    }

    pub fn text(&self, file: FileId) -> Option<&str> {
        self.files.get(file.0 as usize).and_then(|f| f.text.as_deref())
    }

    /// Reads back streamed files that diagnostics point into, so that they
    /// render with snippets. Large files stay out; they render as locations.
    fn load_for(&mut self, diagnostics: &[Diagnostic]) {
        for d in diagnostics {
            for l in &d.labels {
                let Some(f) = self.files.get_mut(l.span.file.0 as usize) else { continue };
                if f.text.is_some() {
                    continue;
                }
                let small = std::fs::metadata(&f.name).map(|m| m.len() <= MAX_RENDER_READ);
                if let (Ok(true), Ok(bytes)) = (small, std::fs::read(&f.name)) {
                    let text = String::from_utf8_lossy(&bytes).into_owned();
                    f.line_starts = files::line_starts(&text).collect();
                    f.text = Some(text);
                }
            }
        }
    }

    /// 1-based line and column (in characters) of a byte offset.
    pub fn line_column(&self, file: FileId, offset: usize) -> Option<(usize, usize)> {
        let f = self.files.get(file.0 as usize)?;
        match &f.text {
            Some(text) => {
                let offset = offset.min(text.len());
                let line = f.line_starts.partition_point(|&s| s <= offset).saturating_sub(1);
                let start = f.line_starts[line];
                let column = text.get(start..offset).map_or(offset - start, |s| s.chars().count());
                Some((line + 1, column + 1))
            }
            None => {
                let index = f.streamed.get_or_init(|| StreamIndex::build(&f.name).ok()).as_ref()?;
                Some(index.line_column(&f.name, offset))
            }
        }
    }
}

impl<'a> Files<'a> for SourceMap {
    type FileId = FileId;
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        Ok(self.name(id))
    }

    fn source(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        self.text(id).ok_or(files::Error::FileMissing)
    }

    fn line_index(&'a self, id: FileId, byte_index: usize) -> Result<usize, files::Error> {
        let f = self.files.get(id.0 as usize).ok_or(files::Error::FileMissing)?;
        Ok(f.line_starts.partition_point(|&s| s <= byte_index).saturating_sub(1))
    }

    fn line_range(&'a self, id: FileId, line_index: usize) -> Result<std::ops::Range<usize>, files::Error> {
        let f = self.files.get(id.0 as usize).ok_or(files::Error::FileMissing)?;
        let text = f.text.as_deref().ok_or(files::Error::FileMissing)?;
        let start = *f
            .line_starts
            .get(line_index)
            .ok_or(files::Error::LineTooLarge { given: line_index, max: f.line_starts.len().saturating_sub(1) })?;
        let end = f.line_starts.get(line_index + 1).copied().unwrap_or(text.len());
        Ok(start..end)
    }
}

/// One diagnostic as `check --format json` prints it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct JsonDiagnostic {
    pub file: String,
    pub severity: Severity,
    pub code: String,
    pub message: String,
    pub line: Option<usize>,
    pub column: Option<usize>,
    pub end_line: Option<usize>,
    pub end_column: Option<usize>,
}

impl SourceMap {
    /// The JSON form of a diagnostic; `fallback_file` names it when it has
    /// no span.
    pub fn to_json(&self, d: &Diagnostic, fallback_file: &str) -> JsonDiagnostic {
        let span = d.primary_span();
        let start = span.and_then(|s| self.line_column(s.file, s.start));
        let end = span.and_then(|s| self.line_column(s.file, s.end));
        JsonDiagnostic {
            file: span.map_or(fallback_file.to_string(), |s| self.name(s.file).to_string()),
            severity: d.severity,
            code: d.code.to_string(),
            message: d.message.clone(),
            line: start.map(|p| p.0),
            column: start.map(|p| p.1),
            end_line: end.map(|p| p.0),
            end_column: end.map(|p| p.1),
        }
    }

    /// Renders diagnostics for people, with source snippets where the text
    /// is at hand.
    pub fn render(&mut self, diagnostics: &[Diagnostic], color: bool) -> String {
        self.load_for(diagnostics);
        let config = codespan_reporting::term::Config::default();
        let mut out = Vec::new();
        for d in diagnostics {
            let rendered = self.render_one(d, &config, color);
            out.extend_from_slice(rendered.as_bytes());
        }
        String::from_utf8_lossy(&out).into_owned()
    }

    fn render_one(&self, d: &Diagnostic, config: &codespan_reporting::term::Config, color: bool) -> String {
        let snippets = d.labels.iter().all(|l| self.text(l.span.file).is_some());
        if !snippets {
            let mut s = format!("{}[{}]: {}\n", d.severity, d.code, d.message);
            for l in &d.labels {
                let (line, col) = self.line_column(l.span.file, l.span.start).unwrap_or((0, 0));
                s.push_str(&format!("  --> {}:{}:{}: {}\n", self.name(l.span.file), line, col, l.message));
            }
            for n in &d.notes {
                s.push_str(&format!("  = note: {n}\n"));
            }
            if let Some(h) = &d.help {
                s.push_str(&format!("  = help: {h}\n"));
            }
            return s;
        }
        let severity = match d.severity {
            Severity::Error => cs::Severity::Error,
            Severity::Warning => cs::Severity::Warning,
            Severity::Note => cs::Severity::Note,
        };
        let mut notes = d.notes.clone();
        if let Some(h) = &d.help {
            notes.push(format!("help: {h}"));
        }
        let diagnostic = cs::Diagnostic::new(severity)
            .with_code(d.code)
            .with_message(&d.message)
            .with_labels(
                d.labels
                    .iter()
                    .map(|l| {
                        let style = if l.primary { cs::LabelStyle::Primary } else { cs::LabelStyle::Secondary };
                        cs::Label::new(style, l.span.file, l.span.start..l.span.end).with_message(&l.message)
                    })
                    .collect(),
            )
            .with_notes(notes);
        let mut buffer = Vec::new();
        let result = if color {
            let mut writer = codespan_reporting::term::termcolor::Ansi::new(&mut buffer);
            codespan_reporting::term::emit_to_write_style(&mut writer, config, self, &diagnostic)
        } else {
            codespan_reporting::term::emit_to_io_write(&mut buffer, config, self, &diagnostic)
        };
        match result {
            Ok(()) => String::from_utf8_lossy(&buffer).into_owned(),
            Err(_) => format!("{}[{}]: {}\n", d.severity, d.code, d.message),
        }
    }
}
