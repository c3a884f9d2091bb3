//! The parser: tokens to a [`Program`], with error recovery.
//!
//! The grammar is written with chumsky over the lexer's tokens: statements
//! in [`stmt`], [`control`] and [`mod@unsupported`]; expressions in
//! [`expr`], [`literals`] and [`operators`]; [`mod@error`] is the error
//! type and [`report`] words the errors. This module owns what they
//! share: the state type, token matchers, automatic semicolon insertion,
//! the nesting guard, and the recovery skippers.
//!
//! Recovery: a statement that does not parse is reported and skipped up to
//! its `;`, the next line break, a `case`/`default`, or the `}` that closes
//! its block (bracketed groups are skipped whole, without recursion), and
//! parsing goes on; a bracketed group inside an expression that does not
//! parse becomes an error expression. Errors are reported once each.
//!
//! Depth: each entry into a nested statement or expression goes through
//! [`guarded`], which refuses to go deeper than [`MAX_NESTING`]; nodes
//! deeper than [`MAX_TREE_DEPTH`] (long operator chains) become error
//! nodes. Either way one diagnostic is reported, never a stack overflow.

mod control;
mod error;
mod expr;
mod literals;
mod operators;
mod patterns;
pub(crate) mod report;
mod stmt;
mod unsupported;

use std::collections::HashMap;

use chumsky::extra;
use chumsky::input::{Checkpoint, InputRef};
use chumsky::input::{Input as _, ValueInput};
use chumsky::inspector::Inspector;
use chumsky::prelude::*;
use postc_ir::{Diagnostic, FileId, Span};

pub(crate) use self::error::{Expected, ExpectedSet, Reason, SyntaxError};
use crate::Syntax;
use crate::ast::{Expr, MAX_TREE_DEPTH, Program, Stmt};
use crate::diagnostics::Construct;
use crate::lexer::Tokens;
use crate::token::{Keyword, Punct, Token, TokenKind};

/// How many statements and expressions may nest inside each other.
pub const MAX_NESTING: u32 = 100;

/// A problem the grammar reports itself (as opposed to "expected X, found
/// Y", which chumsky builds).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Problem {
    Unsupported(Construct),
    /// Code, message, label, help.
    Custom(&'static str, String, &'static str, Option<&'static str>),
    TooDeep,
    /// A recovery skipper found nothing to skip; never reported.
    NoRecovery,
}

/// The grammar's error; `'t`, the tokens' borrow, is not kept.
pub(crate) type Error<'t, 's> = SyntaxError<'s>;
pub(crate) type Extra<'t, 's> = extra::Full<Error<'t, 's>, ParseState, ()>;

/// The input the grammar reads: tokens with byte spans.
pub(crate) trait TokenInput<'t, 's: 't>: ValueInput<'t, Token = Token<'s>, Span = SimpleSpan> {}
impl<'t, 's: 't, T: ValueInput<'t, Token = Token<'s>, Span = SimpleSpan>> TokenInput<'t, 's> for T {}

/// What the grammar keeps while it parses.
#[derive(Debug, Default)]
pub(crate) struct ParseState {
    /// Current nesting of guarded parsers.
    depth: u32,
    /// Where nesting first went too deep.
    too_deep: Option<SimpleSpan>,
    /// For each opening bracket (by start offset), the end offset of the
    /// bracket that closes it.
    closers: HashMap<usize, usize>,
    /// How many tokens the parser has read, re-reads after backtracking
    /// included: the parser's work, which stays linear in the input.
    reads: u64,
    /// Whose JavaScript the text is: Fusion's reads what CNC-Calc's
    /// refuses.
    syntax: Syntax,
    /// The temporaries destructuring introduced (`__postc_d<offset>`),
    /// by offset, not yet declared: the function around them declares
    /// them when it is built, the program those left at the top level.
    temps: Vec<(usize, String)>,
}

impl ParseState {
    /// Whether the text is read as Fusion's JavaScript.
    pub(crate) fn fusion(&self) -> bool {
        self.syntax == Syntax::Fusion
    }
}

