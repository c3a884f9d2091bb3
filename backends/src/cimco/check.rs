//! The CIMCO backend checks what it prints: the CIMCO frontend compiles the
//! printed JavaScript (from memory; it reads no file), and the post it
//! makes must be the post that was printed. That is what makes a converted
//! post post as its source, and it is the one place that knows how the
//! frontend derives a post's handlers from its functions (the entry points
//! by name, the bridges, the fast path that inlines what they return): a
//! post whose handlers are not the ones derived from its functions (a RON
//! post edited by hand) is refused, never printed wrongly.
//!
//! Compared: everything but where things are (spans, which point into
//! another file) and the Rhai script, which the frontend makes again from
//! the printed JavaScript; the functions that run as scripts are compared
//! by the JavaScript they keep (`Function::source`), which is what the
//! script is made from. Locals the frontend made (a `switch`'s value) are
//! named by the backend, and compared under those names.

use std::path::Path;

use postc_ir::{Body, Diagnostic, Post, SourceMap, Span, codes};
use serde::Serialize;

use super::{body, refusal};

/// Compiles `text`, the post printed from `post`, and refuses it unless it
/// compiles to `post` again.
pub(super) fn compiles_back(post: &Post, text: &str) -> Result<(), Vec<Diagnostic>> {
    let mut sources = SourceMap::new();
    let (back, diagnostics) = postc_front_cimco::compile(Path::new(&post.info.source), text.as_bytes(), &mut sources);
    if let Some(e) = diagnostics.iter().find(|d| d.is_error()) {
        return Err(vec![refusal(
            codes::CV006.code,
            None,
            format!("the printed post does not compile: {} {}", e.code, e.message),
            "this is a bug in postc's CIMCO backend",
        )]);
    }
    match difference(post, &back) {
        None => Ok(()),
        Some((what, span)) => Err(vec![refusal(
            codes::CV006.code,
            span,
            format!("the printed post would compile to a different post: {what} differs"),
            "a CNC-Calc post is its globals and functions; the CIMCO frontend derives its handlers, bridges and start-up code from them, so a post whose IR is not what that gives (a RON post edited by hand?) cannot be printed",
        )]),
    }
}

/// A post as compared: no spans, no Rhai text, the backend's names for
/// locals.
fn normal(post: &Post) -> Post {
    let names: Vec<Vec<String>> = post.functions.iter().map(|f| body::local_names(post, f)).collect();
    let mut p = post.clone();
    p.drop_spans();
    for s in &mut p.scripts {
        s.source.clear();
    }
    // How the source spelled it says nothing the IR does not.
    p.drop_written();
    for (f, names) in p.functions.iter_mut().zip(names) {
        if matches!(f.body, Body::Native(_)) {
            f.locals = names.into_iter().skip(f.params.len()).collect();
        }
    }
    p
}

fn same<T: Serialize>(a: &T, b: &T) -> bool {
    // As RON text, so that NaN equals NaN.
    ron::to_string(a).ok() == ron::to_string(b).ok()
}

/// What differs, and where the source has it.
type Difference = (String, Option<Span>);

/// The first part of `want` that `got` has otherwise, and where `want`
/// has it.
fn difference(want: &Post, got: &Post) -> Option<Difference> {
    let (w, g) = (normal(want), normal(got));
    if !same(&w.info, &g.info) {
        return Some(("the post's information (its name, notes, units)".into(), None));
    }
    if !same(&w.options, &g.options) {
        return Some(("the output options (line ending, chord tolerance, lathe)".into(), None));
    }
    let format =
        |i: usize| w.formats[i].name.as_deref().map_or_else(|| format!("format {i}"), |n| format!("format `{n}`"));
    let handler = |i: usize| match &w.handlers[i].key {
        postc_ir::HandlerKey::Section(s) => format!("the handler of {}", s.name()),
        postc_ir::HandlerKey::Word(word) => format!("the handler of {word}"),
    };
    first(&w.formats, &g.formats, "formats", format, |i| want.formats[i].span)
        .or_else(|| {
            let name = |i: usize| format!("output variable `{}`", w.variables[i].name);
            first(&w.variables, &g.variables, "output variables", name, |i| want.variables[i].span)
        })
        .or_else(|| {
            let name = |i: usize| format!("global `{}`", w.globals[i].name);
            first(&w.globals, &g.globals, "globals", name, |i| want.globals[i].span)
        })
        .or_else(|| {
            let name = |i: usize| format!("function `{}`", w.functions[i].name);
            first(&w.functions, &g.functions, "functions", name, |i| want.functions[i].span)
        })
        .or_else(|| (!same(&w.init, &g.init)).then(|| ("what runs at start".to_string(), None)))
        .or_else(|| first(&w.handlers, &g.handlers, "handlers", handler, |i| want.handlers[i].span))
        .or_else(|| (!same(&w, &g)).then(|| ("the post".to_string(), None)))
}

/// The first of `want`'s items that `got` has otherwise or lacks (named by
/// `name`, placed by `span`), or a different number of `what`.
fn first<T: Serialize>(
    want: &[T],
    got: &[T],
    what: &str,
    name: impl Fn(usize) -> String,
    span: impl Fn(usize) -> Option<Span>,
) -> Option<Difference> {
    match want.iter().zip(got).position(|(a, b)| !same(a, b)) {
        Some(i) => Some((name(i), span(i))),
        None => (want.len() != got.len()).then(|| (format!("the number of {what}"), None)),
    }
}
