//! The lexer: post text to tokens, with a chumsky character parser that
//! never fails (a character it cannot read becomes an error token and a
//! diagnostic, and lexing goes on).
//!
//! It owns the lexical rules of VcPost: `'` and `Rem` comments run to the end
//! of the line and are taken out of the token stream (whole-line comments
//! are kept for the keyword-comment reader); ` _` at the end of a line joins
//! it to the next; strings are `"..."` with `""` for a quote; numbers are
//! `12`, `1.5`, `.5`, `1.5E-3`; names start with a letter, go on with letters,
//! digits and `_`, may end in the BASIC `$` type character (dropped) and may
//! be written `[End]` to use a keyword as a name. Keywords ignore case.
//!
//! It also guards the parser: a line longer than [`MAX_LINE_TOKENS`] tokens
//! or with more than [`MAX_PAREN_DEPTH`] nested parentheses is reported and
//! replaced by one error token, so that no input builds a tree deep enough
//! to exhaust the stack.

use chumsky::prelude::*;
use postc_ir::{Diagnostic, FileId, Span};

use crate::diagnostics as codes;
use crate::token::{Kw, Op, Token};

/// Most tokens one logical line may hold.
pub const MAX_LINE_TOKENS: usize = 1000;
/// Deepest nesting of parentheses on one line.
pub const MAX_PAREN_DEPTH: usize = 32;

/// A comment, as the lexer found it.
#[derive(Clone, Debug, PartialEq)]
pub struct Comment {
    /// The text after `'` or `Rem`.
    pub text: String,
    /// Byte offset of `text` in the file.
    pub text_start: usize,
    /// The whole comment, marker included.
    pub span: Span,
    /// Nothing but blanks precedes it on its line.
    pub whole_line: bool,
}

/// The lexer's result.
#[derive(Debug, Default)]
pub struct Lexed {
    /// Tokens with their byte ranges, comments removed.
    pub tokens: Vec<(Token, SimpleSpan)>,
    pub comments: Vec<Comment>,
    pub diagnostics: Vec<Diagnostic>,
    /// Byte ranges of lines already reported (an unreadable character, too
    /// long, too deep): the parser's own error for them is not reported
    /// again.
    pub spoiled: Vec<SimpleSpan>,
}

type LexExtra<'a> = extra::Err<Rich<'a, char>>;

fn lexer<'a>() -> impl Parser<'a, &'a str, Vec<(Token, SimpleSpan)>, LexExtra<'a>> {
    let blank = any().filter(|c: &char| matches!(c, ' ' | '\t' | '\u{0b}' | '\u{0c}' | '\u{a0}' | '\u{feff}'));
    let line_break = choice((just("\r\n"), just("\n"), just("\r")));
    let continuation = just('_').then(blank.repeated()).then(line_break).ignored();
    let skip = blank.ignored().or(continuation).repeated();

    let newline = line_break.to(Token::Newline);
    let comment =
        just('\'').ignore_then(none_of("\r\n").repeated().to_slice()).map(|s: &str| Token::Comment(s.to_string()));

    let digits = any().filter(char::is_ascii_digit).repeated().at_least(1);
    let exponent = one_of("eE").then(one_of("+-").or_not()).then(digits);
    let number = digits
        .then(just('.').then(digits.or_not()).or_not())
        .ignored()
        .or(just('.').then(digits).ignored())
        .then(exponent.or_not())
        .to_slice()
        .map(|s: &str| Token::Number(s.parse().unwrap_or(f64::NAN)));

    let string = just('"')
        .ignore_then(choice((just("\"\"").to('"'), none_of("\"\r\n"))).repeated().collect::<String>())
        .then(just('"').or_not())
        .validate(|(text, closed), e, emitter| {
            if closed.is_none() {
                emitter.emit(Rich::custom(e.span(), codes::UNTERMINATED_STRING_MSG));
            }
            Token::Str(text)
        });

    let word = any()
        .filter(|c: &char| c.is_alphabetic())
        .then(any().filter(|c: &char| c.is_alphanumeric() || *c == '_').repeated())
        .to_slice();
    let rem_comment = word
        .try_map(
            |w: &str, span| {
                if w.eq_ignore_ascii_case("rem") { Ok(()) } else { Err(Rich::custom(span, "not Rem")) }
            },
        )
        .ignore_then(none_of("\r\n").repeated().to_slice())
        .map(|s: &str| Token::Comment(s.to_string()));
    let name = word.then_ignore(just('$').or_not()).map(|w: &str| match Kw::from_word(w) {
        Some(k) => Token::Kw(k),
        None => Token::Ident(w.to_string()),
    });
    let bracketed = just('[')
        .ignore_then(none_of("]\r\n").repeated().at_least(1).to_slice())
        .then_ignore(just(']'))
        .validate(|w: &str, e, emitter| {
            if crate::token::is_valid_name(w) {
                Token::Ident(w.to_string())
            } else {
                emitter.emit(Rich::custom(e.span(), codes::BAD_BRACKET_NAME_MSG));
                Token::Error
            }
        });

    let op = choice((
        just("<>").to(Op::Ne),
        just("<=").to(Op::Le),
        just(">=").to(Op::Ge),
        just('<').to(Op::Lt),
        just('>').to(Op::Gt),
        just('=').to(Op::Eq),
        just('+').to(Op::Plus),
        just('-').to(Op::Minus),
        just('*').to(Op::Star),
        just('/').to(Op::Slash),
        just('\\').to(Op::Backslash),
        just('^').to(Op::Caret),
        just('&').to(Op::Amp),
    ))
    .map(Token::Op);
    let punct = choice((
        just('(').to(Token::LParen),
        just(')').to(Token::RParen),
        just(',').to(Token::Comma),
        just('.').to(Token::Dot),
        just(':').to(Token::Colon),
    ));
    let unreadable = any().validate(|c: char, e, emitter| {
        emitter.emit(Rich::custom(e.span(), format!("{}`{}`", codes::BAD_CHAR_MSG, c.escape_debug())));
        Token::Error
    });

    let token = choice((newline, comment, number, string, rem_comment, name, bracketed, op, punct, unreadable));
    token.map_with(|t, e| (t, e.span())).padded_by(skip).repeated().collect().then_ignore(end())
}

