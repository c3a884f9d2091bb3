//! Diagnostics rendered for people and as JSON.

use std::collections::HashMap;
use std::path::Path;

use codespan_reporting::diagnostic as cs;
use codespan_reporting::files;
use postc_ir::{Diagnostic, FileId, Severity, SourceMap};
use serde::{Deserialize, Serialize};

use crate::display::{self, Side, escape_text};

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
        let mut s = format!("{}[{}]: {}\n", d.severity, d.code, escape_text(&d.message));
        for l in &d.labels {
            let (line, col) = sources.line_column(l.span.file, l.span.start).unwrap_or((0, 0));
            s.push_str(&format!("  --> {}:{}:{}: {}\n", sources.name(l.span.file), line, col, escape_text(&l.message)));
        }
        for n in &d.notes {
            s.push_str(&format!("  = note: {}\n", escape_text(n)));
        }
        if let Some(h) = &d.help {
            s.push_str(&format!("  = help: {}\n", escape_text(h)));
        }
        return s;
    }
    let severity = match d.severity {
        Severity::Error => cs::Severity::Error,
        Severity::Warning => cs::Severity::Warning,
        Severity::Note => cs::Severity::Note,
    };
    let mut notes: Vec<String> = d.notes.iter().map(|n| escape_text(n).into_owned()).collect();
    if let Some(h) = &d.help {
        notes.push(format!("help: {}", escape_text(h)));
    }
    let mut files = Files { sources, shown: HashMap::new() };
    for l in &d.labels {
        let file = l.span.file;
        if files.shown.contains_key(&file) {
            continue;
        }
        let points: Vec<usize> =
            d.labels.iter().filter(|m| m.span.file == file).flat_map(|m| [m.span.start, m.span.end]).collect();
        if let Some(text) = sources.text(file)
            && let Some(shown) = display::shown(text, &SourceLines(sources, file), &points)
        {
            files.shown.insert(file, shown);
        }
    }
    let diagnostic = cs::Diagnostic::new(severity)
        .with_code(d.code)
        .with_message(escape_text(&d.message))
        .with_labels(
            d.labels
                .iter()
                .map(|l| {
                    let style = if l.primary { cs::LabelStyle::Primary } else { cs::LabelStyle::Secondary };
                    let range = match files.shown.get(&l.span.file) {
                        Some(shown) => shown.to_shown(l.span.start, Side::Start)..shown.to_shown(l.span.end, Side::End),
                        None => l.span.start..l.span.end,
                    };
                    cs::Label::new(style, l.span.file, range).with_message(escape_text(&l.message))
                })
                .collect(),
        )
        .with_notes(notes);
    let mut buffer = Vec::new();
    let result = if color {
        let mut writer = codespan_reporting::term::termcolor::Ansi::new(&mut buffer);
        codespan_reporting::term::emit_to_write_style(&mut writer, config, &files, &diagnostic)
    } else {
        codespan_reporting::term::emit_to_io_write(&mut buffer, config, &files, &diagnostic)
    };
    match result {
        Ok(()) => String::from_utf8_lossy(&buffer).into_owned(),
        Err(_) => format!("{}[{}]: {}\n", d.severity, d.code, escape_text(&d.message)),
    }
}

/// The lines of a held file of the map.
struct SourceLines<'m>(&'m SourceMap, FileId);

impl display::Lines for SourceLines<'_> {
    fn line_of(&self, offset: usize) -> usize {
        self.0.line_index(self.1, offset).unwrap_or(0)
    }

    fn range_of(&self, line: usize) -> Option<std::ops::Range<usize>> {
        self.0.line_range(self.1, line)?.ok()
    }
}

/// The files of a map as codespan-reporting reads them for one diagnostic:
/// the files with long lines or control characters where it points, as
/// [`display::shown`] shows them; the others as they are.
struct Files<'m> {
    sources: &'m SourceMap,
    shown: HashMap<FileId, display::Shown>,
}

impl<'a> files::Files<'a> for Files<'_> {
    type FileId = FileId;
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        Ok(self.sources.name(id))
    }

    fn source(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        match self.shown.get(&id) {
            Some(shown) => Ok(&shown.text),
            None => self.sources.text(id).ok_or(files::Error::FileMissing),
        }
    }

    fn line_index(&'a self, id: FileId, byte_index: usize) -> Result<usize, files::Error> {
        match self.shown.get(&id) {
            Some(shown) => Ok(shown.line_index(byte_index)),
            None => self.sources.line_index(id, byte_index).ok_or(files::Error::FileMissing),
        }
    }

    fn line_range(&'a self, id: FileId, line_index: usize) -> Result<std::ops::Range<usize>, files::Error> {
        if let Some(shown) = self.shown.get(&id) {
            return Ok(shown.line_range(line_index));
        }
        match self.sources.line_range(id, line_index) {
            None => Err(files::Error::FileMissing),
            Some(Ok(range)) => Ok(range),
            Some(Err(max)) => Err(files::Error::LineTooLarge { given: line_index, max }),
        }
    }

    /// The line and column in the file itself, not in the lines shown.
    fn location(&'a self, id: FileId, byte_index: usize) -> Result<files::Location, files::Error> {
        let offset = match self.shown.get(&id) {
            Some(shown) => shown.to_source(byte_index),
            None => byte_index,
        };
        let (line_number, column_number) = self.sources.line_column(id, offset).ok_or(files::Error::FileMissing)?;
        Ok(files::Location { line_number, column_number })
    }
}
