//! Turns the grammar's errors into diagnostics a machinist can act on:
//! "expected `)`, found the name `x`", a missing `;` between two
//! statements on one line, the end of the file inside an unclosed
//! bracket (pointing at the bracket), and the grammar's own problems.

use chumsky::span::SimpleSpan;
use postc_ir::{Diagnostic, FileId};

use super::{
    Brackets, Error, Expected, ExpectedSet, Reason, TERMINATOR, is_internal, problem_diagnostic, span,
    too_deep_diagnostic,
};
use crate::Syntax;
use crate::diagnostics as d;
use crate::token::{Keyword, Punct, Token, TokenKind};

/// Diagnostics for the grammar's errors; `too_deep` is where nesting first
/// went too deep, reported once.
pub(crate) fn diagnostics(
    errors: Vec<Error<'_, '_>>,
    file: FileId,
    brackets: &Brackets,
    too_deep: Option<SimpleSpan>,
    syntax: Syntax,
) -> Vec<Diagnostic> {
    let mut out: Vec<Diagnostic> =
        errors.iter().filter(|e| !is_internal(e)).map(|e| one(e, file, brackets, syntax)).collect();
    if let Some(at) = too_deep {
        out.push(too_deep_diagnostic(span(file, at)));
    }
    out
}

fn one(e: &Error<'_, '_>, file: FileId, brackets: &Brackets, syntax: Syntax) -> Diagnostic {
    let at = span(file, *e.span());
    match e.reason() {
        Reason::Custom(problem) => problem_diagnostic(problem, at, syntax),
        Reason::ExpectedFound { expected, found } => {
            let expected = describe_expected(expected);
            match found.as_ref() {
                None => {
                    let mut diag = Diagnostic::error(
                        d::UNEXPECTED_END,
                        format!("the file ends here, but {expected} should follow"),
                    )
                    .at(at, "the file ends here");
                    if let Some((open, open_at)) = brackets.unclosed.last() {
                        diag = diag
                            .also(span(file, *open_at), format!("this `{}` is never closed", open.as_str()))
                            .help("check that every `(`, `[` and `{` has its closing bracket");
                    }
                    diag
                }
                Some(token) if expects_terminator(e) && starts_statement(token) => Diagnostic::error(
                    d::MISSING_SEMICOLON,
                    format!("expected `;` before {token}: two statements on one line need a `;` between them"),
                )
                .at(at, "expected `;` or a line break before this")
                .help("end the statement with `;`, or check for a missing operator or bracket"),
                Some(token) => {
                    let mut diag = Diagnostic::error(d::SYNTAX_ERROR, format!("expected {expected}, found {token}"))
                        .at(at, format!("unexpected {}", short(token)));
                    if let TokenKind::Punct(p @ (Punct::RParen | Punct::RBracket | Punct::RBrace)) = token.kind
                        && !brackets.closers.values().any(|&end| end == e.span().end)
                    {
                        diag = diag.note(format!("this `{}` has no opening bracket to close", p.as_str()));
                    }
                    diag
                }
            }
        }
    }
}

fn expects_terminator(e: &Error<'_, '_>) -> bool {
    e.expected().any(|p| matches!(p, Expected::Label(l) if *l == TERMINATOR))
}

/// Tokens that begin a statement, so that "missing `;`" is the likely
/// mistake when one follows an expression on the same line.
fn starts_statement(t: &Token<'_>) -> bool {
    match t.kind {
        TokenKind::Ident(_) | TokenKind::Number(_) | TokenKind::String(_) => true,
        TokenKind::Keyword(k) => matches!(
            k,
            Keyword::Var
                | Keyword::If
                | Keyword::For
                | Keyword::While
                | Keyword::Do
                | Keyword::Return
                | Keyword::Break
                | Keyword::Continue
                | Keyword::Switch
                | Keyword::Function
                | Keyword::Throw
                | Keyword::Try
                | Keyword::This
                | Keyword::New
        ),
        _ => false,
    }
}

/// A token as the label under it names it.
fn short(t: &Token<'_>) -> String {
    match t.kind {
        TokenKind::Ident(n) => format!("`{n}`"),
        TokenKind::String(_) => "text".to_string(),
        TokenKind::Number(_) => "number".to_string(),
        _ => t.to_string(),
    }
}

/// Tokens never suggested: newer syntax that would be reported anyway.
fn suggestible(t: &Token<'_>) -> bool {
    match t.kind {
        TokenKind::Punct(p) => !matches!(
            p,
            Punct::QuestionDot
                | Punct::Nullish
                | Punct::NullishAssign
                | Punct::StarStar
                | Punct::StarStarAssign
                | Punct::AndAssign
                | Punct::OrAssign
                | Punct::Arrow
                | Punct::Ellipsis
        ),
        TokenKind::Keyword(k) => !matches!(k, Keyword::In | Keyword::Instanceof | Keyword::Delete | Keyword::Void),
        // A template after an expression would be a tagged template.
        TokenKind::TemplatePart { .. } => false,
        _ => true,
    }
}

/// Operators are summarised as "an operator" in expected lists.
fn is_operator(t: &Token<'_>) -> bool {
    matches!(t.kind, TokenKind::Punct(p) if !matches!(
        p,
        Punct::LBrace | Punct::RBrace | Punct::LParen | Punct::RParen | Punct::LBracket | Punct::RBracket
            | Punct::Semi | Punct::Comma | Punct::Colon
    ))
}

/// `(` and `[` continue an expression (a call, an index) when operators
/// could follow too; then they are summarised with the operators.
fn continues_expression(t: &Token<'_>) -> bool {
    t.is_punct(Punct::LParen) || t.is_punct(Punct::LBracket)
}

/// "`)`, `,` or an operator".
fn describe_expected(expected: &ExpectedSet<'_>) -> String {
    let mut items: Vec<String> = Vec::new();
    let mut operators = 0;
    let after_expression = expected.iter().any(|p| matches!(p, Expected::Token(t) if is_operator(t)));
    for p in expected.iter() {
        let item = match p {
            Expected::Token(t) => {
                if !suggestible(t) {
                    continue;
                }
                if is_operator(t) || (after_expression && continues_expression(t)) {
                    operators += 1;
                    continue;
                }
                t.to_string()
            }
            Expected::Label(l) => l.to_string(),
            Expected::EndOfInput => "the end of the file".to_string(),
            Expected::Any | Expected::SomethingElse => continue,
        };
        if !items.contains(&item) {
            items.push(item);
        }
    }
    if operators > 0 {
        items.push("an operator".to_string());
    }
    match items.len() {
        0 => "something else".to_string(),
        1 => items.remove(0),
        n => {
            let last = items.remove(n - 1);
            format!("{} or {last}", items.join(", "))
        }
    }
}