/// Lexes a post.
pub fn lex(text: &str, file: FileId) -> Lexed {
    let (tokens, errors) = lexer().parse(text).into_output_errors();
    let mut diagnostics: Vec<Diagnostic> = errors
        .into_iter()
        .map(|e| {
            let span = Span::new(file, e.span().start, e.span().end);
            codes::lexical(span, &e.reason().to_string())
        })
        .collect();
    let mut lexed = Lexed::default();
    let mut line_has_code = false;
    for (token, span) in tokens.unwrap_or_default() {
        match token {
            Token::Comment(text) => {
                let marker = if text.len() < span.end - span.start { span.end - span.start - text.len() } else { 0 };
                lexed.comments.push(Comment {
                    text,
                    text_start: span.start + marker,
                    span: Span::new(file, span.start, span.end),
                    whole_line: !line_has_code,
                });
            }
            Token::Newline => {
                line_has_code = false;
                lexed.tokens.push((token, span));
            }
            _ => {
                line_has_code = true;
                lexed.tokens.push((token, span));
            }
        }
    }
    lexed.tokens = guard_lines(std::mem::take(&mut lexed.tokens), file, &mut diagnostics, &mut lexed.spoiled);
    lexed.diagnostics = diagnostics;
    lexed
}

/// Marks lines that hold an error token as spoiled, and replaces each line
/// that is too long or nests parentheses too deeply by its first token, an
/// error token and its last token (enough for the parser to keep the block
/// structure: `If ... Then` stays an `If` line).
fn guard_lines(
    tokens: Vec<(Token, SimpleSpan)>,
    file: FileId,
    diagnostics: &mut Vec<Diagnostic>,
    spoiled: &mut Vec<SimpleSpan>,
) -> Vec<(Token, SimpleSpan)> {
    let mut out = Vec::with_capacity(tokens.len());
    let mut line: Vec<(Token, SimpleSpan)> = Vec::new();
    let mut iter = tokens.into_iter();
    loop {
        let next = iter.next();
        let at_line_end = matches!(next, None | Some((Token::Newline, _)));
        if !at_line_end {
            if let Some(t) = next {
                line.push(t);
            }
            continue;
        }
        if let (Some(first), Some(last)) = (line.first(), line.last()) {
            let whole = SimpleSpan::from(first.1.start..last.1.end);
            let depth = paren_depth(&line);
            let has_error = line.iter().any(|(t, _)| *t == Token::Error);
            if line.len() > MAX_LINE_TOKENS || depth > MAX_PAREN_DEPTH {
                diagnostics.push(codes::too_complex(Span::new(file, whole.start, whole.end), line.len(), depth));
                spoiled.push(whole);
                let (first, last) = (first.clone(), last.clone());
                out.push(first);
                out.push((Token::Error, whole));
                out.push(last);
            } else {
                if has_error {
                    spoiled.push(whole);
                }
                out.append(&mut line);
            }
            line.clear();
        }
        match next {
            Some(newline) => out.push(newline),
            None => break,
        }
    }
    out
}

fn paren_depth(line: &[(Token, SimpleSpan)]) -> usize {
    let (mut depth, mut deepest) = (0usize, 0usize);
    for (t, _) in line {
        match t {
            Token::LParen => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            Token::RParen => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}
