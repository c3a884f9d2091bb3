//! The CIMCO backend: a post printed as CNC-Calc JavaScript, in one of two
//! forms.
//!
//! - A CIMCO post with code (its functions, globals, formats and output
//!   variables) prints as the CNC-Calc post it is ([`code`]): the settings
//!   and constants, one `createFormat` / `createVariable` per format and
//!   variable under its source name, the top-level statements, and every
//!   function of the post under its own name, native bodies printed from
//!   the IR ([`body`]). What it prints is compiled back with the CIMCO
//!   frontend and must give the same post ([`check`]).
//! - A post driven by the kind of each move whose handlers are output lines
//!   (a Vectric post, a VcPost section post) prints as a native CNC-Calc
//!   post (`crate::js_sections`): the CNC-Calc manual's entry points, the Vectric rules as
//!   JavaScript state; or, asked for explicitly (`--postc-extension`), as
//!   a *section post*, postc's extension of CNC-Calc ([`sections`]).
//!
//! Everything else is refused with a diagnostic per reason (`docs/convert.md`).

pub(crate) mod apt;
pub(crate) mod body;
mod check;
mod code;
mod sections;

use postc_ir::{CommentTarget, Diagnostic, Dialect, Post, Span};

/// Prints `post` as a CNC-Calc post that CNC-Calc runs, with the
/// conversion's warnings, or says why it cannot be one.
pub fn print(post: &Post) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    if post.info.dialect == Dialect::Cimco && !post.functions.is_empty() {
        code::print(post).map(|t| (t, Vec::new()))
    } else if post.info.dispatch == postc_ir::post::Dispatch::AptWords {
        apt::print(post)
    } else {
        crate::js_sections::print(post, crate::js_sections::Host::Cimco)
    }
}

/// Prints `post` as a CNC-Calc post, a post of another dialect as a
/// section post (postc's extension, which only postc runs).
pub fn print_extension(post: &Post) -> Result<Vec<u8>, Vec<Diagnostic>> {
    if post.info.dialect == Dialect::Cimco && !post.functions.is_empty() {
        code::print(post)
    } else {
        sections::print(post)
    }
}

/// A refusal: what cannot be printed, where the source has it, and why.
pub(crate) fn refusal(code: &'static str, span: Option<Span>, message: String, why: &str) -> Diagnostic {
    let mut d = Diagnostic::error(code, message);
    if !why.is_empty() {
        d = d.note(why.to_string());
    }
    if let Some(span) = span {
        d = d.at(span, "here");
    }
    d
}

/// The source's comment lines before `on`, as `//` lines (the CIMCO
/// frontend reads them back: `postc_front_cimco::docs`).
pub(crate) fn comment(post: &Post, on: &CommentTarget) -> String {
    post.comment(on).iter().map(|l| format!("//{l}\n")).collect()
}

/// The conversion note, then the source's head (read back as the head, the
/// note left out).
pub(crate) fn header(post: &Post) -> String {
    format!("{}\n{}", note(post), comment(post, &CommentTarget::Post))
}

/// The conversion note's line, without its line break.
pub(crate) fn note(post: &Post) -> String {
    format!(
        "// {}{} ({}).",
        postc_ir::post::CONVERSION_NOTE,
        crate::source_name(post),
        crate::dialect_name(post.info.dialect)
    )
}