/// The nesting depth goes back with the input when the parser backtracks,
/// so a guarded parser that fails needs no clean-up.
impl<'t, I: chumsky::input::Input<'t>> Inspector<'t, I> for ParseState {
    type Checkpoint = u32;

    fn on_token(&mut self, _: &I::Token) {
        self.reads += 1;
    }

    fn on_save<'p>(&self, _: &chumsky::input::Cursor<'t, 'p, I>) -> u32 {
        self.depth
    }

    fn on_rewind<'p>(&mut self, marker: &Checkpoint<'t, 'p, I, u32>) {
        self.depth = *marker.inspector();
    }
}

/// Brackets of a token list: which opener each closer closes, and which
/// are left unmatched.
pub(crate) struct Brackets {
    pub closers: HashMap<usize, usize>,
    /// Openers never closed, in file order.
    pub unclosed: Vec<(Punct, SimpleSpan)>,
}

pub(crate) fn match_brackets(tokens: &Tokens<'_>) -> Brackets {
    let mut closers = HashMap::new();
    let mut unclosed = Vec::new();
    let mut stack: Vec<(Punct, SimpleSpan)> = Vec::new();
    for (token, span) in tokens {
        let TokenKind::Punct(p) = token.kind else { continue };
        if p.closer().is_some() {
            stack.push((p, *span));
        } else if matches!(p, Punct::RBrace | Punct::RParen | Punct::RBracket) {
            // A closer closes the nearest opener of its kind; openers
            // above that one are never closed.
            if let Some(pos) = stack.iter().rposition(|(o, _)| o.closer() == Some(p)) {
                unclosed.extend(stack.drain(pos + 1..));
                if let Some((_, open)) = stack.pop() {
                    closers.insert(open.start, span.end);
                }
            }
        }
    }
    unclosed.extend(stack);
    unclosed.sort_by_key(|(_, s)| s.start);
    Brackets { closers, unclosed }
}

/// What parsing a token list gives: the tree, chumsky's errors raw (the
/// caller turns them into diagnostics), where nesting first went too deep,
/// and how many token reads it took.
pub(crate) struct Parsed<'s> {
    pub program: Option<Program>,
    pub errors: Vec<SyntaxError<'s>>,
    pub too_deep: Option<SimpleSpan>,
    pub reads: u64,
}

/// Parses tokens into a program.
pub(crate) fn parse_tokens<'t, 's: 't>(
    tokens: &'t Tokens<'s>,
    text_len: usize,
    file: FileId,
    closers: HashMap<usize, usize>,
    syntax: Syntax,
) -> Parsed<'s> {
    let input = tokens.as_slice().map(SimpleSpan::from(text_len..text_len), |(t, s)| (t, s));
    let mut state = ParseState { closers, syntax, ..ParseState::default() };
    let (program, errors) = stmt::program(file).parse_with_state(input, &mut state).into_output_errors();
    Parsed { program, errors, too_deep: state.too_deep, reads: state.reads }
}

/// A byte span of the post file.
pub(crate) fn span(file: FileId, s: SimpleSpan) -> Span {
    Span::new(file, s.start, s.end)
}

/// One punctuator.
pub(crate) fn punct<'t, 's: 't, I: TokenInput<'t, 's>>(
    p: Punct,
) -> impl Parser<'t, I, Token<'s>, Extra<'t, 's>> + Clone {
    just(Token::punct(p))
}

/// One keyword.
pub(crate) fn kw<'t, 's: 't, I: TokenInput<'t, 's>>(
    k: Keyword,
) -> impl Parser<'t, I, Token<'s>, Extra<'t, 's>> + Clone {
    just(Token::keyword(k))
}

/// A contextual word (`let`, `get`, `async`), which lexes as a name.
pub(crate) fn word<'t, 's: 't, I: TokenInput<'t, 's>>(
    w: &'static str,
) -> impl Parser<'t, I, (), Extra<'t, 's>> + Clone {
    any().filter(move |t: &Token<'s>| t.is_ident(w)).ignored()
}

