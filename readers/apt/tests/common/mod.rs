//! Helpers shared by the reader's integration tests: reading text or files
//! into events and diagnostics, rendering them for snapshots, and finding
//! the shared corpus.

#![allow(dead_code)]

use postc_report::Render as _;
use std::path::{Path, PathBuf};

use postc_ir::diagnostic::{Diagnostic, SourceMap, Span};
use postc_ir::event::{Event, EventSource};
use postc_reader_apt::AptReader;

/// Everything a read produced.
pub struct Read {
    pub sources: SourceMap,
    pub events: Vec<(Event, Span)>,
    pub diagnostics: Vec<Diagnostic>,
}

impl Read {
    pub fn errors(&self) -> Vec<&Diagnostic> {
        self.diagnostics.iter().filter(|d| d.is_error()).collect()
    }

    pub fn count(&self, name: &str) -> usize {
        self.events.iter().filter(|(e, _)| e.name() == name).count()
    }

    pub fn codes(&self) -> Vec<&'static str> {
        self.diagnostics.iter().map(|d| d.code).collect()
    }
}

/// Reads CL bytes held in memory.
pub fn read_bytes(name: &str, bytes: &[u8]) -> Read {
    let mut sources = postc_report::source_map();
    let file = sources.add(name, String::from_utf8_lossy(bytes).into_owned());
    let mut reader = AptReader::new(bytes, file);
    let mut events = Vec::new();
    let mut diagnostics = Vec::new();
    while let Some(event) = reader.next_event(&mut diagnostics) {
        events.push(event);
    }
    Read { sources, events, diagnostics }
}

pub fn read_text(text: &str) -> Read {
    read_bytes("test.cl", text.as_bytes())
}

/// The shared corpus folder, or `None` (with a message) when it is absent.
pub fn corpus_dir() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/corpus/apt");
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("corpus not found at {}: skipped", dir.display());
        None
    }
}

/// Every corpus file (not the `.md` notes), sorted.
pub fn corpus_files() -> Vec<PathBuf> {
    let Some(dir) = corpus_dir() else { return Vec::new() };
    let mut files = Vec::new();
    for vendor in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
        if vendor.path().is_dir() {
            for f in std::fs::read_dir(vendor.path()).into_iter().flatten().flatten() {
                let p = f.path();
                if p.extension().is_none_or(|e| e != "md") {
                    files.push(p);
                }
            }
        }
    }
    files.sort();
    files
}

/// A line-per-item rendering of a read, for snapshots.
pub fn render(read: &Read) -> String {
    let mut out = String::from("# events\n");
    for (event, span) in &read.events {
        let line = read.sources.line_column(span.file, span.start).map_or(0, |p| p.0);
        out.push_str(&format!("{line:>4} {event:?}\n"));
    }
    out.push_str("# diagnostics\n");
    for d in &read.diagnostics {
        let json = read.sources.to_json(d, "test.cl");
        out.push_str(&format!(
            "{}[{}] {}:{}-{}:{} {}\n",
            d.severity,
            d.code,
            json.line.unwrap_or(0),
            json.column.unwrap_or(0),
            json.end_line.unwrap_or(0),
            json.end_column.unwrap_or(0),
            d.message
        ));
    }
    out
}

/// Compares `actual` with the `insta` snapshot `tests/snapshots/NAME.snap`
/// (`cargo insta review` or `INSTA_UPDATE=always` accepts new output).
pub fn assert_snapshot(name: &str, actual: &str) {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots"));
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings.bind(|| insta::assert_snapshot!(name, actual));
}

/// The order the event contract asks for: one Job first; toolpaths that
/// open and close in turn, with every move inside one; holes inside a
/// drilling cycle; End last. A `refused` file (an APT part program found
/// part way) may stop with a toolpath open.
pub fn check_order(name: &str, events: &[(postc_ir::event::Event, postc_ir::Span)], refused: bool) {
    use postc_ir::event::Event;
    let (mut open, mut cycle) = (false, false);
    for (i, (event, _)) in events.iter().enumerate() {
        match event {
            Event::Job(_) => assert_eq!(i, 0, "{name}: Job at {i}"),
            Event::ToolpathStart(_) => {
                assert!(!open, "{name}: ToolpathStart inside a toolpath at {i}");
                open = true;
            }
            Event::ToolpathEnd => {
                assert!(open && !cycle, "{name}: ToolpathEnd at {i}");
                open = false;
            }
            Event::Rapid(_) | Event::Feed(_) | Event::Arc(_) => {
                assert!(open && !cycle, "{name}: move outside a toolpath at {i}")
            }
            Event::DrillCycle(_) => {
                assert!(open && !cycle, "{name}: DrillCycle at {i}");
                cycle = true;
            }
            Event::DrillPoint(_) => assert!(cycle, "{name}: DrillPoint outside a cycle at {i}"),
            Event::DrillEnd => {
                assert!(cycle, "{name}: DrillEnd at {i}");
                cycle = false;
            }
            Event::End => assert_eq!(i + 1, events.len(), "{name}: End before the last event"),
            _ => {}
        }
    }
    assert!(refused || (!open && !cycle), "{name}: a toolpath or cycle is left open");
}
