//! # CIMCO CNC-Calc JavaScript posts
//!
//! CNC-Calc posts (the CNC-Calc Post Processor Manual) are JavaScript files: globals that set up the
//! output (`decimalMark`, `linebreak`, `useRadius`, ... or a
//! `globals = {...}` object with a `PostInfo`), number formats and output
//! variables made with `createFormat` and `createVariable`, and the
//! functions CNC-Calc calls (`onInit`, `onOpen`, `onLinear`, `onCircular`,
//! `onDrillingPoint`, ...). They use the ES5 of their era.
//!
//! This crate reads that JavaScript and compiles it to the IR
//! ([`compile`]). The front half:
//!
//! - [`lexer`]: text to tokens (comments, line breaks for automatic
//!   semicolon insertion, strings, numbers, regular expressions);
//! - `parser`: tokens to the [`ast`], a chumsky grammar with error
//!   recovery, so every error in a file is reported;
//! - [`validate`]: `return`/`break`/`continue` where they belong;
//! - [`diagnostics`]: the `JS` codes, and the JavaScript outside the subset,
//!   each reported at its line and column with its name and what to write
//!   instead;
//! - [`mod@print`] and [`dump`]: the tree back as JavaScript, and as a compact
//!   dump for tests.
//!
//! The back half, `lower`, turns the [`ast`] into a post: the Globals and
//! `createFormat`/`createVariable` calls into output options, formats and
//! variables; each function into native IR statements where the IR says
//! what it means, and every function into one Rhai script (with a span map
//! back to the post) for the rest; the entry points into section handlers,
//! with the text of native functions built straight in the output.
//! `docs/cimco.md` gives the host semantics.

pub mod ast;
pub mod diagnostics;
pub mod docs;
pub mod dump;
pub mod fusion;
pub mod host_names;
pub mod lexer;
mod lower;
pub mod made;
mod parser;
pub mod print;
pub mod sections;
mod sniff;
mod strings;
pub mod token;
pub mod validate;

use postc_ir::{Diagnostic, FileId, Span};

pub use ast::Program;
pub use lower::builtins;
pub use lower::compile;
/// How native code reads a value as a JavaScript number (`UnaryOp::Plus`
/// around what is not surely one): a backend prints such a value plainly
/// where the lowering adds it again.
pub use lower::to_number;
pub use parser::MAX_NESTING;
pub use sniff::looks_like_cimco;

/// Which engine's JavaScript a text is read as.
///
/// CNC-Calc's engine reads the ES5 of its era; what is newer is reported
/// by name ([`diagnostics::Construct`]). Autodesk's Fusion engine runs
/// modern JavaScript in sloppy mode: read as [`Syntax::Fusion`], template
/// literals, arrow functions, destructuring, default parameter values,
/// shorthand properties, legacy octal and `0b`/`0o` numbers are part of
/// the language (docs/fusion.md, "Language").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Syntax {
    #[default]
    Cimco,
    Fusion,
}

/// Parses a CIMCO post. Always returns a tree (parts that did not parse
/// are error nodes) and every problem found, sorted by position.
pub fn parse(text: &str, file: FileId) -> (Program, Vec<Diagnostic>) {
    parse_as(text, file, Syntax::Cimco)
}

/// Parses a post as the engine of `syntax` reads it.
pub fn parse_as(text: &str, file: FileId, syntax: Syntax) -> (Program, Vec<Diagnostic>) {
    let (program, diagnostics, _) = parse_counted(text, file, syntax);
    (program, diagnostics)
}

/// How much work parsing a text takes: its number of tokens and the
/// number of token reads the parser made (re-reads after backtracking and
/// recovery included). Tests hold the ratio bounded, so that checking a
/// post stays linear in its size whatever its errors.
pub fn parse_work(text: &str) -> (usize, u64) {
    parse_work_as(text, Syntax::Cimco)
}

/// [`parse_work`] for a text read as the engine of `syntax` reads it.
pub fn parse_work_as(text: &str, syntax: Syntax) -> (usize, u64) {
    let (tokens, _) = lexer::lex_as(text, FileId(0), syntax);
    let (_, _, reads) = parse_counted(text, FileId(0), syntax);
    (tokens.len(), reads)
}

fn parse_counted(text: &str, file: FileId, syntax: Syntax) -> (Program, Vec<Diagnostic>, u64) {
    let (tokens, mut diagnostics) = lexer::lex_as(text, file, syntax);
    let brackets = parser::match_brackets(&tokens);
    let parsed = parser::parse_tokens(&tokens, text.len(), file, brackets.closers.clone(), syntax);
    diagnostics.extend(parser::report::diagnostics(parsed.errors, file, &brackets, parsed.too_deep, syntax));
    let program = parsed.program.unwrap_or_else(|| Program { body: Vec::new(), span: Span::new(file, 0, text.len()) });
    diagnostics.extend(validate::check(&program));
    diagnostics.sort_by_key(|d| d.primary_span().map(|s| (s.start, s.end)));
    diagnostics.dedup_by(|a, b| a.code == b.code && a.primary_span() == b.primary_span() && a.message == b.message);
    (program, diagnostics, parsed.reads)
}

/// What the tests of this crate's modules (`tests/modules/`) reach that is
/// not its interface: nothing else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod strings {
        pub use crate::strings::{decode, quote};
    }
}
