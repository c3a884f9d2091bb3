//! Statements and the whole program: `var`, function declarations,
//! blocks, `if`/`else if`/`else`, `switch` and `for` (in [`super::control`]), `while`,
//! `do`-`while`, `break`, `continue`, `return`, `throw`, `try`, and
//! expression statements, each ended by `;` or by automatic semicolon
//! insertion. Newer or unsupported statements (`let`, `const`, `class`,
//! labels, `with`, `import`/`export`, `debugger`, `for ... of`) are parsed
//! far enough to be named in a diagnostic.

use chumsky::prelude::*;
use postc_ir::FileId;

use super::SyntaxError;
use super::control::{for_statement, switch_statement};
use super::expr::{expression, sequence};
use super::literals::function_parts;
use super::patterns::{self, element};
use super::unsupported::unsupported_statements;
use super::{
    Extra, Problem, TokenInput, cap_stmt, guarded, kw, name, punct, same_line, skip_statement, span, terminator,
    unsupported, word,
};
use crate::ast::{CatchClause, Expr, IfBranch, Program, Stmt, StmtKind, VarDeclarator};
use crate::diagnostics::{self as d, Construct};
use crate::token::{Keyword, Punct, Token};

type Boxed<'t, 's, I, O> = chumsky::Boxed<'t, 't, I, O, Extra<'t, 's>>;

/// The whole file: statements up to the end. A stray closing bracket at the
/// top level is reported and skipped.
pub(super) fn program<'t, 's: 't, I: TokenInput<'t, 's>>(file: FileId) -> impl Parser<'t, I, Program, Extra<'t, 's>> {
    let stmt = recursive(move |stmt| statement(file, guarded(stmt)));
    let stray = punct(Punct::RBrace).validate(move |_, e, emitter| {
        emitter.emit(SyntaxError::custom(
            e.span(),
            Problem::Custom(
                d::UNMATCHED_CLOSER,
                "this `}` has no `{` to close".to_string(),
                "nothing to close",
                Some("remove it, or add the `{` it belongs to"),
            ),
        ));
        Stmt::error(span(file, e.span()))
    });
    stmt.or(stray).repeated().collect::<Vec<_>>().then_ignore(end()).map_with(move |mut body, e| {
        let whole: SimpleSpan = e.span();
        if let Some(temps) = patterns::declare_temps(e.state(), SimpleSpan::from(0..usize::MAX), file) {
            body.insert(0, temps);
        }
        Program { body, span: span(file, whole) }
    })
}

/// `{ statements }`, with the span of the braces. At the end of the file a
/// missing `}` is reported at its `{`.
pub(super) fn braced<'t, 's: 't, I, S>(stmt: S) -> Boxed<'t, 's, I, (Vec<Stmt>, SimpleSpan)>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    punct(Punct::LBrace)
        .map_with(|_, e| e.span())
        .then(stmt.repeated().collect::<Vec<_>>())
        .then(punct(Punct::RBrace).to(true).or(end().to(false)))
        .validate(|((open, body), closed), e, emitter| {
            if !closed {
                emitter.emit(SyntaxError::custom(
                    open,
                    Problem::Custom(
                        d::UNCLOSED,
                        "this `{` is never closed".to_string(),
                        "opened here",
                        Some("add the missing `}`"),
                    ),
                ));
            }
            (body, e.span())
        })
        .boxed()
}

