//! The binary operators by precedence (a Pratt parser), the conditional
//! operator, and assignments. `instanceof` (in CNC-Calc posts), `**`,
//! `??`, logical assignment and arrow functions are parsed so they can be
//! named in a diagnostic.

use chumsky::pratt::{infix, left, right};
use chumsky::prelude::*;
use postc_ir::FileId;

use super::SyntaxError;
use super::patterns;
use super::{Extra, Problem, TokenInput, cap_expr, kw, punct, span, unsupported};
use crate::ast::{AssignOp, BinaryOp, Expr, ExprKind, LogicalOp, Stmt};
use crate::diagnostics as d;
use crate::diagnostics::Construct;
use crate::token::{Keyword, Punct, Token, TokenKind};

use super::expr::check_target;
use super::stmt::braced;

type Boxed<'t, 's, I, O> = chumsky::Boxed<'t, 't, I, O, Extra<'t, 's>>;

/// The binary operators, by precedence (lowest first).
pub(super) fn binary<'t, 's: 't, I: TokenInput<'t, 's>>(unary: Boxed<'t, 's, I, Expr>) -> Boxed<'t, 's, I, Expr> {
    #[derive(Clone, Copy)]
    enum Op {
        Binary(BinaryOp),
        Logical(LogicalOp),
        Unsupported(Construct),
    }
    let fold = move |l: Expr,
                     (op, at): (Op, SimpleSpan),
                     r: Expr,
                     e: &mut chumsky::input::MapExtra<'t, '_, I, Extra<'t, 's>>| {
        let whole = l.span.to(r.span);
        let node = match op {
            Op::Binary(op) => Expr::new(ExprKind::Binary { op, left: Box::new(l), right: Box::new(r) }, whole),
            // Fusion posts have prototypes to test; CNC-Calc posts are refused it.
            Op::Unsupported(Construct::Instanceof) if e.state().fusion() => {
                let op = BinaryOp::Instanceof;
                Expr::new(ExprKind::Binary { op, left: Box::new(l), right: Box::new(r) }, whole)
            }
            Op::Logical(op) => Expr::new(ExprKind::Logical { op, left: Box::new(l), right: Box::new(r) }, whole),
            Op::Unsupported(construct) => {
                e.emit(unsupported(construct, at));
                Expr::error(whole)
            }
        };
        cap_expr(node, e.state(), at)
    };
    // One parser a level: a failure adds the level's operators to the
    // expected set at once, in the order listed.
    let ops = |list: Vec<(Punct, Op)>| {
        let tokens: Vec<Token<'s>> = list.iter().map(|&(p, _)| Token::punct(p)).collect();
        one_of(tokens)
            .map(move |t: Token<'s>| list.iter().find(|&&(p, _)| t.is_punct(p)).map_or(list[0].1, |&(_, op)| op))
            .map_with(|op, e| (op, e.span()))
            .boxed()
    };
    use BinaryOp as B;
    let or =
        ops(vec![(Punct::PipePipe, Op::Logical(LogicalOp::Or)), (Punct::Nullish, Op::Unsupported(Construct::Nullish))]);
    let and = ops(vec![(Punct::AmpAmp, Op::Logical(LogicalOp::And))]);
    let bit_or = ops(vec![(Punct::Pipe, Op::Binary(B::BitOr))]);
    let bit_xor = ops(vec![(Punct::Caret, Op::Binary(B::BitXor))]);
    let bit_and = ops(vec![(Punct::Amp, Op::Binary(B::BitAnd))]);
    let equality = ops(vec![
        (Punct::StrictEq, Op::Binary(B::StrictEq)),
        (Punct::StrictNe, Op::Binary(B::StrictNe)),
        (Punct::EqEq, Op::Binary(B::Eq)),
        (Punct::NotEq, Op::Binary(B::Ne)),
    ]);
    let relational = ops(vec![
        (Punct::LtEq, Op::Binary(B::Le)),
        (Punct::GtEq, Op::Binary(B::Ge)),
        (Punct::Lt, Op::Binary(B::Lt)),
        (Punct::Gt, Op::Binary(B::Gt)),
    ])
    .or(kw(Keyword::In).to(Op::Binary(B::In)).map_with(|op, e| (op, e.span())))
    .or(kw(Keyword::Instanceof).to(Op::Unsupported(Construct::Instanceof)).map_with(|op, e| (op, e.span())));
    let shift = ops(vec![
        (Punct::UShr, Op::Binary(B::UShr)),
        (Punct::Shl, Op::Binary(B::Shl)),
        (Punct::Shr, Op::Binary(B::Shr)),
    ]);
    let additive = ops(vec![(Punct::Plus, Op::Binary(B::Add)), (Punct::Minus, Op::Binary(B::Sub))]);
    let multiplicative = ops(vec![
        (Punct::Star, Op::Binary(B::Mul)),
        (Punct::Slash, Op::Binary(B::Div)),
        (Punct::Percent, Op::Binary(B::Rem)),
    ]);
    let exponent = ops(vec![(Punct::StarStar, Op::Unsupported(Construct::Exponent))]);
    unary
        .pratt((
            infix(left(1), or, fold),
            infix(left(2), and, fold),
            infix(left(3), bit_or, fold),
            infix(left(4), bit_xor, fold),
            infix(left(5), bit_and, fold),
            infix(left(6), equality, fold),
            infix(left(7), relational, fold),
            infix(left(8), shift, fold),
            infix(left(9), additive, fold),
            infix(left(10), multiplicative, fold),
            infix(right(11), exponent, fold),
        ))
        .boxed()
}

