//! The statement grammar: simple statements (those that fit on one line,
//! single-line `If` included) and the lines that open, continue or close a
//! block (`Sub`, `If ... Then`, `ElseIf`, `Else`, `End If`, `Select Case`,
//! `Case`, `For`, `Next`, `While`, `Wend`, `Do`, `Loop`, ...), as
//! [`LineItem`]s. How blocks nest is decided afterwards, by
//! [`crate::blocks`].

use chumsky::input::ValueInput;
use chumsky::prelude::*;
use postc_ir::FileId;

use super::expr::{comparison, expression};
use super::{Extra, LineItem, kw, name, span};
use crate::ast::{CaseTest, DimItem, ExitKind, FormalParam, LoopKind, LoopTest, Name, ProcKind, Stmt, StmtKind};
use crate::token::{Kw, Op, Token};

/// A statement that fits on one line.
pub(crate) fn simple_statement<'t, I>(file: FileId) -> impl Parser<'t, I, Stmt, Extra<'t>> + Clone
where
    I: ValueInput<'t, Token = Token, Span = SimpleSpan>,
{
    recursive(move |simple| {
        let expr = expression(file);
        let stmt_end =
            choice((just(Token::Newline).ignored(), just(Token::Colon).ignored(), kw(Kw::Else).ignored(), end()))
                .rewind();
        let args_paren = expr
            .clone()
            .separated_by(just(Token::Comma))
            .collect::<Vec<_>>()
            .delimited_by(just(Token::LParen), just(Token::RParen));

        let assign = kw(Kw::Let)
            .or_not()
            .ignore_then(name(file))
            .then_ignore(just(Token::Op(Op::Eq)))
            .then(expr.clone())
            .map(|(target, value)| StmtKind::Assign { target, value });
        let set_property = name(file)
            .then_ignore(just(Token::Dot))
            .then(name(file))
            .then_ignore(just(Token::Op(Op::Eq)))
            .then(expr.clone())
            .map(|((register, property), value)| StmtKind::SetProperty { register, property, value });
        let out = kw(Kw::Out).ignore_then(expr.clone().or_not()).map(StmtKind::Out);
        let call_keyword = kw(Kw::Call)
            .ignore_then(name(file))
            .then(args_paren.clone().or_not())
            .map(|(name, args)| StmtKind::Call { name, args: args.unwrap_or_default() });
        let call_paren =
            name(file).then(args_paren).then_ignore(stmt_end).map(|(name, args)| StmtKind::Call { name, args });
        let call_bare = name(file)
            .then(expr.clone().separated_by(just(Token::Comma)).collect::<Vec<_>>())
            .map(|(name, args)| StmtKind::Call { name, args });
        let exit = kw(Kw::Exit)
            .ignore_then(select! {
                Token::Kw(Kw::Sub) => ExitKind::Sub,
                Token::Kw(Kw::Function) => ExitKind::Function,
                Token::Kw(Kw::For) => ExitKind::For,
                Token::Kw(Kw::Do) => ExitKind::Do,
                Token::Kw(Kw::While) => ExitKind::While,
            })
            .map(StmtKind::Exit);

        let bounds = just(Token::LParen)
            .then(none_of([Token::RParen, Token::Newline]).repeated())
            .then(just(Token::RParen))
            .map_with(move |_, e| span(file, e.span()));
        let dim_item = name(file)
            .then(bounds.or_not())
            .then(kw(Kw::As).ignore_then(name(file)).or_not())
            .then(just(Token::Op(Op::Eq)).ignore_then(expr.clone()).or_not())
            .map(|(((name, array), ty), init)| DimItem { name, array, ty, init });
        let dim = choice((kw(Kw::Dim), kw(Kw::Public), kw(Kw::Private)))
            .ignore_then(dim_item.separated_by(just(Token::Comma)).at_least(1).collect::<Vec<_>>())
            .map(StmtKind::Dim);
        let constant = name(file)
            .then_ignore(kw(Kw::As).then(name(file)).or_not())
            .then_ignore(just(Token::Op(Op::Eq)))
            .then(expr.clone());
        let constants = kw(Kw::Const)
            .ignore_then(constant.separated_by(just(Token::Comma)).at_least(1).collect::<Vec<_>>())
            .map(StmtKind::Const);

        let list = simple.separated_by(just(Token::Colon)).at_least(1).collect::<Vec<Stmt>>();
        let single_if = kw(Kw::If)
            .ignore_then(expr.clone())
            .then_ignore(kw(Kw::Then))
            .then(list.clone())
            .then(kw(Kw::Else).ignore_then(list).or_not())
            .map(|((cond, then), otherwise)| StmtKind::If {
                branches: vec![(cond, then)],
                otherwise: otherwise.unwrap_or_default(),
            });

        choice((single_if, out, exit, dim, constants, call_keyword, assign, set_property, call_paren, call_bare))
            .map_with(move |kind, e| Stmt { kind, span: span(file, e.span()) })
            .labelled("a statement")
    })
}

