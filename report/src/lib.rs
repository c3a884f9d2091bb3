//! # postc report: the edge where diagnostics and files meet the world
//!
//! `postc_ir` holds [`Diagnostic`]s and the [`SourceMap`] of files they point
//! into, and reads nothing by itself. This crate is what the command line,
//! the language server and the tests put around it:
//!
//! - [`FsLoader`]: the [`SourceLoader`] over the file system, and
//!   [`source_map`], a map that reads through it;
//! - [`Render`]: diagnostics rendered for people (codespan-reporting, with
//!   source snippets where the text is at hand) and as JSON
//!   ([`JsonDiagnostic`], `check --format json`);
//! - [`now`]: the clock, as every edge that posts reads it (the command
//!   line, the Python package);
//! - [`output`]: where an output goes (links followed, devices and pipes
//!   written into), for the same edges.
//!
//! gleam's split is the model: one project-wide diagnostic type in the
//! compiler core, rendered only by the CLI.

mod clock;
pub mod display;
mod fs;
pub mod output;
mod render;

pub use clock::now;
pub use fs::{FsLoader, source_map};
pub use render::{JsonDiagnostic, Render};

#[doc(no_inline)]
pub use postc_ir::{Diagnostic, SourceLoader, SourceMap};