/// Succeeds, consuming nothing, when the next token is on the same line.
pub(crate) fn same_line<'t, 's: 't, I: TokenInput<'t, 's>>() -> impl Parser<'t, I, (), Extra<'t, 's>> + Clone {
    any().filter(|t: &Token<'s>| !t.newline_before).rewind().ignored()
}

/// The label the statement terminator reports as expected.
pub(crate) const TERMINATOR: &str = "`;`";

/// The end of a statement: `;`, or (automatic semicolon insertion) a line
/// break, a `}` or the end of the file before the next token.
pub(crate) fn terminator<'t, 's: 't, I: TokenInput<'t, 's>>() -> impl Parser<'t, I, (), Extra<'t, 's>> + Clone {
    punct(Punct::Semi)
        .ignored()
        .or(any().filter(|t: &Token<'s>| t.newline_before || t.is_punct(Punct::RBrace)).rewind().ignored())
        .or(end())
        .labelled(TERMINATOR)
}

/// A name, with its span.
pub(crate) fn name<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
) -> impl Parser<'t, I, crate::ast::Ident, Extra<'t, 's>> + Clone {
    select! { Token { kind: TokenKind::Ident(n), .. } => n }
        .map_with(move |n: &str, e| crate::ast::Ident { name: n.to_string(), span: span(file, e.span()) })
        .labelled("a name")
}

/// Emits an unsupported-construct error at `at`.
pub(crate) fn unsupported<'t, 's>(construct: Construct, at: SimpleSpan) -> Error<'t, 's> {
    SyntaxError::custom(at, Problem::Unsupported(construct))
}

/// Runs `parser` one level deeper, or fails with [`Problem::TooDeep`] past
/// [`MAX_NESTING`]. The level is given back when `parser` is done, or by
/// the rewind when it fails.
pub(crate) fn guarded<'t, 's: 't, I, O, P>(parser: P) -> impl Parser<'t, I, O, Extra<'t, 's>> + Clone
where
    I: TokenInput<'t, 's>,
    P: Parser<'t, I, O, Extra<'t, 's>> + Clone,
{
    let enter = custom(|inp: &mut InputRef<'t, '_, I, Extra<'t, 's>>| {
        if inp.state().depth >= MAX_NESTING {
            // Point at the next token.
            let here = inp.save();
            let before = inp.cursor();
            inp.next();
            let at = inp.span_since(&before);
            inp.rewind(here);
            inp.state().too_deep.get_or_insert(at);
            return Err(SyntaxError::custom(at, Problem::TooDeep));
        }
        inp.state().depth += 1;
        Ok(())
    });
    let leave = custom(|inp: &mut InputRef<'t, '_, I, Extra<'t, 's>>| {
        let state = inp.state();
        state.depth = state.depth.saturating_sub(1);
        Ok(())
    });
    enter.ignore_then(parser).then_ignore(leave)
}

/// Caps tree depth: a node deeper than [`MAX_TREE_DEPTH`] becomes an error
/// node, and the first place this happens is remembered for the report.
pub(crate) fn cap_expr(e: Expr, state: &mut ParseState, at: SimpleSpan) -> Expr {
    if e.depth() <= MAX_TREE_DEPTH {
        return e;
    }
    state.too_deep.get_or_insert(at);
    Expr::error(e.span)
}

pub(crate) fn cap_stmt(s: Stmt, state: &mut ParseState, at: SimpleSpan) -> Stmt {
    if s.depth() <= MAX_TREE_DEPTH {
        return s;
    }
    state.too_deep.get_or_insert(at);
    Stmt::error(s.span)
}

/// Skips one bracketed group starting with `open` (the brackets and
/// everything between), without recursion. A group that is never closed
/// is reported.
pub(crate) fn balanced<'t, 's: 't, I: TokenInput<'t, 's>>(
    open: Punct,
) -> impl Parser<'t, I, SimpleSpan, Extra<'t, 's>> + Clone {
    let skip = custom(move |inp: &mut InputRef<'t, '_, I, Extra<'t, 's>>| {
        let start = inp.cursor();
        let target = closer_of(inp, open)?;
        skip_to(inp, target);
        Ok(inp.span_since(&start))
    });
    punct(open).rewind().ignore_then(skip)
}

/// Succeeds, consuming nothing, when the next token is `open` and a
/// bracket closes it; fails as [`balanced`] does otherwise. A pattern is
/// read only inside closed brackets, so that an unclosed one is reported
/// where it opens.
pub(crate) fn closed<'t, 's: 't, I: TokenInput<'t, 's>>(open: Punct) -> impl Parser<'t, I, (), Extra<'t, 's>> + Clone {
    let check = custom(move |inp: &mut InputRef<'t, '_, I, Extra<'t, 's>>| closer_of(inp, open).map(|_| ()));
    punct(open).rewind().ignore_then(check.rewind())
}

