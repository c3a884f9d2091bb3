//! # postc-front-vectric: Vectric `.pp` posts
//!
//! Reads a Vectric post processor (the format of the Vectric guides, seeds
//! 000 and 001) and lowers it to the post IR of `postc-ir`.
//!
//! - [`decode`]: the file's bytes to text (UTF-8, else Windows-1252), and
//!   literal output text back to the file's own bytes;
//! - [`parser`](parse): a chumsky grammar that reads every line, reports
//!   each bad line with a machinist's message and goes on, so one `check`
//!   shows every error of a file;
//! - [`ast`]: the syntax tree, one item per line;
//! - [`format_spec`]: the value formats of `VAR`s (`1.3`, `02.0`, `+1,3`);
//! - lowering: follows `POST_BASE`, merges the chain, gives undeclared
//!   labels the defaults of [`defaults`], and builds the IR: one number
//!   format and one variable per `VAR`, one handler per section whose lines
//!   are literal bytes and variables, Lua kept as scripts postc does not run;
//! - [`revision`]: what `[REVISION]` prints (a hash of the post file);
//! - [`diagnostics`]: the `PP` codes.

pub mod ast;
pub mod decode;
pub mod defaults;
mod detect;
pub mod diagnostics;
pub mod format_spec;
mod lower;
pub mod names;
mod parser;
pub mod revision;

use std::path::Path;

use postc_ir::{Diagnostic, FileId, Post, SourceMap};

/// Compiles a Vectric post. Decodes `bytes` (UTF-8, or Windows-1252 when
/// not valid UTF-8), registers the decoded text in `sources` under `path`
/// (spans in diagnostics point into it), follows POST_BASE (reads the base
/// from the post's folder, registers it too), parses with error recovery,
/// lowers to the IR. Always returns a Post (best effort) plus every
/// diagnostic.
pub fn compile(path: &Path, bytes: &[u8], sources: &mut SourceMap) -> (Post, Vec<Diagnostic>) {
    lower::compile(path, bytes, sources)
}

/// Parses only (for snapshots and tooling): the syntax tree and the parse
/// diagnostics.
pub fn parse(text: &str, file: FileId) -> (ast::PostFile, Vec<Diagnostic>) {
    parser::parse(text, file)
}

/// Whether bytes look like a Vectric post (for dialect detection when the
/// extension says nothing).
pub fn looks_like_vectric(bytes: &[u8]) -> bool {
    detect::looks_like_vectric(bytes)
}

/// What the tests of this crate's modules (`tests/modules/`) reach that is
/// not its interface: nothing else uses these.
#[doc(hidden)]
pub mod testing {
    pub use crate::defaults::default_text;
}
