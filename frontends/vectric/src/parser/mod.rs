//! The chumsky grammar of Vectric posts.
//!
//! A post is a sequence of lines; each line is one of the forms in
//! [`lines`], tried in order, the last of which takes any text at all. Every
//! form reads to the end of its line and reports its own problems, so a bad
//! line costs one diagnostic and parsing goes on with the next line: `check`
//! sees every error of a file, not only the first.

mod common;
mod error;
mod lines;

use chumsky::prelude::*;
use postc_ir::{Diagnostic, FileId, Span};

use crate::ast::{Item, PostFile};
use crate::diagnostics::Code;
use common::{Extra, eol, span};
pub use error::ParseIssue;

fn file_parser<'a>(file: FileId) -> impl Parser<'a, &'a str, Vec<Item>, Extra> {
    let line = choice((
        lines::blank(),
        lines::comment(),
        lines::script_call(file),
        lines::output(file),
        lines::script_block(file),
        lines::var(file),
        lines::begin(file),
        lines::global(file),
        lines::bare_variables(file),
        lines::stray(file),
    ))
    .map_with(move |kind, e| kind.map(|kind| Item { kind, span: span(file, e.span()), blank_before: false }));
    just('\u{feff}')
        .or_not()
        .ignore_then(line.separated_by(eol()).collect::<Vec<_>>())
        .then_ignore(end())
        .map(|items| items.into_iter().flatten().collect())
}

/// Parses a post's text: the syntax tree (best effort, whatever the errors)
/// and the diagnostics, in file order.
pub fn parse(text: &str, file: FileId) -> (PostFile, Vec<Diagnostic>) {
    let (items, issues) = file_parser(file).parse(text).into_output_errors();
    let mut diagnostics: Vec<Diagnostic> = issues
        .into_iter()
        .map(|issue| match issue {
            ParseIssue::Report(d) => *d,
            ParseIssue::Unexpected(s) => Code::Unreadable
                .diag("postc could not read this line")
                .at(Span::new(file, s.start, s.end.max(s.start)), "unreadable")
                .note("this is a gap in postc's grammar; please report the line"),
        })
        .collect();
    diagnostics.sort_by_key(|d| d.primary_span().map_or(0, |s| s.start));
    let mut items = items.unwrap_or_default();
    let mut previous_end = 0;
    for item in &mut items {
        let between = text.get(previous_end..item.span.start).unwrap_or("");
        item.blank_before = previous_end > 0 && between.matches('\n').count() > 1;
        previous_end = item.span.end;
    }
    (PostFile { file, items }, diagnostics)
}
