//! Diagnostics rendered for people and as JSON.

use std::path::Path;

use codespan_reporting::diagnostic as cs;
use codespan_reporting::files;
use postc_ir::{Diagnostic, FileId, Severity, SourceMap};
use serde::{Deserialize, Serialize};

/// Files larger than this are not read back to render a snippet.
const MAX_RENDER_READ: u64 = 64 << 20;

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

/// Rendering diagnostics against the files of a [`SourceMap`].
pub trait Render {
    /// Renders diagnostics for people, with source snippets where the text
    /// is at hand (streamed files small enough are read back through the
    /// map's loader).
    fn render(&mut self, diagnostics: &[Diagnostic], color: bool) -> String;

    /// The JSON form of a diagnostic; `fallback_file` names it when it has
    /// no span.
    fn to_json(&self, d: &Diagnostic, fallback_file: &str) -> JsonDiagnostic;
}

impl Render for SourceMap {
    fn render(&mut self, diagnostics: &[Diagnostic], color: bool) -> String {
        load_for(self, diagnostics);
        let config = codespan_reporting::term::Config::default();
        let mut out = String::new();
        for d in diagnostics {
            out.push_str(&render_one(self, d, &config, color));
        }
        out
    }

    fn to_json(&self, d: &Diagnostic, fallback_file: &str) -> JsonDiagnostic {
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
}

/// Reads back streamed files that diagnostics point into, so that they
/// render with snippets. Large files stay out; they render as locations.
fn load_for(sources: &mut SourceMap, diagnostics: &[Diagnostic]) {
    for d in diagnostics {
        for l in &d.labels {
            let file = l.span.file;
            if file.0 as usize >= sources.len() || sources.text(file).is_some() {
                continue;
            }
            let path = Path::new(sources.name(file)).to_path_buf();
            let loader = sources.loader();
            if !loader.len(&path).is_ok_and(|len| len <= MAX_RENDER_READ) {
                continue;
            }
            if let Ok(bytes) = loader.read(&path) {
                let text = String::from_utf8_lossy(&bytes).into_owned();
                sources.hold(file, text);
            }
        }
    }
}

fn render_one(sources: &SourceMap, d: &Diagnostic, config: &codespan_reporting::term::Config, color: bool) -> String {
    let snippets = d.labels.iter().all(|l| sources.text(l.span.file).is_some());
    if !snippets {
        let mut s = format!("{}[{}]: {}\n", d.severity, d.code, d.message);
        for l in &d.labels {
            let (line, col) = sources.line_column(l.span.file, l.span.start).unwrap_or((0, 0));
            s.push_str(&format!("  --> {}:{}:{}: {}\n", sources.name(l.span.file), line, col, l.message));
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
    let files = Files(sources);
    let mut buffer = Vec::new();
    let result = if color {
        let mut writer = codespan_reporting::term::termcolor::Ansi::new(&mut buffer);
        codespan_reporting::term::emit_to_write_style(&mut writer, config, &files, &diagnostic)
    } else {
        codespan_reporting::term::emit_to_io_write(&mut buffer, config, &files, &diagnostic)
    };
    match result {
        Ok(()) => String::from_utf8_lossy(&buffer).into_owned(),
        Err(_) => format!("{}[{}]: {}\n", d.severity, d.code, d.message),
    }
}

/// The files of a map as codespan-reporting reads them.
struct Files<'m>(&'m SourceMap);

impl<'a> files::Files<'a> for Files<'_> {
    type FileId = FileId;
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        Ok(self.0.name(id))
    }

    fn source(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        self.0.text(id).ok_or(files::Error::FileMissing)
    }

    fn line_index(&'a self, id: FileId, byte_index: usize) -> Result<usize, files::Error> {
        self.0.line_index(id, byte_index).ok_or(files::Error::FileMissing)
    }

    fn line_range(&'a self, id: FileId, line_index: usize) -> Result<std::ops::Range<usize>, files::Error> {
        match self.0.line_range(id, line_index) {
            None => Err(files::Error::FileMissing),
            Some(Ok(range)) => Ok(range),
            Some(Err(max)) => Err(files::Error::LineTooLarge { given: line_index, max }),
        }
    }
}
