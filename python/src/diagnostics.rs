//! Diagnostics as Python sees them: the `Diagnostic` class (the fields of
//! `postc check --format json`, from `postc_report`'s JSON form), the
//! `PostError` exception that carries them, and `PostWarning`, the
//! warnings category a run's warnings are given under.

use postc_ir::{Diagnostic as Found, SourceMap};
use postc_report::{JsonDiagnostic, Render};
use pyo3::prelude::*;
use pyo3::types::PyList;

pyo3::create_exception!(
    postc,
    PostError,
    pyo3::exceptions::PyException,
    "A post, toolpath or program postc refuses. `.diagnostics` lists every reason as `Diagnostic`s; the message renders them as `postc` prints them."
);

pyo3::create_exception!(
    postc,
    PostWarning,
    pyo3::exceptions::PyUserWarning,
    "A warning of a post or a run (a diagnostic of warning severity), given through Python's `warnings` module."
);

/// One diagnostic as `postc check --format json` gives it.
#[pyclass(module = "postc", frozen, get_all)]
#[derive(Clone)]
pub struct Diagnostic {
    /// The stable code, e.g. `PP012` (`postc explain CODE` documents it).
    pub code: String,
    /// `"error"`, `"warning"` or `"note"`.
    pub severity: String,
    pub message: String,
    /// The file the diagnostic points into (a path, or `<post text>`,
    /// `<toolpath iterable>`, `<program text>`).
    pub file: String,
    /// 1-based line and column of the start, when the diagnostic has a place.
    pub line: Option<usize>,
    pub column: Option<usize>,
    /// 1-based line and column of the end.
    pub end_line: Option<usize>,
    pub end_column: Option<usize>,
}

#[pymethods]
impl Diagnostic {
    /// `(end_line, end_column)`, or `None` when the diagnostic has no place.
    #[getter]
    fn end(&self) -> Option<(usize, usize)> {
        Some((self.end_line?, self.end_column?))
    }

    /// The diagnostic as the dict `postc check --format json` prints for it.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(pythonize::pythonize(py, &self.json())?)
    }

    fn __repr__(&self) -> String {
        let place = match (self.line, self.column) {
            (Some(l), Some(c)) => format!("{}:{l}:{c}", self.file),
            _ => self.file.clone(),
        };
        format!("<Diagnostic {} {} at {place}: {}>", self.severity, self.code, self.message)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<Diagnostic>().is_ok_and(|o| o.get().json() == self.json())
    }
}

impl Diagnostic {
    fn json(&self) -> JsonDiagnostic {
        JsonDiagnostic {
            file: self.file.clone(),
            severity: serde_json::from_value(serde_json::Value::String(self.severity.clone()))
                .unwrap_or(postc_ir::Severity::Error),
            code: self.code.clone(),
            message: self.message.clone(),
            line: self.line,
            column: self.column,
            end_line: self.end_line,
            end_column: self.end_column,
        }
    }

    /// A diagnostic of `sources` as `check --format json` gives it;
    /// `file` names it when it has no place.
    pub fn of(sources: &SourceMap, d: &Found, file: &str) -> Diagnostic {
        let j = sources.to_json(d, file);
        let severity = match serde_json::to_value(j.severity) {
            Ok(serde_json::Value::String(s)) => s,
            _ => d.severity.to_string(),
        };
        Diagnostic {
            code: j.code,
            severity,
            message: j.message,
            file: j.file,
            line: j.line,
            column: j.column,
            end_line: j.end_line,
            end_column: j.end_column,
        }
    }
}

/// Diagnostics as a Python list of `Diagnostic`.
pub fn list<'py>(py: Python<'py>, sources: &SourceMap, found: &[Found], file: &str) -> PyResult<Bound<'py, PyList>> {
    PyList::new(py, found.iter().map(|d| Diagnostic::of(sources, d, file)))
}

/// A `PostError` saying `headline`, then the diagnostics as `postc`
/// renders them for people; `.diagnostics` holds them.
pub fn error(py: Python<'_>, sources: &mut SourceMap, found: &[Found], file: &str, headline: &str) -> PyErr {
    let rendered = sources.render(found, false);
    let message = if rendered.trim().is_empty() { headline.to_string() } else { format!("{headline}\n{rendered}") };
    let err = PostError::new_err(message);
    match list(py, sources, found, file) {
        Ok(list) => match err.value(py).setattr("diagnostics", list) {
            Ok(()) => err,
            Err(e) => e,
        },
        Err(e) => e,
    }
}

/// Gives each warning (and note) of `found` to Python's `warnings` module
/// as a `PostWarning`, rendered as `postc` prints it.
pub fn warn(py: Python<'_>, sources: &mut SourceMap, found: &[Found]) -> PyResult<()> {
    let category = py.get_type::<PostWarning>();
    for d in found.iter().filter(|d| !d.is_error()) {
        let text = sources.render(std::slice::from_ref(d), false);
        let text = text.trim_end();
        let c = std::ffi::CString::new(text.replace('\0', " ")).unwrap_or_default();
        PyErr::warn(py, &category, &c, 1)?;
    }
    Ok(())
}
