//! Building blocks of the grammar: blanks, line ends, keywords, quoted
//! strings with their `[LABEL]` and `[nn]` pieces, the values of global
//! statements, and the check for stray text at the end of a line.

use chumsky::prelude::*;
use postc_ir::{FileId, Span};

use crate::ast::{QuotedText, Spanned, TextPiece, Value};
use crate::diagnostics::Code;
use crate::parser::error::ParseIssue;

/// The parser extras: diagnostics are [`ParseIssue`]s.
pub type Extra = extra::Err<ParseIssue>;

/// Reports a diagnostic from inside the grammar.
pub fn emit(emitter: &mut chumsky::input::Emitter<ParseIssue>, diagnostic: postc_ir::Diagnostic) {
    emitter.emit(ParseIssue::from(diagnostic));
}

/// A byte span of the file being parsed.
pub fn span(file: FileId, s: SimpleSpan) -> Span {
    Span::new(file, s.start, s.end)
}

/// Blanks inside a line (none or more).
pub fn hspace<'a>() -> impl Parser<'a, &'a str, (), Extra> + Clone {
    one_of(" \t").repeated()
}

/// One line ending: CR LF, LF, or a lone CR.
pub fn eol<'a>() -> impl Parser<'a, &'a str, (), Extra> + Clone {
    choice((just("\r\n"), just("\n"), just("\r"))).ignored()
}

/// The rest of the current line, without its ending.
pub fn rest<'a>() -> impl Parser<'a, &'a str, &'a str, Extra> + Clone {
    none_of("\r\n").repeated().to_slice()
}

/// A keyword, in any letter case, as a whole word.
pub fn keyword<'a>(word: &'static str) -> impl Parser<'a, &'a str, (), Extra> + Clone {
    text::ascii::ident().filter(move |s: &&str| s.eq_ignore_ascii_case(word)).ignored()
}

/// A name (`POST_NAME`, `X_POSITION`) with its span.
pub fn name<'a>(file: FileId) -> impl Parser<'a, &'a str, Spanned<String>, Extra> + Clone {
    text::ascii::ident().map_with(move |s: &str, e| Spanned::new(s.to_string(), span(file, e.span())))
}

/// Whether a bare word starts a trailing comment (`+ ...`, `| ...`) rather
/// than being a value (`+5`).
fn starts_comment(word: &str) -> bool {
    let mut chars = word.chars();
    match chars.next() {
        Some('|') => true,
        Some('+') => !matches!(chars.next(), Some(c) if c.is_ascii_digit() || c == '.'),
        _ => false,
    }
}

/// The rest of a line after what it holds: blanks and a trailing comment
/// are fine, anything else is reported as ignored.
pub fn trailing<'a>(file: FileId, after: &'static str) -> impl Parser<'a, &'a str, (), Extra> + Clone {
    rest().validate(move |text: &str, e, emitter| {
        let trimmed = text.trim();
        if trimmed.is_empty() || starts_comment(trimmed) {
            return;
        }
        let start = e.span().start + (text.len() - text.trim_start().len());
        let at = Span::new(file, start, start + trimmed.len());
        emit(
            emitter,
            Code::StrayText
                .diag(format!("text {after} is ignored"))
                .at(at, "ignored")
                .help("start a comment with + or |; output text goes between double quotes"),
        );
    })
}

/// Reads the `[...]` piece of a string.
fn bracket_piece<'a>(file: FileId) -> impl Parser<'a, &'a str, Spanned<TextPiece>, Extra> + Clone {
    just('[')
        .ignore_then(none_of("[]\"\r\n").repeated().to_slice())
        .then(just(']').or_not())
        .validate(move |(inner, close): (&str, Option<char>), e, emitter| {
            let at = span(file, e.span());
            if close.is_none() {
                emit(emitter,
                    Code::UnclosedBracket
                        .diag("this `[` is never closed with `]`")
                        .at(at, "no `]` after this")
                        .help("close the variable with `]`, or write [91] to print a `[`"),
                );
                return Spanned::new(TextPiece::Text(format!("[{inner}")), at);
            }
            if !inner.is_empty() && inner.bytes().all(|b| b.is_ascii_digit()) {
                return match inner.parse::<u32>().ok().and_then(|n| u8::try_from(n).ok()) {
                    Some(code) => Spanned::new(TextPiece::Code(code), at),
                    None => {
                        emit(emitter,
                            Code::BadCharCode
                                .diag(format!("character code [{inner}] is over 255"))
                                .at(at, "not a character code")
                                .help("a [nn] code is one byte from 0 to 255, like [13] for a carriage return or [34] for a quote"),
                        );
                        Spanned::new(TextPiece::Text(format!("[{inner}]")), at)
                    }
                };
            }
            Spanned::new(TextPiece::Label(inner.to_string()), at)
        })
}

/// A quoted string, from its opening quote to its closing quote (or to the
/// end of the line, reported).
pub fn quoted<'a>(file: FileId) -> impl Parser<'a, &'a str, QuotedText, Extra> + Clone {
    let text_run = none_of("[\"\r\n")
        .repeated()
        .at_least(1)
        .to_slice()
        .map_with(move |s: &str, e| Spanned::new(TextPiece::Text(s.to_string()), span(file, e.span())));
    let pieces = choice((text_run, bracket_piece(file)))
        .repeated()
        .collect::<Vec<_>>()
        .map_with(|pieces, e| (pieces, e.slice()));
    just('"').ignore_then(pieces).then(just('"').or_not()).validate(
        move |((pieces, raw), close): ((Vec<_>, &str), Option<char>), e, emitter| {
            if close.is_none() {
                emit(
                    emitter,
                    Code::UnterminatedString
                        .diag("this string has no closing quote")
                        .at(span(file, e.span()), "the string starts here and runs to the end of the line")
                        .help("end the string with \"; to print a quote inside it, write [34]"),
                );
            }
            QuotedText { pieces, raw: raw.to_string(), closed: close.is_some() }
        },
    )
}

/// One value of a global statement: a quoted string, a number or a word.
fn value<'a>(file: FileId) -> impl Parser<'a, &'a str, Spanned<Value>, Extra> + Clone {
    let bare =
        none_of(" \t\r\n\"").repeated().at_least(1).to_slice().filter(|w: &&str| !starts_comment(w)).map(|w: &str| {
            let numeric = w.starts_with(|c: char| c.is_ascii_digit() || c == '-' || c == '+' || c == '.');
            match w.parse::<f64>() {
                Ok(n) if numeric && n.is_finite() => Value::Number(n),
                _ => Value::Word(w.to_string()),
            }
        });
    choice((quoted(file).map(Value::Text), bare)).map_with(move |v, e| Spanned::new(v, span(file, e.span())))
}

/// The values after `=`, then the rest of the line.
pub fn values<'a>(file: FileId) -> impl Parser<'a, &'a str, Vec<Spanned<Value>>, Extra> + Clone {
    value(file)
        .separated_by(one_of(" \t").repeated().at_least(1))
        .collect::<Vec<_>>()
        .then_ignore(trailing(file, "after the value"))
}
