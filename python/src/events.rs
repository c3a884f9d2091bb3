//! A Python iterable as a toolpath: each item an event of the native
//! schema (docs/toolpath-format.md) as Python writes its JSON form, a dict
//! of one event name and its fields (`{"Feed": {"x": 10, "y": 5, "z": -1}}`)
//! or a unit event's name (`"End"`). Items are read one at a time as the
//! runtime asks for them, so a CAM program's generator streams its moves
//! in flat memory, and checked as every native stream is
//! (`postc_reader_native::StreamChecks`: ranges, the closing `End`).
//!
//! Each item becomes an [`Event`] directly: moves (nearly every item) by a
//! fast path that reads the dict's fields (`moves`), every other event
//! through serde (`pythonize`), from the same serde types the file readers
//! use. An exception raised by the iterable ends the stream and is raised
//! again to the caller.

use postc_ir::codes;
use postc_ir::{Diagnostic, Event, EventSource, FileId, Span};
use postc_reader_native::StreamChecks;
use pyo3::prelude::*;
use pyo3::types::PyIterator;

/// The events of a Python iterable, as a toolpath stream.
pub struct PyEvents<'py> {
    items: Bound<'py, PyIterator>,
    /// The source map's entry for the iterable; spans are item numbers.
    pub file: FileId,
    /// Items read so far.
    read: usize,
    checks: StreamChecks,
    done: bool,
    /// The exception the iterable raised, raised again when the run ends.
    pub error: Option<PyErr>,
}

/// What a diagnostic about an item says of where it is.
fn at_item(n: usize) -> String {
    format!("event {n} of the toolpath iterable (the first is 1)")
}

/// Labels in the iterable (whose spans are item numbers, not places in a
/// text) become notes naming the item: `event N of the toolpath iterable`.
pub fn locate(found: &mut [Diagnostic], file: FileId) {
    for d in found {
        let mut notes = Vec::new();
        d.labels.retain(|l| {
            if l.span.file != file {
                return true;
            }
            notes.push(format!("{}: {}", at_item(l.span.start + 1), l.message));
            false
        });
        d.notes.splice(0..0, notes);
    }
}

impl<'py> PyEvents<'py> {
    pub fn new(items: Bound<'py, PyIterator>, file: FileId) -> PyEvents<'py> {
        PyEvents { items, file, read: 0, checks: StreamChecks::default(), done: false, error: None }
    }
}

impl EventSource for PyEvents<'_> {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        while !self.done {
            let item = match self.items.next() {
                Some(Ok(item)) => item,
                Some(Err(e)) => {
                    self.error = Some(e);
                    self.done = true;
                    return None;
                }
                None => break,
            };
            self.read += 1;
            let span = Span::new(self.file, self.read - 1, self.read);
            match crate::moves::event(&item) {
                Ok(event) => {
                    let next = Some((event, span));
                    self.checks.check(next.as_ref(), span, diagnostics);
                    return next;
                }
                Err(why) => diagnostics.push(
                    Diagnostic::error(codes::TP006, format!("{} is not a valid event: {why}", at_item(self.read)))
                        .at(span, "this event")
                        .help("events look like {\"Feed\": {\"x\": 10, \"y\": 5, \"z\": -1}} or \"End\"; docs/toolpath-format.md lists every event and field"),
                ),
            }
        }
        self.done = true;
        let end = Span::new(self.file, self.read, self.read);
        self.checks.check(None, end, diagnostics);
        None
    }
}
