//! The project-wide diagnostic: one type for every error and warning any
//! frontend, reader or the runtime reports. Only the edge renders it (for
//! people and as JSON: `postc_report`); this crate holds the data.
//!
//! Every diagnostic has a stable code (`PP012`), a severity, a message a
//! machinist understands, labels that point at byte spans of source files,
//! notes and an optional help line. Codes are grouped by where they come
//! from: `PP` Vectric posts, `JS` CIMCO posts, `VC` VcPost posts, `CL` APT CL
//! files, `TP` native toolpaths, `RT` the runtime, `IO` files and the
//! command line. `docs/diagnostics.md` lists them all.

use std::fmt;
use std::io::{self, Read};
use std::ops::Range;
use std::path::Path;
use std::sync::{Arc, OnceLock};

use serde::{Deserialize, Serialize};

use crate::source::{NoFiles, SourceLoader};

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

/// Files diagnostics point into, and the [`SourceLoader`] that reads more:
/// `POST_BASE` files and the lines of files streamed rather than held.
#[derive(Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
    loader: Option<Arc<dyn SourceLoader>>,
}

impl fmt::Debug for SourceMap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SourceMap").field("files", &self.files).field("loader", &self.loader.is_some()).finish()
    }
}

/// One file: its name as shown, and its text when it is held in memory.
#[derive(Debug)]
struct SourceFile {
    name: String,
    /// The text spans index into. Streamed files (large toolpaths) are not
    /// held; the edge reads their text back through the loader only to
    /// render a diagnostic.
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
    fn build(loader: &dyn SourceLoader, path: &str) -> io::Result<StreamIndex> {
        let mut file = loader.open(Path::new(path))?;
        let mut index = StreamIndex { line_starts: vec![0], non_ascii: vec![0], len: 0 };
        let mut buf = vec![0u8; 1 << 16];
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
    fn line_column(&self, loader: &dyn SourceLoader, path: &str, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.len);
        let line = self.line_starts.partition_point(|&s| s <= offset).saturating_sub(1);
        let start = self.line_starts[line];
        let ascii = self.non_ascii[line / 64] & (1 << (line % 64)) == 0;
        let column =
            if ascii { offset - start } else { chars_between(loader, path, start, offset).unwrap_or(offset - start) };
        (line + 1, column + 1)
    }
}

/// Characters between two byte offsets of one line of a file.
fn chars_between(loader: &dyn SourceLoader, path: &str, start: usize, end: usize) -> io::Result<usize> {
    let bytes = loader.read_at(Path::new(path), start as u64, (end - start) as u64)?;
    Ok(bytes.iter().filter(|&&b| b & 0xC0 != 0x80).count())
}

/// Byte offsets where the lines of a text start.
fn line_starts(text: &str) -> Vec<usize> {
    std::iter::once(0).chain(text.match_indices('\n').map(|(i, _)| i + 1)).collect()
}

impl SourceMap {
    /// A map without a loader: it holds the files it is given and reads
    /// nothing else.
    pub fn new() -> SourceMap {
        SourceMap::default()
    }

    /// A map that reads `POST_BASE` files and streamed files through `loader`.
    pub fn with_loader(loader: Arc<dyn SourceLoader>) -> SourceMap {
        SourceMap { files: Vec::new(), loader: Some(loader) }
    }

    /// The loader files are read through ([`NoFiles`] when none was given).
    pub fn loader(&self) -> &dyn SourceLoader {
        self.loader.as_deref().unwrap_or(&NoFiles)
    }

    /// The loader itself, to read files again on another map.
    pub fn shared_loader(&self) -> Option<Arc<dyn SourceLoader>> {
        self.loader.clone()
    }

    /// Adds a file whose text is held in memory.
    pub fn add(&mut self, name: impl Into<String>, text: impl Into<String>) -> FileId {
        let text = text.into();
        let line_starts = line_starts(&text);
        self.files.push(SourceFile { name: name.into(), text: Some(text), line_starts, streamed: OnceLock::new() });
        FileId(self.files.len() as u32 - 1)
    }

    /// Adds a file that is streamed (through the loader) and not held in memory.
    pub fn add_streamed(&mut self, path: impl Into<String>) -> FileId {
        self.files.push(SourceFile {
            name: path.into(),
            text: None,
            line_starts: Vec::new(),
            streamed: OnceLock::new(),
        });
        FileId(self.files.len() as u32 - 1)
    }

    /// How many files the map has.
    pub fn len(&self) -> usize {
        self.files.len()
    }

    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    pub fn name(&self, file: FileId) -> &str {
        self.files.get(file.0 as usize).map_or("<unknown>", |f| f.name.as_str())
    }

    pub fn text(&self, file: FileId) -> Option<&str> {
        self.files.get(file.0 as usize).and_then(|f| f.text.as_deref())
    }

    /// Gives a streamed file its text, read back to render a diagnostic.
    /// Files already held keep theirs.
    pub fn hold(&mut self, file: FileId, text: String) {
        if let Some(f) = self.files.get_mut(file.0 as usize)
            && f.text.is_none()
        {
            f.line_starts = line_starts(&text);
            f.text = Some(text);
        }
    }

    /// The 0-based line of a byte offset of a held file.
    pub fn line_index(&self, file: FileId, offset: usize) -> Option<usize> {
        let f = self.files.get(file.0 as usize)?;
        Some(f.line_starts.partition_point(|&s| s <= offset).saturating_sub(1))
    }

    /// The byte range of a 0-based line of a held file (with its line end),
    /// or `Err(last line)` when there is no such line.
    pub fn line_range(&self, file: FileId, line: usize) -> Option<Result<Range<usize>, usize>> {
        let f = self.files.get(file.0 as usize)?;
        let text = f.text.as_deref()?;
        let Some(&start) = f.line_starts.get(line) else {
            return Some(Err(f.line_starts.len().saturating_sub(1)));
        };
        let end = f.line_starts.get(line + 1).copied().unwrap_or(text.len());
        Some(Ok(start..end))
    }

    /// 1-based line and column (in characters) of a byte offset; positions
    /// in a streamed file are found through the map's loader.
    pub fn line_column(&self, file: FileId, offset: usize) -> Option<(usize, usize)> {
        let loader = self.loader();
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
                let index = f.streamed.get_or_init(|| StreamIndex::build(loader, &f.name).ok()).as_ref()?;
                Some(index.line_column(loader, &f.name, offset))
            }
        }
    }
}
