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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ast::{ItemKind, TextPiece, VarBody};

    fn items(text: &str) -> (Vec<ItemKind>, Vec<Diagnostic>) {
        let (post, diags) = parse(text, FileId(0));
        (post.items.into_iter().map(|i| i.kind).collect(), diags)
    }

    #[test]
    fn every_bad_line_is_reported_and_parsing_goes_on() {
        let text = "VAR X_POSITION [X|A|X|1.3]\n\"G0 [300]\"\nbegin\n\"G1[X]\"\nVAR Y_POSITION = [Y|Q|Y|1.3]\n";
        let (items, diags) = items(text);
        assert_eq!(items.len(), 5);
        let errors: Vec<(&str, usize)> =
            diags.iter().filter(|d| d.is_error()).map(|d| (d.code, d.labels[0].span.start)).collect();
        assert_eq!(errors, vec![("PP001", 0), ("PP008", 31), ("PP013", 38), ("PP004", 72)]);
        assert!(matches!(&items[3], ItemKind::Output(q) if q.closed && q.pieces.len() == 2));
    }

    #[test]
    fn output_pieces() {
        let (items, diags) = items("  \"G0[X][13][10]x\"  + comment\r\n");
        assert!(diags.is_empty(), "{diags:?}");
        let ItemKind::Output(q) = &items[0] else { panic!("{items:?}") };
        let pieces: Vec<&TextPiece> = q.pieces.iter().map(|p| &p.value).collect();
        assert_eq!(
            pieces,
            [
                &TextPiece::Text("G0".into()),
                &TextPiece::Label("X".into()),
                &TextPiece::Code(13),
                &TextPiece::Code(10),
                &TextPiece::Text("x".into())
            ]
        );
    }

    #[test]
    fn keywords_in_any_case_and_prefix_blanks_kept() {
        let (items, diags) = items("var X_POSITION = [X|c| X |1.3]\nBEGIN header\n");
        assert!(diags.is_empty(), "{diags:?}");
        let ItemKind::Var(v) = &items[0] else { panic!("{items:?}") };
        let VarBody::Fields(f) = &v.body else { panic!("{v:?}") };
        assert_eq!(f.prefix.value, " X ");
        assert!(matches!(&items[1], ItemKind::Begin(b) if b.words[0].value == "header"));
    }

    #[test]
    fn script_block_runs_to_endscript() {
        let (items, diags) = items("SCRIPT\r\nlocal a = 1\r\nENDSCRIPT\r\n\"G0\"\r\n");
        assert!(diags.is_empty(), "{diags:?}");
        assert!(matches!(&items[0], ItemKind::ScriptBlock(code) if code.value == "local a = 1"));
        assert!(matches!(&items[1], ItemKind::Output(_)));
    }
}
