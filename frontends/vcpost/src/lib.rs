//! # The Vericut VcPost frontend
//!
//! Reads `.VcPost` post processors, Vericut's BASIC-like post language, and
//! lowers them to the post IR ([`postc_ir::Post`]).
//!
//! The pipeline:
//!
//! 1. [`lexer`]: text to tokens (chumsky, never fails; comments kept aside);
//! 2. [`parser`]: tokens to lines of items (chumsky, with per-line
//!    recovery and a Pratt expression parser);
//! 3. [`blocks`]: lines nested into Subs, `If`, `Select Case`, `For`,
//!    `While` and `Do` blocks, with missing `End ...` reported at the
//!    opening line;
//! 4. [`keywords`]: keyword comments (`' #Cycle !X !Y`) attached to their
//!    Subs and checked; [`mod@signatures`] gives the typed view;
//! 5. [`lower`]: the tree to a [`postc_ir::Post`]: Subs to functions (and to
//!    handlers keyed by APT word or composites routine name), statements
//!    outside Subs to `init`, registers to variables with number formats.
//!
//! Besides posts it reads the inputs of VcPost's two applications that are
//! not toolpaths, into the Sub calls of [`postc_ir::calls`]:
//!
//! - [`table`]: probe-cycle tables (CSV, cells split by [`csv`]) checked
//!   against the post's keyword comments (PT codes);
//! - [`composites`]: composites event files (RON or JSON Lines) checked
//!   against Vericut's post-processor notes' call sequences (CP codes).
//!
//! Every post diagnostic has a `VC` code; [`diagnostics`] has the table.
//! The language and the three applications as postc reads them (every
//! choice where the seed is silent) are in `docs/vcpost.md`.

pub mod ast;
pub mod blocks;
pub mod builtins;
pub mod call_tables;
pub mod composites;
pub mod csv;
pub mod diagnostics;
pub mod docs;
pub mod keywords;
pub mod lexer;
pub mod lower;
pub mod parser;
pub mod registers;
pub mod routines;
pub mod signatures;
pub mod table;
pub mod token;

use std::path::Path;

use postc_ir::{Diagnostic, FileId, Post, SourceMap};

pub use signatures::{SubSignature, probe_cycles};

/// Parses a post's text. Always returns a tree (lines that could not be
/// read become error statements) and every diagnostic found, in file order.
pub fn parse(text: &str, file: FileId) -> (ast::Program, Vec<Diagnostic>) {
    parse_all(text, file)
}

fn parse_all(text: &str, file: FileId) -> (ast::Program, Vec<Diagnostic>) {
    let lexed = lexer::lex(text, file);
    let (lines, parse_diagnostics) = parser::parse_lines(&lexed.tokens, &lexed.spoiled, text.len(), file);
    let built = blocks::build(lines, text.len(), file);
    let mut program = ast::Program { file, items: built.items, stray_keyword_comments: Vec::new(), doc: Vec::new() };
    let keyword_diagnostics = keywords::attach(&mut program, &lexed.comments, &built.ranges);
    docs::attach(&mut program, &lexed.comments, text);
    let mut diagnostics = lexed.diagnostics;
    diagnostics.extend(parse_diagnostics);
    diagnostics.extend(built.diagnostics);
    diagnostics.extend(keyword_diagnostics);
    sort_by_position(&mut diagnostics);
    (program, diagnostics)
}

/// Reads a post file: decodes it (UTF-8, or Windows-1252 when it is not
/// valid UTF-8), adds it to `sources`, parses and lowers it.
pub fn compile(path: &Path, bytes: &[u8], sources: &mut SourceMap) -> (Post, Vec<Diagnostic>) {
    let (text, legacy) = decode(bytes);
    let file = sources.add(path.display().to_string(), text);
    let text = sources.text(file).unwrap_or_default();
    let (program, mut diagnostics) = parse_all(text, file);
    let (mut post, lower_diagnostics) = lower::lower(&program, legacy);
    post.info.source = path.display().to_string();
    // The file as written, for the VcPost backend (`PostInfo::written`).
    post.info.written = text.to_string();
    if post.info.name.is_empty() {
        // The file's name, unless `Postc.Name` gave one.
        post.info.name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    }
    diagnostics.extend(lower_diagnostics);
    sort_by_position(&mut diagnostics);
    (post, diagnostics)
}

/// The signatures of every Sub with a keyword comment.
pub fn signatures(program: &ast::Program) -> Vec<SubSignature> {
    signatures::signatures(program)
}

/// Whether a file's content looks like a VcPost post: a line that starts
/// with `End Sub`, or a `Sub` line together with an `Out` line.
pub fn looks_like_vcpost(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(1 << 20)];
    let text = String::from_utf8_lossy(head);
    let (mut sub, mut out) = (false, false);
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().take(2).collect();
        let first = words.first().copied().unwrap_or("");
        let second = words.get(1).copied().unwrap_or("");
        if first.eq_ignore_ascii_case("End") && second.eq_ignore_ascii_case("Sub") {
            return true;
        }
        sub |= first.eq_ignore_ascii_case("Sub") && second.chars().next().is_some_and(char::is_alphabetic);
        out |= first.eq_ignore_ascii_case("Out") && second.starts_with('"');
    }
    sub && out
}

/// Text of a post file and whether it was Windows-1252 (not UTF-8).
fn decode(bytes: &[u8]) -> (String, bool) {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    match std::str::from_utf8(bytes) {
        Ok(text) => (text.to_string(), false),
        Err(_) => (encoding_rs::WINDOWS_1252.decode_without_bom_handling(bytes).0.into_owned(), true),
    }
}

fn sort_by_position(diagnostics: &mut [Diagnostic]) {
    diagnostics.sort_by_key(|d| d.primary_span().map_or(usize::MAX, |s| s.start));
}

/// What the tests of this crate's modules (`tests/modules/`) reach that is
/// not its interface: nothing else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod composites_check {
        pub use crate::composites::check::add_cut;
    }
    pub mod lower_template {
        pub use crate::lower::template::{TemplatePart, split, unclosed};
    }
    pub mod parser_recover {
        pub use crate::parser::recover::line;
    }
}