/// A line item other than `Else`: a block line or a simple statement.
pub(crate) fn line_item<'t, I>(file: FileId) -> impl Parser<'t, I, LineItem, Extra<'t>> + Clone
where
    I: ValueInput<'t, Token = Token, Span = SimpleSpan>,
{
    let expr = expression(file);
    let line_end = choice((just(Token::Newline).ignored(), end())).rewind();
    let proc_kind = choice((kw(Kw::Sub).to(ProcKind::Sub), kw(Kw::Function).to(ProcKind::Function)));
    let pass_by = select! {
        Token::Ident(w) if w.eq_ignore_ascii_case("ByVal") => false,
        Token::Ident(w) if w.eq_ignore_ascii_case("ByRef") => true,
    };
    let formal = pass_by.or_not().then(name(file)).then(kw(Kw::As).ignore_then(name(file)).or_not()).map(
        |((by_ref, name), ty): ((Option<bool>, Name), Option<Name>)| FormalParam {
            name,
            by_ref: by_ref.unwrap_or(false),
            ty,
        },
    );
    let formals = formal
        .separated_by(just(Token::Comma))
        .collect::<Vec<_>>()
        .delimited_by(just(Token::LParen), just(Token::RParen));
    let proc_start = choice((kw(Kw::Public), kw(Kw::Private)))
        .or_not()
        .ignore_then(proc_kind.clone())
        .then(name(file))
        .then(formals.or_not())
        .then_ignore(kw(Kw::As).then(name(file)).or_not())
        .map_with(move |((kind, name), params), e| LineItem::ProcStart {
            kind,
            name,
            params: params.unwrap_or_default(),
            span: span(file, e.span()),
        });
    let proc_end = kw(Kw::End)
        .ignore_then(proc_kind)
        .map_with(move |kind, e| LineItem::ProcEnd { kind, span: span(file, e.span()) });

    let if_start = kw(Kw::If)
        .ignore_then(expr.clone())
        .then_ignore(kw(Kw::Then))
        .then_ignore(line_end)
        .map_with(move |cond, e| LineItem::IfStart { cond, span: span(file, e.span()) });
    let else_if = kw(Kw::ElseIf)
        .ignore_then(expr.clone())
        .then_ignore(kw(Kw::Then))
        .map_with(move |cond, e| LineItem::ElseIf { cond, span: span(file, e.span()) });
    let end_if = kw(Kw::End).then(kw(Kw::If)).map_with(move |_, e| LineItem::EndIf { span: span(file, e.span()) });

    let select_start = kw(Kw::Select)
        .then(kw(Kw::Case))
        .ignore_then(expr.clone())
        .map_with(move |subject, e| LineItem::SelectStart { subject, span: span(file, e.span()) });
    let case_else =
        kw(Kw::Case).then(kw(Kw::Else)).map_with(move |_, e| LineItem::CaseElse { span: span(file, e.span()) });
    let case_test = choice((
        kw(Kw::Is).or_not().ignore_then(comparison()).then(expr.clone()).map(|(op, e)| CaseTest::Is(op, e)),
        expr.clone().then(kw(Kw::To).ignore_then(expr.clone()).or_not()).map(|(from, to)| match to {
            Some(to) => CaseTest::Range(from, to),
            None => CaseTest::Value(from),
        }),
    ));
    let case = kw(Kw::Case)
        .ignore_then(case_test.separated_by(just(Token::Comma)).at_least(1).collect::<Vec<_>>())
        .map_with(move |tests, e| LineItem::Case { tests, span: span(file, e.span()) });
    let end_select =
        kw(Kw::End).then(kw(Kw::Select)).map_with(move |_, e| LineItem::EndSelect { span: span(file, e.span()) });

    let for_start = kw(Kw::For)
        .ignore_then(name(file))
        .then_ignore(just(Token::Op(Op::Eq)))
        .then(expr.clone())
        .then_ignore(kw(Kw::To))
        .then(expr.clone())
        .then(kw(Kw::Step).ignore_then(expr.clone()).or_not())
        .map_with(move |(((var, from), to), step), e| LineItem::ForStart {
            var,
            from,
            to,
            step,
            span: span(file, e.span()),
        });
    let next = kw(Kw::Next)
        .ignore_then(name(file).or_not())
        .map_with(move |var, e| LineItem::Next { var, span: span(file, e.span()) });

    let loop_test = choice((kw(Kw::While).to(false), kw(Kw::Until).to(true)))
        .then(expr.clone())
        .map(|(until, cond)| LoopTest { until, cond });
    let while_start = kw(Kw::While).ignore_then(expr).map_with(move |cond, e| LineItem::LoopStart {
        kind: LoopKind::While,
        test: Some(LoopTest { until: false, cond }),
        span: span(file, e.span()),
    });
    let wend = choice((kw(Kw::Wend).ignored(), kw(Kw::End).then(kw(Kw::While)).ignored()))
        .map_with(move |_, e| LineItem::LoopEnd { kind: LoopKind::While, test: None, span: span(file, e.span()) });
    let do_start = kw(Kw::Do).ignore_then(loop_test.clone().or_not()).map_with(move |test, e| LineItem::LoopStart {
        kind: LoopKind::Do,
        test,
        span: span(file, e.span()),
    });
    let loop_end = kw(Kw::Loop).ignore_then(loop_test.or_not()).map_with(move |test, e| LineItem::LoopEnd {
        kind: LoopKind::Do,
        test,
        span: span(file, e.span()),
    });

    let unreadable = just(Token::Error).map_with(move |_, e| LineItem::Error { span: span(file, e.span()) });

    choice((
        unreadable,
        proc_start,
        proc_end,
        end_if,
        end_select,
        wend,
        if_start,
        else_if,
        select_start,
        case_else,
        case,
        for_start,
        next,
        while_start,
        do_start,
        loop_end,
        simple_statement(file).map(LineItem::Stmt),
    ))
    .boxed()
}
