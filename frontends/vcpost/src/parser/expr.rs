//! The expression grammar: a chumsky Pratt parser over tokens with BASIC's
//! operator precedence, tightest first:
//!
//! | level | operators | associativity |
//! |-------|-----------|---------------|
//! | 12 | `^` | left (`2^3^2` is 64, as in VB) |
//! | 11 | unary `-` `+` | (`-2^2` is -4, as in VB) |
//! | 10 | `*` `/` | left |
//! | 9  | `\` (integer division) | left |
//! | 8  | `Mod` | left |
//! | 7  | `+` `-` | left |
//! | 6  | `&` (join as text) | left |
//! | 5  | `=` `<>` `<` `<=` `>` `>=` | left |
//! | 4  | `Not` | (`Not a = b` is `Not (a = b)`) |
//! | 3  | `And` | left |
//! | 2  | `Or` | left |
//! | 1  | `Xor` | left |
//!
//! Atoms are numbers, strings, `True`/`False`, names, `Name.Previous` (any
//! other `.Property` is parsed and refused later), calls `Name(args)` and
//! parenthesized expressions.

use chumsky::input::ValueInput;
use chumsky::pratt::{infix, left, prefix};
use chumsky::prelude::*;
use postc_ir::FileId;

use super::{Extra, name, span};
use crate::ast::{BinaryOp, Expr, ExprKind, UnaryOp};
use crate::token::{Kw, Op, Token};

/// Parses one expression.
pub(crate) fn expression<'t, I>(file: FileId) -> impl Parser<'t, I, Expr, Extra<'t>> + Clone
where
    I: ValueInput<'t, Token = Token, Span = SimpleSpan>,
{
    recursive(move |expr| {
        let args = expr
            .clone()
            .separated_by(just(Token::Comma))
            .collect::<Vec<_>>()
            .delimited_by(just(Token::LParen), just(Token::RParen));
        let literal = select! {
            Token::Number(n) => ExprKind::Number(n),
            Token::Str(s) => ExprKind::Text(s),
            Token::Kw(Kw::True) => ExprKind::Bool(true),
            Token::Kw(Kw::False) => ExprKind::Bool(false),
        };
        let property = name(file).then_ignore(just(Token::Dot)).then(name(file)).map(|(target, property)| {
            if property.is("Previous") { ExprKind::Previous(target) } else { ExprKind::Property { target, property } }
        });
        let call = name(file).then(args).map(|(name, args)| ExprKind::Call { name, args });
        let plain = name(file).map(ExprKind::Name);
        let paren =
            expr.clone().delimited_by(just(Token::LParen), just(Token::RParen)).map(|e| ExprKind::Paren(Box::new(e)));
        let atom = choice((literal, property, call, plain, paren))
            .map_with(move |kind, e| Expr { kind, span: span(file, e.span()) })
            .labelled("a value");

        let binary = move |l: Expr, op: BinaryOp, r: Expr, s: SimpleSpan| Expr {
            kind: ExprKind::Binary(op, Box::new(l), Box::new(r)),
            span: span(file, s),
        };
        let unary = move |op: UnaryOp, e: Expr, s: SimpleSpan| Expr {
            kind: ExprKind::Unary(op, Box::new(e)),
            span: span(file, s),
        };
        atom.pratt((
            infix(left(12), just(Token::Op(Op::Caret)).to(BinaryOp::Pow), move |l, op, r, e| {
                binary(l, op, r, e.span())
            }),
            prefix(
                11,
                select! { Token::Op(Op::Minus) => UnaryOp::Neg, Token::Op(Op::Plus) => UnaryOp::Plus },
                move |op, r, e| unary(op, r, e.span()),
            ),
            infix(
                left(10),
                select! { Token::Op(Op::Star) => BinaryOp::Mul, Token::Op(Op::Slash) => BinaryOp::Div },
                move |l, op, r, e| binary(l, op, r, e.span()),
            ),
            infix(left(9), just(Token::Op(Op::Backslash)).to(BinaryOp::IntDiv), move |l, op, r, e| {
                binary(l, op, r, e.span())
            }),
            infix(left(8), just(Token::Kw(Kw::Mod)).to(BinaryOp::Mod), move |l, op, r, e| binary(l, op, r, e.span())),
            infix(
                left(7),
                select! { Token::Op(Op::Plus) => BinaryOp::Add, Token::Op(Op::Minus) => BinaryOp::Sub },
                move |l, op, r, e| binary(l, op, r, e.span()),
            ),
            infix(left(6), just(Token::Op(Op::Amp)).to(BinaryOp::Concat), move |l, op, r, e| {
                binary(l, op, r, e.span())
            }),
            infix(left(5), comparison(), move |l, op, r, e| binary(l, op, r, e.span())),
            prefix(4, just(Token::Kw(Kw::Not)).to(UnaryOp::Not), move |op, r, e| unary(op, r, e.span())),
            infix(left(3), just(Token::Kw(Kw::And)).to(BinaryOp::And), move |l, op, r, e| binary(l, op, r, e.span())),
            infix(left(2), just(Token::Kw(Kw::Or)).to(BinaryOp::Or), move |l, op, r, e| binary(l, op, r, e.span())),
            infix(left(1), just(Token::Kw(Kw::Xor)).to(BinaryOp::Xor), move |l, op, r, e| binary(l, op, r, e.span())),
        ))
        .labelled("an expression")
    })
}

/// A comparison operator.
pub(crate) fn comparison<'t, I>() -> impl Parser<'t, I, BinaryOp, Extra<'t>> + Clone
where
    I: ValueInput<'t, Token = Token, Span = SimpleSpan>,
{
    select! {
        Token::Op(Op::Eq) => BinaryOp::Eq,
        Token::Op(Op::Ne) => BinaryOp::Ne,
        Token::Op(Op::Lt) => BinaryOp::Lt,
        Token::Op(Op::Le) => BinaryOp::Le,
        Token::Op(Op::Gt) => BinaryOp::Gt,
        Token::Op(Op::Ge) => BinaryOp::Ge,
    }
}
