//! One Python item as an [`Event`]: the three move events (nearly every
//! item of a toolpath) read from their dicts' fields directly, every other
//! event, and any move this does not read completely, through serde
//! (`pythonize`, the serde types of `postc_ir::event`).
//!
//! The fast path answers only for a dict of one key, `Rapid`, `Feed` or
//! `Arc`, whose value is a dict of that event's fields, each known, each a
//! Python `float` or `int` (or for `intent`, `dir` and `plane` a variant's
//! name as a `str`), with the required ones present; then the event is
//! exactly what serde gives for the same dict. Anything else (another
//! event, `None`, an unknown key, `tool_axis`, a `bool` where a number
//! goes) goes to serde, which reads it or says what is wrong. So the fast
//! path changes the speed of reading, never what is read (python/tests/
//! test_post.py compares both against the CLI reading the same events).

use postc_ir::Event;
use postc_ir::event::{ArcDir, ArcMove, FeedMove, Intent, Move, Plane};
use pyo3::intern;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyFloat, PyInt, PyString};

/// The event of a Python item, or why it is not one.
pub fn event(item: &Bound<'_, PyAny>) -> Result<Event, String> {
    if let Some(event) = fast(item) {
        return Ok(event);
    }
    pythonize::depythonize::<Event>(item).map_err(|e| e.to_string())
}

/// The move of a plain move dict, or `None` to leave it to serde.
fn fast(item: &Bound<'_, PyAny>) -> Option<Event> {
    let outer = item.cast_exact::<PyDict>().ok()?;
    if outer.len() != 1 {
        return None;
    }
    let py = item.py();
    let (name, fields) = outer.iter().next()?;
    let name = name.cast_exact::<PyString>().ok()?;
    let fields = fields.cast_exact::<PyDict>().ok()?;
    let mut r = Fields { d: fields, found: 0 };
    let event = match name.to_str().ok()? {
        "Rapid" => Event::Rapid(Move {
            x: r.number(intern!(py, "x"))??,
            y: r.number(intern!(py, "y"))??,
            z: r.number(intern!(py, "z"))??,
            a: r.number(intern!(py, "a"))?,
            b: r.number(intern!(py, "b"))?,
            c: r.number(intern!(py, "c"))?,
            tool_axis: None,
        }),
        "Feed" => Event::Feed(FeedMove {
            x: r.number(intern!(py, "x"))??,
            y: r.number(intern!(py, "y"))??,
            z: r.number(intern!(py, "z"))??,
            intent: r.name(intern!(py, "intent"), intent)?.unwrap_or_default(),
            feed: r.number(intern!(py, "feed"))?,
            a: r.number(intern!(py, "a"))?,
            b: r.number(intern!(py, "b"))?,
            c: r.number(intern!(py, "c"))?,
            tool_axis: None,
        }),
        "Arc" => Event::Arc(ArcMove {
            dir: r.name(intern!(py, "dir"), dir)??,
            x: r.number(intern!(py, "x"))??,
            y: r.number(intern!(py, "y"))??,
            z: r.number(intern!(py, "z"))??,
            cx: r.number(intern!(py, "cx"))??,
            cy: r.number(intern!(py, "cy"))??,
            cz: r.number(intern!(py, "cz"))?.unwrap_or_default(),
            plane: r.name(intern!(py, "plane"), plane)?.unwrap_or_default(),
            intent: r.name(intern!(py, "intent"), intent)?.unwrap_or_default(),
            feed: r.number(intern!(py, "feed"))?,
        }),
        _ => return None,
    };
    // A key this did not read (unknown, or tool_axis) is serde's to judge.
    (r.found == fields.len()).then_some(event)
}

/// The fields of a move's dict, counting those read.
struct Fields<'a, 'py> {
    d: &'a Bound<'py, PyDict>,
    found: usize,
}

impl Fields<'_, '_> {
    /// `Some(None)`: the key is absent; `Some(Some(v))`: a number;
    /// `None`: present but not a plain number (serde's to read).
    fn number(&mut self, key: &Bound<'_, PyString>) -> Option<Option<f64>> {
        let Ok(Some(value)) = self.d.get_item(key) else { return Some(None) };
        self.found += 1;
        if let Ok(f) = value.cast_exact::<PyFloat>() {
            return Some(Some(f.value()));
        }
        // Exactly int: a bool is an int to Python but not a number to serde.
        let i = value.cast_exact::<PyInt>().ok()?;
        i.extract::<i64>().ok().map(|i| Some(i as f64))
    }

    /// A unit variant given by its name, as [`Fields::number`] answers.
    fn name<T>(&mut self, key: &Bound<'_, PyString>, of: fn(&str) -> Option<T>) -> Option<Option<T>> {
        let Ok(Some(value)) = self.d.get_item(key) else { return Some(None) };
        self.found += 1;
        of(value.cast_exact::<PyString>().ok()?.to_str().ok()?).map(Some)
    }
}

fn intent(name: &str) -> Option<Intent> {
    Some(match name {
        "Cut" => Intent::Cut,
        "Plunge" => Intent::Plunge,
        "Retract" => Intent::Retract,
        "LeadIn" => Intent::LeadIn,
        "LeadOut" => Intent::LeadOut,
        _ => return None,
    })
}

fn dir(name: &str) -> Option<ArcDir> {
    Some(match name {
        "Cw" => ArcDir::Cw,
        "Ccw" => ArcDir::Ccw,
        _ => return None,
    })
}

fn plane(name: &str) -> Option<Plane> {
    Some(match name {
        "Xy" => Plane::Xy,
        "Zx" => Plane::Zx,
        "Yz" => Plane::Yz,
        _ => return None,
    })
}
