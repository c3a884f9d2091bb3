//! The line parser: a chumsky parser over the lexer's tokens that reads each
//! physical line into [`LineItem`]s (statements separated by `:`, or a line
//! that opens, continues or closes a block).
//!
//! Recovery is per line: a line that does not parse gives one VC001
//! diagnostic at the first token that could not be read, and parsing
//! resumes at the next line. Block structure (which `End If` closes which
//! `If`) is not decided here but by [`crate::blocks`], which sees every
//! line at once and so can point a missing `End If` at its `If`.

mod expr;
pub(crate) mod recover;
mod stmt;

use chumsky::error::RichPattern;
use chumsky::input::ValueInput;
use chumsky::prelude::*;
use postc_ir::{Diagnostic, FileId, Span};

use crate::ast::{CaseTest, Expr, FormalParam, LoopKind, LoopTest, Name, ProcKind, Stmt};
use crate::diagnostics as codes;
use crate::token::{Kw, Token};

pub(crate) type Extra<'t> = extra::Err<Rich<'t, Token, SimpleSpan>>;

/// One piece of a line.
#[derive(Clone, Debug, PartialEq)]
pub enum LineItem {
    Stmt(Stmt),
    ProcStart {
        kind: ProcKind,
        name: Name,
        params: Vec<FormalParam>,
        span: Span,
    },
    ProcEnd {
        kind: ProcKind,
        span: Span,
    },
    IfStart {
        cond: Expr,
        span: Span,
    },
    ElseIf {
        cond: Expr,
        span: Span,
    },
    Else {
        span: Span,
    },
    EndIf {
        span: Span,
    },
    SelectStart {
        subject: Expr,
        span: Span,
    },
    Case {
        tests: Vec<CaseTest>,
        span: Span,
    },
    CaseElse {
        span: Span,
    },
    EndSelect {
        span: Span,
    },
    ForStart {
        var: Name,
        from: Expr,
        to: Expr,
        step: Option<Expr>,
        span: Span,
    },
    Next {
        var: Option<Name>,
        span: Span,
    },
    /// `While c`, `Do`, `Do While c`, `Do Until c`.
    LoopStart {
        kind: LoopKind,
        test: Option<LoopTest>,
        span: Span,
    },
    /// `Wend`, `End While`, `Loop`, `Loop While c`, `Loop Until c`.
    LoopEnd {
        kind: LoopKind,
        test: Option<LoopTest>,
        span: Span,
    },
    /// A line that could not be read (already reported).
    Error {
        span: Span,
    },
}

impl LineItem {
    /// Where the item is.
    pub fn span(&self) -> Span {
        match self {
            LineItem::Stmt(s) => s.span,
            LineItem::ProcStart { span, .. }
            | LineItem::ProcEnd { span, .. }
            | LineItem::IfStart { span, .. }
            | LineItem::ElseIf { span, .. }
            | LineItem::Else { span }
            | LineItem::EndIf { span }
            | LineItem::SelectStart { span, .. }
            | LineItem::Case { span, .. }
            | LineItem::CaseElse { span }
            | LineItem::EndSelect { span }
            | LineItem::ForStart { span, .. }
            | LineItem::Next { span, .. }
            | LineItem::LoopStart { span, .. }
            | LineItem::LoopEnd { span, .. }
            | LineItem::Error { span } => *span,
        }
    }
}

pub(crate) fn span(file: FileId, s: SimpleSpan) -> Span {
    Span::new(file, s.start, s.end)
}

pub(crate) fn kw<'t, I>(k: Kw) -> impl Parser<'t, I, Token, Extra<'t>> + Clone
where
    I: ValueInput<'t, Token = Token, Span = SimpleSpan>,
{
    just(Token::Kw(k))
}

pub(crate) fn name<'t, I>(file: FileId) -> impl Parser<'t, I, Name, Extra<'t>> + Clone
where
    I: ValueInput<'t, Token = Token, Span = SimpleSpan>,
{
    select! { Token::Ident(text) => text }
        .map_with(move |text, e| Name { text, span: span(file, e.span()) })
        .labelled("a name")
}