/// One statement, with recovery: a statement that does not parse is
/// reported and skipped.
pub(super) fn statement<'t, 's: 't, I, S>(file: FileId, stmt: S) -> Boxed<'t, 's, I, Stmt>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    let assign = expression(file, stmt.clone());
    let seq = sequence(file, assign.clone());
    let body = braced(stmt.clone());
    let at = move |s: SimpleSpan| span(file, s);
    let mk = move |kind: StmtKind, s: SimpleSpan| Stmt::new(kind, span(file, s));
    let cond = seq
        .clone()
        .delimited_by(punct(Punct::LParen), punct(Punct::RParen))
        .recover_with(via_parser(super::balanced(Punct::LParen).map(move |s| Expr::error(at(s)))))
        .boxed();

    let declarator = name(file)
        .then(punct(Punct::Assign).ignore_then(assign.clone()).or_not())
        .map_with(move |(name, init), e| vec![VarDeclarator { name, init, span: at(e.span()) }]);
    // `var [a, b] = list`, `var {a, b} = obj`: written out in Fusion
    // (super::patterns), reported in CNC-Calc posts.
    let patterned = element(file, assign.clone()).validate(move |el, e, emitter| {
        let whole = at(e.span());
        let pattern_at = el.pattern.span();
        let simple = SimpleSpan::from(pattern_at.start..pattern_at.end);
        match el.default {
            Some(init) if e.state().fusion() => patterns::declarators(&el.pattern, init, whole),
            init => {
                if e.state().fusion() {
                    emitter.emit(SyntaxError::custom(
                        simple,
                        Problem::Custom(
                            d::SYNTAX_ERROR,
                            "a destructuring declaration needs a value".to_string(),
                            "no `=` after this",
                            Some("write `var [a, b] = list;`"),
                        ),
                    ));
                } else {
                    emitter.emit(unsupported(Construct::Destructuring, simple));
                }
                let name = crate::ast::Ident { name: String::new(), span: pattern_at };
                vec![VarDeclarator { name, init, span: whole }]
            }
        }
    });
    let destructured = super::balanced(Punct::LBrace)
        .or(super::balanced(Punct::LBracket))
        .then(punct(Punct::Assign).ignore_then(assign.clone()).or_not())
        .validate(move |(s, init), e, emitter| {
            emitter.emit(unsupported(Construct::Destructuring, s));
            let name = crate::ast::Ident { name: String::new(), span: at(s) };
            vec![VarDeclarator { name, init, span: at(e.span()) }]
        });
    let declarators = choice((declarator.boxed(), patterned.boxed(), destructured.boxed()))
        .labelled("a variable name")
        .separated_by(punct(Punct::Comma))
        .at_least(1)
        .collect::<Vec<_>>()
        .map(|groups| groups.into_iter().flatten().collect::<Vec<_>>())
        .boxed();
    // `let x` / `const x`: reported, then read as `var`.
    let let_or_const = word("let")
        .then_ignore(same_line())
        .then_ignore(
            any()
                .filter(|t: &Token<'s>| {
                    matches!(t.kind, crate::token::TokenKind::Ident(_))
                        || t.is_punct(Punct::LBrace)
                        || t.is_punct(Punct::LBracket)
                })
                .rewind(),
        )
        .to(Construct::Let)
        .or(kw(Keyword::Const).to(Construct::Const))
        .map_with(|c, e| (c, e.span()))
        .boxed();

    let var = kw(Keyword::Var)
        .ignore_then(declarators.clone())
        .then_ignore(terminator())
        .map_with(move |decls, e| mk(StmtKind::Var(decls), e.span()));
    let let_const = let_or_const.clone().then(declarators.clone()).then_ignore(terminator()).validate(
        move |((c, s), decls), e, emitter| {
            emitter.emit(unsupported(c, s));
            mk(StmtKind::Var(decls), e.span())
        },
    );
    let function = function_parts(file, stmt.clone(), assign.clone()).validate(move |f, e, emitter| {
        if f.name.is_none() {
            emitter.emit(SyntaxError::custom(
                e.span(),
                Problem::Custom(
                    d::SYNTAX_ERROR,
                    "a function declared as a statement needs a name".to_string(),
                    "no name",
                    Some("write `function name(...) { ... }`, or assign the function: `var name = function (...) { ... };`"),
                ),
            ));
        }
        mk(StmtKind::Function(f), e.span())
    });
    let block = body.clone().map_with(move |(b, _), e| mk(StmtKind::Block(b), e.span()));

    let else_if = kw(Keyword::Else)
        .ignore_then(kw(Keyword::If))
        .ignore_then(cond.clone())
        .then(stmt.clone())
        .map(|(cond, body)| IfBranch { cond, body });
    let if_ = kw(Keyword::If)
        .ignore_then(cond.clone())
        .then(stmt.clone())
        .map(|(cond, body)| IfBranch { cond, body })
        .then(else_if.repeated().collect::<Vec<_>>())
        .then(kw(Keyword::Else).ignore_then(stmt.clone()).or_not())
        .map_with(move |((first, mut rest), otherwise), e| {
            rest.insert(0, first);
            mk(StmtKind::If { branches: rest, otherwise: otherwise.map(Box::new) }, e.span())
        });

    let while_ = kw(Keyword::While)
        .ignore_then(cond.clone())
        .then(stmt.clone())
        .map_with(move |(cond, body), e| mk(StmtKind::While { cond, body: Box::new(body) }, e.span()));
    let do_while = kw(Keyword::Do)
        .ignore_then(stmt.clone())
        .then_ignore(kw(Keyword::While))
        .then(cond.clone())
        .then_ignore(punct(Punct::Semi).or_not())
        .map_with(move |(body, cond), e| mk(StmtKind::DoWhile { body: Box::new(body), cond }, e.span()));

    let for_ = for_statement(file, stmt.clone(), seq.clone(), declarators, let_or_const);
    let switch = switch_statement(file, stmt.clone(), seq.clone(), cond.clone());

    let catch = kw(Keyword::Catch)
        .ignore_then(name(file).delimited_by(punct(Punct::LParen), punct(Punct::RParen)))
        .then(body.clone())
        .map_with(move |(param, (body, _)), e| CatchClause { param, body, span: at(e.span()) });
    let try_ = kw(Keyword::Try)
        .ignore_then(body.clone())
        .then(catch.or_not())
        .then(kw(Keyword::Finally).ignore_then(body.clone()).or_not())
        .validate(move |(((block, _), handler), finalizer), e, emitter| {
            if handler.is_none() && finalizer.is_none() {
                emitter.emit(SyntaxError::custom(
                    e.span(),
                    Problem::Custom(
                        d::TRY_WITHOUT_HANDLER,
                        "`try` needs a `catch` or a `finally` block after it".to_string(),
                        "no `catch` or `finally`",
                        Some("add `catch (e) { ... }`"),
                    ),
                ));
            }
            let kind = StmtKind::Try { block, handler, finalizer: finalizer.map(|(b, _)| b) };
            mk(kind, e.span())
        });

    let label_after =
        same_line().ignore_then(name(file)).map_with(|_, e| e.span()).or_not().validate(|label, _, emitter| {
            if let Some(s) = label {
                emitter.emit(unsupported(Construct::Label, s));
            }
        });
    let break_ = kw(Keyword::Break)
        .ignore_then(label_after.clone())
        .then_ignore(terminator())
        .map_with(move |_, e| mk(StmtKind::Break, e.span()));
    let continue_ = kw(Keyword::Continue)
        .ignore_then(label_after)
        .then_ignore(terminator())
        .map_with(move |_, e| mk(StmtKind::Continue, e.span()));
    let return_ = kw(Keyword::Return)
        .ignore_then(same_line().ignore_then(seq.clone()).or_not())
        .then_ignore(terminator())
        .map_with(move |value, e| mk(StmtKind::Return(value), e.span()));
    let throw = kw(Keyword::Throw)
        .ignore_then(seq.clone())
        .then_ignore(terminator())
        .map_with(move |value, e| mk(StmtKind::Throw(value), e.span()));
    let empty = punct(Punct::Semi).map_with(move |_, e| mk(StmtKind::Empty, e.span()));

    let unsupported_stmts = unsupported_statements(file, stmt.clone(), cond);
    // An expression statement cannot start with `function` or `{` (those
    // are a declaration and a block), which also keeps the parser from
    // reading a failed declaration a second time.
    let expr_stmt = kw(Keyword::Function)
        .or(punct(Punct::LBrace))
        .not()
        .ignore_then(seq)
        .then_ignore(terminator())
        .map_with(move |value, e| mk(StmtKind::Expr(value), e.span()));

    choice((
        block.boxed(),
        var.boxed(),
        let_const.boxed(),
        function.boxed(),
        if_.boxed(),
        for_,
        while_.boxed(),
        do_while.boxed(),
        switch,
        try_.boxed(),
        return_.boxed(),
        break_.boxed(),
        continue_.boxed(),
        throw.boxed(),
        empty.boxed(),
        unsupported_stmts,
        expr_stmt.boxed(),
    ))
    .labelled("a statement")
    .recover_with(via_parser(skip_statement(file)))
    .map_with(|s, e| {
        let at = e.span();
        cap_stmt(s, e.state(), at)
    })
    .boxed()
}
