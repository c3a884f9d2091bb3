//! `for` in its three forms (`for (;;)`, `for (var k in obj)`, and the
//! reported `for ... of`) and `switch` with fallthrough cases.

use chumsky::prelude::*;
use postc_ir::FileId;

use super::SyntaxError;
use super::{Extra, Problem, TokenInput, kw, name, punct, span, unsupported, word};
use crate::ast::{Expr, ForInit, Stmt, StmtKind, SwitchCase, VarDeclarator};
use crate::diagnostics::{self as d, Construct};
use crate::token::{Keyword, Punct};

type Boxed<'t, 's, I, O> = chumsky::Boxed<'t, 't, I, O, Extra<'t, 's>>;

/// `for (init; test; update)`, `for (var k in obj)`, and (reported)
/// `for (var x of list)`.
pub(super) fn for_statement<'t, 's: 't, I, S>(
    file: FileId,
    stmt: S,
    seq: Boxed<'t, 's, I, Expr>,
    declarators: Boxed<'t, 's, I, Vec<VarDeclarator>>,
    let_or_const: Boxed<'t, 's, I, (Construct, SimpleSpan)>,
) -> Boxed<'t, 's, I, Stmt>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    #[derive(Clone)]
    enum Head {
        In { declared: bool, name: crate::ast::Ident, object: Expr },
        Classic { init: Option<ForInit>, test: Option<Expr>, update: Option<Expr> },
    }
    let declared = kw(Keyword::Var).to(true).or(let_or_const.clone().validate(|(c, s), _, emitter| {
        emitter.emit(unsupported(c, s));
        true
    }));
    // Once `var k in` or `var k of` is seen, the head is that form: the
    // classic form is not tried after it fails.
    let in_ahead = declared.clone().or_not().then(name(file)).then(kw(Keyword::In)).rewind();
    let of_ahead = declared.clone().or_not().then(name(file)).then(word("of")).rewind();
    let for_in = in_ahead
        .clone()
        .ignore_then(declared.clone().or_not())
        .then(name(file))
        .then_ignore(kw(Keyword::In))
        .then(seq.clone())
        .map(|((declared, name), object)| Head::In { declared: declared.is_some(), name, object });
    let for_of = of_ahead
        .clone()
        .ignore_then(declared.or_not())
        .then(name(file))
        .then(word("of").map_with(|_, e| e.span()))
        .then(seq.clone())
        .validate(|(((declared, name), at), object), _, emitter| {
            emitter.emit(unsupported(Construct::ForOf, at));
            Head::In { declared: declared.is_some(), name, object }
        });
    let init = choice((
        kw(Keyword::Var).ignore_then(declarators.clone()).map(ForInit::Var),
        let_or_const.then(declarators).validate(|((c, s), decls), _, emitter| {
            emitter.emit(unsupported(c, s));
            ForInit::Var(decls)
        }),
        seq.clone().map(ForInit::Expr),
    ));
    let classic = in_ahead
        .not()
        .then(of_ahead.not())
        .ignore_then(init.or_not())
        .then_ignore(punct(Punct::Semi))
        .then(seq.clone().or_not())
        .then_ignore(punct(Punct::Semi))
        .then(seq.or_not())
        .map(|((init, test), update)| Head::Classic { init, test, update });
    kw(Keyword::For)
        .ignore_then(
            choice((for_in.boxed(), for_of.boxed(), classic.boxed()))
                .delimited_by(punct(Punct::LParen), punct(Punct::RParen)),
        )
        .then(stmt)
        .map_with(move |(head, body), e| {
            let body = Box::new(body);
            let kind = match head {
                Head::In { declared, name, object } => StmtKind::ForIn { declared, name, object, body },
                Head::Classic { init, test, update } => StmtKind::For { init, test, update, body },
            };
            Stmt::new(kind, span(file, e.span()))
        })
        .boxed()
}

/// `switch (x) { case a: ... default: ... }`
pub(super) fn switch_statement<'t, 's: 't, I, S>(
    file: FileId,
    stmt: S,
    seq: Boxed<'t, 's, I, Expr>,
    cond: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Stmt>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    let label = kw(Keyword::Case)
        .ignore_then(seq)
        .map(Some)
        .or(kw(Keyword::Default).to(None))
        .map_with(|test, e| (test, e.span()))
        .then_ignore(punct(Punct::Colon));
    let case_body = kw(Keyword::Case).or(kw(Keyword::Default)).not().ignore_then(stmt).repeated().collect::<Vec<_>>();
    let case = label
        .then(case_body)
        .map_with(move |((test, at), body), e| (at, SwitchCase { test, body, span: span(file, e.span()) }));
    kw(Keyword::Switch)
        .ignore_then(cond)
        .then(case.repeated().collect::<Vec<_>>().delimited_by(punct(Punct::LBrace), punct(Punct::RBrace)))
        .validate(move |(discriminant, cases), e, emitter| {
            let mut seen_default = false;
            let mut kept = Vec::with_capacity(cases.len());
            for (at, case) in cases {
                if case.test.is_none() {
                    if seen_default {
                        emitter.emit(SyntaxError::custom(
                            at,
                            Problem::Custom(
                                d::DUPLICATE_DEFAULT,
                                "a `switch` can have only one `default`".to_string(),
                                "second `default`",
                                None,
                            ),
                        ));
                    }
                    seen_default = true;
                }
                kept.push(case);
            }
            Stmt::new(StmtKind::Switch { discriminant, cases: kept }, span(file, e.span()))
        })
        .boxed()
}