fn program<'t, I>(file: FileId) -> impl Parser<'t, I, Vec<Vec<LineItem>>, Extra<'t>>
where
    I: ValueInput<'t, Token = Token, Span = SimpleSpan>,
{
    let base = stmt::line_item(file);
    let else_item = kw(Kw::Else)
        .map_with(move |_, e| LineItem::Else { span: span(file, e.span()) })
        .then(base.clone().or_not())
        .map(|(e, rest)| std::iter::once(e).chain(rest).collect::<Vec<_>>());
    let item = else_item.or(base.map(|i| vec![i]));
    let line_end = choice((just(Token::Newline).ignored(), end())).rewind();
    let line = item
        .separated_by(just(Token::Colon))
        .allow_trailing()
        .collect::<Vec<Vec<LineItem>>>()
        .map(|items| items.into_iter().flatten().collect::<Vec<_>>())
        .then_ignore(line_end)
        .recover_with(via_parser(
            none_of([Token::Newline])
                .repeated()
                .at_least(1)
                .collect::<Vec<Token>>()
                .map_with(move |tokens, e| recover::line(&tokens, span(file, e.span()))),
        ));
    line.separated_by(just(Token::Newline)).collect().then_ignore(end())
}

/// Parses the tokens of a file into lines of items. Errors inside the
/// `spoiled` ranges (lines the lexer already reported) are not reported.
pub fn parse_lines(
    tokens: &[(Token, SimpleSpan)],
    spoiled: &[SimpleSpan],
    text_len: usize,
    file: FileId,
) -> (Vec<Vec<LineItem>>, Vec<Diagnostic>) {
    let eoi = SimpleSpan::from(text_len..text_len);
    let input = tokens.map(eoi, |(t, s)| (t, s));
    let (lines, errors) = program(file).parse(input).into_output_errors();
    let diagnostics = errors
        .into_iter()
        .filter(|e| !spoiled.iter().any(|s| s.start <= e.span().start && e.span().start <= s.end))
        .map(|e| syntax_error(&e, file))
        .collect();
    (lines.unwrap_or_default(), diagnostics)
}

/// A chumsky error as a VC001 diagnostic a machinist can read.
fn syntax_error(e: &Rich<'_, Token, SimpleSpan>, file: FileId) -> Diagnostic {
    let mut at = span(file, *e.span());
    let found = match e.found() {
        Some(Token::Newline) | None => {
            at = Span::new(file, at.start, at.start);
            if e.found().is_some() { "end of line".to_string() } else { "end of file".to_string() }
        }
        Some(Token::Number(n)) => format!("number `{n}`"),
        Some(Token::Str(s)) => format!("text \"{s}\""),
        Some(t) => t.to_string(),
    };
    let mut expected: Vec<String> = Vec::new();
    for pattern in e.expected() {
        let text = match pattern {
            RichPattern::Token(t) => t.to_string(),
            RichPattern::Label(l) => l.to_string(),
            RichPattern::Identifier(i) => format!("`{i}`"),
            RichPattern::EndOfInput => "the end of the file".to_string(),
            _ => continue,
        };
        if !expected.contains(&text) {
            expected.push(text);
        }
    }
    if expected.iter().any(|x| x == "a value") {
        expected.retain(|x| x != "`Not`");
    }
    expected.sort();
    let label = match expected.len() {
        0 => "VcPost did not expect this here".to_string(),
        1 => format!("expected {}", expected[0]),
        n if n <= 6 => format!("expected {} or {}", expected[..n - 1].join(", "), expected[n - 1]),
        _ if expected.iter().any(|x| x == "`)`") => "expected `)` or more of the expression".to_string(),
        _ => "this does not continue the statement".to_string(),
    };
    let mut d =
        Diagnostic::error(codes::SYNTAX, format!("VcPost cannot read this line: unexpected {found}")).at(at, label);
    if let Some(help) = syntax_help(e.found()) {
        d = d.help(help);
    }
    d
}

fn syntax_help(found: Option<&Token>) -> Option<&'static str> {
    match found? {
        Token::Kw(Kw::End) => Some("`End` is followed by `Sub`, `Function`, `If`, `Select` or `While`"),
        Token::Kw(Kw::Then) => Some("an `If` reads `If condition Then`"),
        Token::Kw(k) if crate::token::Kw::ALL.contains(k) => {
            Some("keywords cannot be used as names; write `[Name]` in brackets to use one as a name")
        }
        Token::Str(_) => Some("join texts with `&`, for example `Out \"<N>(\" & Text & \")\"`"),
        _ => None,
    }
}