/// The assignment a punctuator stands for, and the construct to report
/// when it is not ES5.
fn assign_op(p: Punct) -> Option<(AssignOp, Option<Construct>)> {
    use AssignOp as A;
    Some(match p {
        Punct::Assign => (A::Assign, None),
        Punct::PlusAssign => (A::Add, None),
        Punct::MinusAssign => (A::Sub, None),
        Punct::StarAssign => (A::Mul, None),
        Punct::SlashAssign => (A::Div, None),
        Punct::PercentAssign => (A::Rem, None),
        Punct::ShlAssign => (A::Shl, None),
        Punct::ShrAssign => (A::Shr, None),
        Punct::UShrAssign => (A::UShr, None),
        Punct::AmpAssign => (A::BitAnd, None),
        Punct::PipeAssign => (A::BitOr, None),
        Punct::CaretAssign => (A::BitXor, None),
        Punct::StarStarAssign => (A::Mul, Some(Construct::Exponent)),
        Punct::AndAssign | Punct::OrAssign | Punct::NullishAssign => (A::Assign, Some(Construct::LogicalAssign)),
        _ => return None,
    })
}

/// What may follow a conditional expression at the assignment level.
#[derive(Clone)]
enum Tail {
    Assign(AssignOp, Option<Construct>, SimpleSpan, Expr),
    Arrow(SimpleSpan),
}

/// `test ? a : b`, then `target op= value` or (reported) `params => body`.
pub(super) fn conditional_and_assignment<'t, 's: 't, I, S>(
    file: FileId,
    binary: Boxed<'t, 's, I, Expr>,
    assign: Boxed<'t, 's, I, Expr>,
    stmt: S,
) -> Boxed<'t, 's, I, Expr>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    let conditional = binary
        .then(
            punct(Punct::Question)
                .ignore_then(assign.clone())
                .then_ignore(punct(Punct::Colon))
                .then(assign.clone())
                .or_not(),
        )
        .map_with(move |(test, branches), e| match branches {
            None => test,
            Some((consequent, alternate)) => {
                let kind = ExprKind::Conditional {
                    test: Box::new(test),
                    consequent: Box::new(consequent),
                    alternate: Box::new(alternate),
                };
                let s = e.span();
                cap_expr(Expr::new(kind, span(file, s)), e.state(), s)
            }
        });
    let op = select! {
        Token { kind: TokenKind::Punct(p), .. } if assign_op(p).is_some() => assign_op(p),
    }
    .map_with(|op, e| {
        let (op, construct) = op.unwrap_or((AssignOp::Assign, None));
        (op, construct, e.span())
    });
    let assignment = op.then(assign.clone()).map(|((op, construct, at), value)| Tail::Assign(op, construct, at, value));
    let brace = punct(Punct::LBrace).rewind();
    let arrow_body = brace.clone().ignore_then(braced(stmt)).ignored().or(brace.not().ignore_then(assign).ignored());
    let arrow = punct(Punct::Arrow).map_with(|_, e| e.span()).then_ignore(arrow_body).map(Tail::Arrow);
    conditional
        .then(choice((assignment, arrow)).or_not())
        .validate(move |(target, tail), e, emitter| match tail {
            None => target,
            // Arrow functions are read where an expression starts
            // (`super::expr`); what is left has no parameters an arrow
            // function can take.
            Some(Tail::Arrow(_)) if e.state().fusion() => {
                let params = SimpleSpan::from(target.span.start..target.span.end);
                emitter.emit(SyntaxError::custom(
                    params,
                    Problem::Custom(
                        d::SYNTAX_ERROR,
                        "an arrow function's parameters are names in brackets: `(a, b) => a + b`".to_string(),
                        "not parameters",
                        None,
                    ),
                ));
                Expr::error(span(file, e.span()))
            }
            Some(Tail::Arrow(at)) => {
                emitter.emit(unsupported(Construct::Arrow, at));
                Expr::error(span(file, e.span()))
            }
            Some(Tail::Assign(op, construct, at, value)) => {
                if let Some(construct) = construct {
                    emitter.emit(unsupported(construct, at));
                }
                // `[a, b] = list`, `({a, b} = obj)`: destructuring in Fusion.
                if op == AssignOp::Assign
                    && matches!(target.kind, ExprKind::Array(_) | ExprKind::Object(_))
                    && e.state().fusion()
                {
                    let whole = span(file, e.span());
                    match patterns::from_expr(&target) {
                        Ok(pattern) => return patterns::assignment(&pattern, value, whole, e.state()),
                        Err(bad) => emitter.emit(SyntaxError::custom(
                            SimpleSpan::from(bad.start..bad.end),
                            Problem::Custom(
                                d::INVALID_ASSIGNMENT,
                                "a destructuring assignment takes variables, properties (`a.b`) and elements (`a[i]`)"
                                    .to_string(),
                                "cannot be assigned",
                                None,
                            ),
                        )),
                    }
                    return Expr::error(whole);
                }
                check_target(&target, emitter);
                let kind = ExprKind::Assign { op, target: Box::new(target), value: Box::new(value) };
                Expr::new(kind, span(file, e.span()))
            }
        })
        .boxed()
}
