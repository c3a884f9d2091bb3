//! The `postc` Python package (pyo3, built by maturin; python/README.md):
//! `post`, `check`, `convert` and `verify` as Python functions that call
//! the library code the `postc` command calls (`postc_driver` to compile
//! posts and open toolpaths, `postc_runtime` to post, `postc_lint`,
//! `postc_backends`, `postc_verify`), with a toolpath given as a file or as
//! any Python iterable of events (`events`, `moves`), and diagnostics as
//! Python objects and exceptions (`diagnostics`).
//!
//! Python holds the interpreter lock for the whole of a call: the events
//! of an iterable are Python objects, read as the runtime asks for them.

mod diagnostics;
mod events;
mod moves;
mod verifying;

use std::path::{Path, PathBuf};

use postc_ir::codes;
use postc_ir::{Diagnostic as Found, Dialect, EventSource, Post, SourceMap};
use postc_runtime::{Finished, Output};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList, PyString};

use diagnostics::{Diagnostic, PostError, PostWarning};

/// A post, a program or a toolpath given as a file or in memory.
enum Input {
    Path(PathBuf),
    Text(String, Vec<u8>),
}

impl Input {
    /// A `str` is text when it holds a line break, else a path; an
    /// `os.PathLike` is a path; `bytes` are text. `name` names the text.
    fn of(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Input> {
        if let Ok(s) = obj.cast::<PyString>() {
            let s = s.to_str()?;
            return Ok(if s.contains('\n') {
                Input::Text(name.into(), s.as_bytes().to_vec())
            } else {
                Input::Path(s.into())
            });
        }
        if let Ok(b) = obj.cast::<PyBytes>() {
            return Ok(Input::Text(name.into(), b.as_bytes().to_vec()));
        }
        Ok(Input::Path(obj.extract::<PathBuf>()?))
    }

    fn name(&self) -> String {
        match self {
            Input::Path(p) => p.display().to_string(),
            Input::Text(name, _) => name.clone(),
        }
    }
}

/// The dialect names of `dialect=` (the CLI's `--dialect`; `ir` is `ron`).
fn dialect(name: Option<&str>) -> PyResult<Option<Dialect>> {
    let Some(name) = name else { return Ok(None) };
    Ok(Some(match name.to_ascii_lowercase().as_str() {
        "vectric" | "pp" => Dialect::Vectric,
        "cimco" | "js" => Dialect::Cimco,
        "vcpost" => Dialect::VcPost,
        "fusion" | "cps" => Dialect::Fusion,
        "ron" | "ir" => Dialect::Ron,
        _ => {
            return Err(PyValueError::new_err(format!(
                "dialect={name:?}: postc reads vectric, cimco, vcpost, fusion and ir (ron)"
            )));
        }
    }))
}

/// Compiles a post; a post with errors is refused with them, its warnings
/// go to Python's `warnings`.
fn compile(py: Python<'_>, post: &Input, dialect: Option<Dialect>, sources: &mut SourceMap) -> PyResult<Post> {
    let compiled = match post {
        Input::Path(path) => postc_driver::compile_post(path, dialect, sources),
        Input::Text(name, bytes) => postc_driver::compile_post_bytes(Path::new(name), bytes, dialect, sources),
    };
    let name = post.name();
    match compiled.post {
        Some(p) if !compiled.has_errors() => {
            diagnostics::warn(py, sources, &compiled.diagnostics)?;
            Ok(p)
        }
        _ => Err(diagnostics::error(
            py,
            sources,
            &compiled.diagnostics,
            &name,
            &format!("`{name}` has errors; nothing was posted"),
        )),
    }
}

/// A toolpath: a file (a path) or the events of an iterable.
enum Toolpath<'py> {
    File(Box<dyn EventSource>),
    Items(events::PyEvents<'py>),
}

impl<'py> Toolpath<'py> {
    fn open(obj: &Bound<'py, PyAny>, sources: &mut SourceMap) -> PyResult<Result<Toolpath<'py>, Found>> {
        let is_path = obj.is_instance_of::<PyString>() || obj.hasattr("__fspath__")?;
        if is_path {
            let path: PathBuf = obj.extract()?;
            return Ok(postc_driver::open_toolpath(&path, sources).map(Toolpath::File));
        }
        let items = obj.try_iter()?;
        let file = sources.add_streamed(ITERABLE);
        Ok(Ok(Toolpath::Items(events::PyEvents::new(items, file))))
    }

    fn name(obj: &Bound<'py, PyAny>) -> String {
        obj.extract::<PathBuf>().map_or_else(|_| ITERABLE.to_string(), |p| p.display().to_string())
    }

    fn source(&mut self) -> &mut dyn EventSource {
        match self {
            Toolpath::File(f) => f,
            Toolpath::Items(i) => i,
        }
    }

    /// Diagnostics with their labels in an iterable turned into notes
    /// naming the item ([`events::locate`]).
    fn locate(&self, found: &mut [Found]) {
        if let Toolpath::Items(i) = self {
            events::locate(found, i.file);
        }
    }

    /// The exception the iterable raised, if it did.
    fn raised(&mut self) -> Option<PyErr> {
        match self {
            Toolpath::File(_) => None,
            Toolpath::Items(i) => i.error.take(),
        }
    }
}

/// What diagnostics about an iterable toolpath name as its file.
const ITERABLE: &str = "<toolpath iterable>";

/// `set=`: a dict of names and values, or `NAME=VALUE` strings.
fn sets(set: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<String>> {
    let Some(set) = set else { return Ok(Vec::new()) };
    if let Ok(d) = set.cast::<PyDict>() {
        return d.iter().map(|(k, v)| Ok(format!("{}={}", k.str()?, v.str()?))).collect();
    }
    if set.is_instance_of::<PyString>() {
        return Ok(vec![set.extract()?]);
    }
    set.try_iter()?.map(|s| s?.extract::<String>()).collect()
}

/// A program's bytes as Python text: UTF-8, or byte for character
/// (Latin-1) when the post writes other bytes (a Windows-1252 post's
/// strings are written back unchanged).
fn text(bytes: Vec<u8>) -> String {
    match String::from_utf8(bytes) {
        Ok(s) => s,
        Err(e) => e.into_bytes().iter().map(|&b| char::from(b)).collect(),
    }
}

/// Whether two paths name the same file (links followed).
fn same_file(a: &Path, b: &Path) -> bool {
    matches!((std::fs::canonicalize(a), std::fs::canonicalize(b)), (Ok(a), Ok(b)) if a == b)
}

/// Posts `toolpath` through `post` and returns the program's text, or
/// writes it to `out` (whole, or not at all; tape-split parts beside it)
/// and returns None.
///
/// `post` is a path, or a post's text (a str with a line break, or bytes);
/// its dialect comes from its extension or its content, and `dialect`
/// ("vectric", "cimco", "vcpost", "fusion", "ir") overrides. `toolpath` is
/// a path (.ron, .jsonl, APT CL) or any iterable of events as dicts,
/// {"Feed": {"x": 10, "y": 5, "z": -1}}, or names, "End"
/// (docs/toolpath-format.md). `set` gives job values as `--set` does: a
/// dict ({"date": "2026-01-01"}) or "NAME=VALUE" strings. `exact_arcs`
/// computes arc words from the printed end points.
///
/// Raises PostError (with `.diagnostics`) when the post has errors, the
/// toolpath does not read or posting fails; an exception the iterable
/// raises is raised again. Warnings go to Python's warnings module as
/// PostWarning. The program is verified as `postc post` verifies it (the
/// generic controller, 0.01 mm): an error refuses it (PostError with the
/// findings), a program verify does not read is said as a VF044 note;
/// `verify=False` skips verification.
#[pyfunction]
#[pyo3(signature = (post, toolpath, *, out=None, set=None, dialect=None, exact_arcs=false, verify=true))]
#[allow(clippy::too_many_arguments)]
fn post(
    py: Python<'_>,
    post: &Bound<'_, PyAny>,
    toolpath: &Bound<'_, PyAny>,
    out: Option<PathBuf>,
    set: Option<&Bound<'_, PyAny>>,
    dialect: Option<&str>,
    exact_arcs: bool,
    verify: bool,
) -> PyResult<Option<String>> {
    let mut sources = postc_report::source_map();
    let post_input = Input::of(post, "<post text>")?;
    let dialect = self::dialect(dialect)?;
    let toolpath_name = Toolpath::name(toolpath);
    if let Some(out) = &out {
        let inputs = [post_input.name(), toolpath_name.clone()];
        if let Some(input) = inputs.iter().find(|i| same_file(Path::new(i), out)) {
            let d = Found::error(codes::IO012, format!("the output `{}` is the input `{input}`", out.display()))
                .help("write the program to a file of its own that the call does not read");
            return Err(diagnostics::error(py, &mut sources, &[d], input, "nothing was posted"));
        }
    }
    let compiled = compile(py, &post_input, dialect, &mut sources)?;
    let mut options =
        postc_runtime::RunOptions { now: Some(postc_report::now()), ..postc_driver::run_options(&compiled) };
    options.exact_arcs = exact_arcs;
    if let Err(d) = postc_driver::settings::apply_sets(&sets(set)?, &mut options) {
        return Err(diagnostics::error(py, &mut sources, &[d], "set", "a setting postc does not take"));
    }
    let compiled = postc_driver::settings::post_for_run(compiled, &mut options);
    options.file = out.as_deref().map(postc_driver::settings::file_info);
    let mut toolpath_events = match Toolpath::open(toolpath, &mut sources)? {
        Ok(t) => t,
        Err(d) => return Err(diagnostics::error(py, &mut sources, &[d], &toolpath_name, "nothing was posted")),
    };
    let (run, records) = if verify {
        let mut recording = verifying::Recording { inner: toolpath_events.source(), records: Vec::new() };
        let run = postc_runtime::run(&compiled, &mut recording, Output::memory(), options);
        (run, Some(recording.records))
    } else {
        (postc_runtime::run(&compiled, toolpath_events.source(), Output::memory(), options), None)
    };
    if let Some(raised) = toolpath_events.raised() {
        return Err(raised);
    }
    let mut report = match run {
        Ok(report) => report,
        Err(mut found) => {
            toolpath_events.locate(&mut found);
            return Err(diagnostics::error(
                py,
                &mut sources,
                &found,
                &toolpath_name,
                "posting failed; no output was written",
            ));
        }
    };
    toolpath_events.locate(&mut report.warnings);
    diagnostics::warn(py, &mut sources, &report.warnings)?;
    let Finished::Memory(parts) = report.output else {
        return Err(PostError::new_err("postc posted to memory but the program is not there"));
    };
    if let Some(records) = records {
        let program = parts.concat();
        let name = out.as_ref().map_or_else(|| "<program>".to_string(), |p| p.display().to_string());
        let ext =
            out.as_deref().and_then(Path::extension).map(|e| e.to_string_lossy().into_owned()).unwrap_or_default();
        match verifying::verify(&compiled, &program, &name, &ext, records, &mut sources) {
            verifying::Verdict::Unverified(note) => diagnostics::warn(py, &mut sources, &[note])?,
            verifying::Verdict::Findings(mut findings) => {
                toolpath_events.locate(&mut findings);
                if postc_ir::diagnostic::has_errors(&findings) {
                    return Err(diagnostics::error(
                        py,
                        &mut sources,
                        &findings,
                        &name,
                        "verifying the program found errors; the program was not written (post with verify=False to have it anyway)",
                    ));
                }
                diagnostics::warn(py, &mut sources, &findings)?;
            }
        }
    }
    match out {
        None => Ok(Some(text(parts.concat()))),
        Some(out) => {
            let tape = compiled.options.tape_splitting.as_ref();
            let names = postc_runtime::output::part_names(&out, parts.len(), tape);
            for (name, bytes) in names.iter().zip(&parts) {
                postc_report::output::write_whole(name, bytes).map_err(|e| {
                    let d = Found::error(codes::IO003, format!("cannot write `{}`: {e}", name.display()));
                    diagnostics::error(
                        py,
                        &mut sources,
                        &[d],
                        &name.display().to_string(),
                        "the program was not written",
                    )
                })?;
            }
            Ok(None)
        }
    }
}

/// What `postc check` says about a post (or a toolpath file): every
/// diagnostic, errors included, as a list of Diagnostic; an empty list for
/// a clean post. `product` ("cut2d", "vcarve", "aspire", "cut3d",
/// "photovcarve") warns about what that Vectric product's post processor
/// does not support.
#[pyfunction]
#[pyo3(signature = (post, *, dialect=None, product=None))]
fn check<'py>(
    py: Python<'py>,
    post: &Bound<'py, PyAny>,
    dialect: Option<&str>,
    product: Option<&str>,
) -> PyResult<Bound<'py, PyList>> {
    let mut sources = postc_report::source_map();
    let input = Input::of(post, "<post text>")?;
    let dialect = self::dialect(dialect)?;
    let product = match product.map(str::to_ascii_lowercase).as_deref() {
        None => None,
        Some("cut2d") => Some(postc_lint::Product::Cut2d),
        Some("vcarve") => Some(postc_lint::Product::Vcarve),
        Some("aspire") => Some(postc_lint::Product::Aspire),
        Some("cut3d") => Some(postc_lint::Product::Cut3d),
        Some("photovcarve") => Some(postc_lint::Product::PhotoVcarve),
        Some(other) => {
            return Err(PyValueError::new_err(format!(
                "product={other:?}: postc knows cut2d, vcarve, aspire, cut3d and photovcarve"
            )));
        }
    };
    let lint = postc_lint::Options { product };
    let name = input.name();
    let found = match &input {
        Input::Path(path) if !path.exists() => {
            vec![Found::error(codes::IO001, format!("`{}` does not exist", path.display()))]
        }
        Input::Path(path) if dialect.is_none() && postc_driver::is_toolpath(path, &postc_report::FsLoader) => {
            postc_driver::check_toolpath(path, &mut sources)
        }
        Input::Path(path) => postc_lint::check_post(path, dialect, &lint, &mut sources),
        Input::Text(name, bytes) => postc_lint::check_post_bytes(Path::new(name), bytes, dialect, &lint, &mut sources),
    };
    diagnostics::list(py, &sources, &found, &name)
}

/// The post as a post of another dialect, `to` = "vectric", "vcpost",
/// "cimco", "fusion" or "ron" (`postc convert`); `postc_extension=True`
/// writes a post of another dialect as a CIMCO or VcPost section post
/// (`--postc-extension`). Raises PostError with every reason when the
/// target cannot hold the post.
#[pyfunction]
#[pyo3(signature = (post, to, *, dialect=None, postc_extension=false))]
fn convert(
    py: Python<'_>,
    post: &Bound<'_, PyAny>,
    to: &str,
    dialect: Option<&str>,
    postc_extension: bool,
) -> PyResult<String> {
    let mut sources = postc_report::source_map();
    let input = Input::of(post, "<post text>")?;
    let target = match to.to_ascii_lowercase().as_str() {
        "vectric" | "pp" => postc_backends::Target::Vectric,
        "vcpost" if postc_extension => postc_backends::Target::VcPostSections,
        "vcpost" => postc_backends::Target::VcPost,
        "cimco" | "js" if postc_extension => postc_backends::Target::CimcoSections,
        "cimco" | "js" => postc_backends::Target::Cimco,
        "fusion" | "cps" => postc_backends::Target::Fusion,
        "ron" | "ir" => postc_backends::Target::Ron,
        _ => {
            return Err(PyValueError::new_err(format!(
                "to={to:?}: postc converts to vectric, vcpost, cimco, fusion and ron"
            )));
        }
    };
    let compiled = compile(py, &input, self::dialect(dialect)?, &mut sources)?;
    match postc_backends::convert(&compiled, target) {
        Ok(bytes) => Ok(text(bytes)),
        Err(found) => {
            let name = input.name();
            Err(diagnostics::error(
                py,
                &mut sources,
                &found,
                &name,
                &format!("`{name}` cannot be converted to {to}; nothing was written"),
            ))
        }
    }
}

/// Replays a G-code program (a path, or its text) and compares its motion
/// with the toolpath it was posted from (a path or an iterable of events),
/// as `postc verify` does; returns the findings as Diagnostics (no error
/// among them: the program makes the toolpath's moves). `post` tells
/// verify the program's units, rounding and block numbering; `controller`
/// ("linuxcnc", "fanuc", "haas", "grbl", "generic") its limits;
/// `tolerance` is in mm. Raises PostError for a program verify does not
/// read (HPGL, ShopBot, Heidenhain conversational, binary) or a toolpath
/// that does not read.
#[pyfunction]
#[pyo3(signature = (program, toolpath, *, post=None, dialect=None, controller="generic", tolerance=0.01))]
fn verify<'py>(
    py: Python<'py>,
    program: &Bound<'py, PyAny>,
    toolpath: &Bound<'py, PyAny>,
    post: Option<&Bound<'py, PyAny>>,
    dialect: Option<&str>,
    controller: &str,
    tolerance: f64,
) -> PyResult<Bound<'py, PyList>> {
    use postc_verify::{Controller, Settings};
    let mut sources = postc_report::source_map();
    let controller = match controller.to_ascii_lowercase().as_str() {
        "linuxcnc" => Controller::LinuxCnc,
        "fanuc" => Controller::Fanuc,
        "haas" => Controller::Haas,
        "grbl" => Controller::Grbl,
        "generic" => Controller::Generic,
        other => {
            return Err(PyValueError::new_err(format!(
                "controller={other:?}: postc knows linuxcnc, fanuc, haas, grbl and generic"
            )));
        }
    };
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(PyValueError::new_err(format!(
            "tolerance={tolerance}: the tolerance must be a positive number of mm"
        )));
    }
    let compiled = match post {
        Some(p) => Some(compile(py, &Input::of(p, "<post text>")?, self::dialect(dialect)?, &mut sources)?),
        None => None,
    };
    let settings = match &compiled {
        Some(p) => Settings::from_post(p, controller, tolerance),
        None => Settings { controller, tolerance, ..Settings::default() },
    };
    let program = Input::of(program, "<program text>")?;
    let name = program.name();
    let bytes = match &program {
        Input::Text(_, bytes) => bytes.clone(),
        Input::Path(path) => std::fs::read(path).map_err(|e| {
            let d = Found::error(codes::IO001, format!("cannot read `{name}`: {e}"));
            diagnostics::error(py, &mut sources, &[d], &name, "nothing was verified")
        })?,
    };
    let ext = match &program {
        Input::Path(path) => path.extension().map(|e| e.to_string_lossy().into_owned()).unwrap_or_default(),
        Input::Text(..) => String::new(),
    };
    if let Some(refused) = postc_verify::refusal(&name, compiled.as_ref(), &ext, &bytes[..bytes.len().min(4096)]) {
        return Err(diagnostics::error(py, &mut sources, &[refused], &name, "nothing was verified"));
    }
    let file = sources.add(name.clone(), String::from_utf8_lossy(&bytes).into_owned());
    let toolpath_name = Toolpath::name(toolpath);
    let mut toolpath_events = match Toolpath::open(toolpath, &mut sources)? {
        Ok(t) => t,
        Err(d) => return Err(diagnostics::error(py, &mut sources, &[d], &toolpath_name, "nothing was verified")),
    };
    let mut report = postc_verify::verify(&mut bytes.as_slice(), file, toolpath_events.source(), &settings);
    if let Some(raised) = toolpath_events.raised() {
        return Err(raised);
    }
    toolpath_events.locate(&mut report.findings);
    diagnostics::list(py, &sources, &report.findings, &name)
}

/// postc: post CNC toolpaths through Vectric, CIMCO, VcPost and Fusion
/// posts, check and convert posts, and verify programs, from Python.
#[pymodule]
#[pyo3(name = "postc")]
fn postc_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(post, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(convert, m)?)?;
    m.add_function(wrap_pyfunction!(verify, m)?)?;
    m.add_class::<Diagnostic>()?;
    m.add("PostError", m.py().get_type::<PostError>())?;
    m.add("PostWarning", m.py().get_type::<PostWarning>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
