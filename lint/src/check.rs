//! What `postc check` says about a post: its compiler's diagnostics
//! (`postc_driver`) and, when it compiles without errors, the lints'. The
//! command line and the Python package's `check` both call this.

use std::path::Path;

use postc_ir::{Diagnostic, Dialect, SourceMap};

use crate::Options;

/// Every diagnostic of a post file: compiling it, then linting it.
pub fn check_post(
    path: &Path,
    dialect: Option<Dialect>,
    options: &Options,
    sources: &mut SourceMap,
) -> Vec<Diagnostic> {
    checked(postc_driver::compile_post(path, dialect, sources), options)
}

/// [`check_post`] of a post given as bytes (a post's text in memory).
pub fn check_post_bytes(
    path: &Path,
    bytes: &[u8],
    dialect: Option<Dialect>,
    options: &Options,
    sources: &mut SourceMap,
) -> Vec<Diagnostic> {
    checked(postc_driver::compile_post_bytes(path, bytes, dialect, sources), options)
}

fn checked(compiled: postc_driver::Compiled, options: &Options) -> Vec<Diagnostic> {
    let mut diagnostics = compiled.diagnostics;
    if let Some(post) = &compiled.post
        && !postc_ir::diagnostic::has_errors(&diagnostics)
    {
        diagnostics.extend(crate::lint(post, options));
    }
    diagnostics
}