/// Reads the opening bracket `open` and gives the end offset of the
/// bracket that closes it, or the error of a bracket never closed.
fn closer_of<'t, 's: 't, I: TokenInput<'t, 's>>(
    inp: &mut InputRef<'t, '_, I, Extra<'t, 's>>,
    open: Punct,
) -> Result<usize, Error<'t, 's>> {
    let start = inp.cursor();
    inp.next();
    let first_span = inp.span_since(&start);
    inp.state().closers.get(&first_span.start).copied().ok_or_else(|| {
        let message = format!("this `{}` is never closed", open.as_str());
        let help = Some("add the missing closing bracket");
        SyntaxError::custom(first_span, Problem::Custom(crate::diagnostics::UNCLOSED, message, "opened here", help))
    })
}

/// Consumes tokens until one ends at or after `end`.
fn skip_to<'t, 's: 't, I: TokenInput<'t, 's>>(inp: &mut InputRef<'t, '_, I, Extra<'t, 's>>, end: usize) {
    loop {
        let before = inp.cursor();
        if inp.next().is_none() {
            return;
        }
        if inp.span_since(&before).end >= end {
            return;
        }
    }
}

/// Recovery for a statement: skips from where it started to the end of the
/// statement (see the module documentation) and yields an error statement.
pub(crate) fn skip_statement<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
) -> impl Parser<'t, I, Stmt, Extra<'t, 's>> + Clone {
    custom(move |inp: &mut InputRef<'t, '_, I, Extra<'t, 's>>| {
        let start = inp.cursor();
        let mut first = true;
        let mut last: Option<Token<'s>> = None;
        loop {
            let here = inp.save();
            let before = inp.cursor();
            let Some(token) = inp.next() else {
                inp.rewind(here);
                break;
            };
            let token_span = inp.span_since(&before);
            // A line break ends the skipped statement unless the lines
            // around it are one expression: stopping inside a long chain
            // of `+` lines would re-parse the rest of the chain once per
            // line.
            let line_ends = token.newline_before
                && !token.continues_before()
                && !last.is_some_and(|t: Token<'s>| t.continues_after());
            let stop_before = token.is_punct(Punct::RBrace)
                || (!first && (line_ends || token.is_keyword(Keyword::Case) || token.is_keyword(Keyword::Default)));
            if stop_before {
                inp.rewind(here);
                break;
            }
            first = false;
            last = Some(token);
            if token.is_punct(Punct::Semi) {
                break;
            }
            let opens = matches!(token.kind, TokenKind::Punct(p) if p.closer().is_some());
            if opens && let Some(target) = inp.state().closers.get(&token_span.start).copied() {
                skip_to(inp, target);
                last = None;
            }
        }
        if first {
            let at = inp.span_since(&start);
            return Err(SyntaxError::custom(at, Problem::NoRecovery));
        }
        let s = inp.span_since(&start);
        Ok(Stmt::error(span(file, s)))
    })
}

/// Whether an error is not reported on its own: the guard's (reported
/// once, separately) and the skippers'.
pub(crate) fn is_internal(e: &Error<'_, '_>) -> bool {
    matches!(e.reason(), Reason::Custom(Problem::TooDeep | Problem::NoRecovery))
}

/// Turns a grammar problem into a diagnostic.
pub(crate) fn problem_diagnostic(problem: &Problem, at: Span, syntax: Syntax) -> Diagnostic {
    match problem {
        Problem::Unsupported(c) => c.diagnostic_as(at, syntax),
        Problem::Custom(code, message, label, help) => {
            let d = Diagnostic::error(*code, message.clone()).at(at, *label);
            match help {
                Some(h) => d.help(*h),
                None => d,
            }
        }
        Problem::TooDeep | Problem::NoRecovery => too_deep_diagnostic(at),
    }
}

pub(crate) fn too_deep_diagnostic(at: Span) -> Diagnostic {
    Diagnostic::error(
        crate::diagnostics::TOO_DEEP,
        format!(
            "the code is nested too deeply here (more than {MAX_NESTING} levels of statements and brackets, or an expression of more than {MAX_TREE_DEPTH} operators)"
        ),
    )
    .at(at, "nested too deeply")
    .help("split the expression or the nested blocks into helper functions")
}
