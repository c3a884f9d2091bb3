//! Expressions: the assignment-level entry point, the comma operator,
//! primary expressions (literals, names, brackets), member/index/call
//! chains and `new`, and the prefix and postfix operators. Literals with
//! structure are in [`super::literals`], the binary operators, `?:` and
//! assignments in [`super::operators`].

use chumsky::prelude::*;
use postc_ir::FileId;

use super::SyntaxError;
use super::literals::{arguments, array, function_body, function_parts, object, parameter_list};
use super::operators::{binary, conditional_and_assignment};
use super::patterns::{Element, Pattern};
use super::stmt::braced;
use super::{
    Extra, Problem, TokenInput, balanced, cap_expr, guarded, kw, name, punct, same_line, span, unsupported, word,
};
use crate::ast::{Expr, ExprKind, Function, Ident, Stmt, StmtKind, UnaryOp, UpdateOp};
use crate::diagnostics::{self as d, Construct};
use crate::strings;
use crate::token::{Keyword, Punct, Token, TokenKind};

type Boxed<'t, 's, I, O> = chumsky::Boxed<'t, 't, I, O, Extra<'t, 's>>;

/// The assignment-level expression parser (what an argument, an array
/// element or an initializer is). `stmt` parses one statement, for the
/// bodies of function expressions.
pub(super) fn expression<'t, 's: 't, I, S>(file: FileId, stmt: S) -> Boxed<'t, 's, I, Expr>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    recursive(move |assign| {
        let assign = guarded(assign).boxed();
        let seq = sequence(file, assign.clone());
        let primary = primary(file, assign.clone(), seq.clone(), stmt.clone());
        let chain = call_chain(file, primary, assign.clone(), seq);
        let unary = unary(file, postfix(file, chain));
        let binary = binary(unary);
        conditional_and_assignment(file, binary, assign, stmt.clone())
    })
    .boxed()
}

/// `a, b, c` over the assignment-level parser.
pub(super) fn sequence<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
    assign: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Expr> {
    assign
        .separated_by(punct(Punct::Comma))
        .at_least(1)
        .collect::<Vec<_>>()
        .map_with(move |mut items, e| {
            if items.len() == 1 {
                items.pop().unwrap_or_else(|| Expr::error(span(file, e.span())))
            } else {
                Expr::new(ExprKind::Sequence(items), span(file, e.span()))
            }
        })
        .boxed()
}

/// Literals, names, brackets, object and array literals, function
/// expressions.
fn primary<'t, 's: 't, I, S>(
    file: FileId,
    assign: Boxed<'t, 's, I, Expr>,
    seq: Boxed<'t, 's, I, Expr>,
    stmt: S,
) -> Boxed<'t, 's, I, Expr>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    let literal = select! {
        Token { kind: TokenKind::Number(n), .. } => ExprKind::Number(n),
        Token { kind: TokenKind::String(s), .. } => ExprKind::String(strings::decode(s).0),
        Token { kind: TokenKind::Keyword(Keyword::True), .. } => ExprKind::Bool(true),
        Token { kind: TokenKind::Keyword(Keyword::False), .. } => ExprKind::Bool(false),
        Token { kind: TokenKind::Keyword(Keyword::Null), .. } => ExprKind::Null,
        Token { kind: TokenKind::Keyword(Keyword::This), .. } => ExprKind::This,
        Token { kind: TokenKind::Ident("undefined"), .. } => ExprKind::Undefined,
        Token { kind: TokenKind::Ident(n), .. } => ExprKind::Ident(n.to_string()),
    }
    .map_with(move |kind, e| Expr::new(kind, span(file, e.span())));

    let regex = select! { Token { kind: TokenKind::Regex { pattern, flags }, .. } => (pattern, flags) }.validate(
        move |(pattern, flags): (&str, &str), e, emitter| {
            let mut seen = String::new();
            for c in flags.chars() {
                if !matches!(c, 'g' | 'i' | 'm') || seen.contains(c) {
                    emitter.emit(unsupported(Construct::RegexFlag, e.span()));
                    break;
                }
                seen.push(c);
            }
            let kind = ExprKind::Regex { pattern: pattern.to_string(), flags: flags.to_string() };
            Expr::new(kind, span(file, e.span()))
        },
    );

    let template = select! { Token { kind: TokenKind::Template(_), .. } => () }.validate(move |_, e, emitter| {
        emitter.emit(unsupported(Construct::Template, e.span()));
        Expr::error(span(file, e.span()))
    });
    let fusion_template = template_literal(file, seq.clone());
    let arrow = arrow_function(file, assign.clone(), stmt.clone());

    // `() =>`: the arrow itself is reported by the assignment level.
    let empty_arrow_params = punct(Punct::LParen)
        .then(punct(Punct::RParen))
        .then_ignore(punct(Punct::Arrow).rewind())
        .map_with(move |_, e| Expr::error(span(file, e.span())));

    let paren = seq
        .clone()
        .delimited_by(punct(Punct::LParen), punct(Punct::RParen))
        .recover_with(via_parser(balanced(Punct::LParen).map(move |at| Expr::error(span(file, at)))));

    let array = array(file, assign.clone());
    let object = object(file, assign.clone(), stmt.clone());

    let function = function_parts(file, stmt.clone(), assign.clone())
        .map_with(move |f, e| Expr::new(ExprKind::Function(Box::new(f)), span(file, e.span())));

    let async_function = word("async")
        .map_with(|_, e| e.span())
        .then_ignore(same_line().then(kw(Keyword::Function).rewind()))
        .then(function_parts(file, stmt, assign))
        .validate(move |(at, f), e, emitter| {
            emitter.emit(unsupported(Construct::Async, at));
            Expr::new(ExprKind::Function(Box::new(f)), span(file, e.span()))
        });

    let class = kw(Keyword::Class)
        .map_with(|_, e| e.span())
        .then_ignore(any().filter(|t: &Token<'s>| !t.is_punct(Punct::LBrace)).repeated())
        .then_ignore(balanced(Punct::LBrace))
        .validate(move |at, e, emitter| {
            emitter.emit(unsupported(Construct::Class, at));
            Expr::error(span(file, e.span()))
        });

    choice((
        async_function.boxed(),
        arrow,
        literal.boxed(),
        regex.boxed(),
        template.boxed(),
        fusion_template,
        empty_arrow_params.boxed(),
        paren.boxed(),
        array,
        object,
        function.boxed(),
        class.boxed(),
    ))
    .labelled("an expression")
    .boxed()
}

/// A template literal as Fusion's lexer gives it
/// ([`TokenKind::TemplatePart`]): its text pieces, escapes decoded, and
/// the expression of each `${...}` between them.
fn template_literal<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
    seq: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Expr> {
    let cooked = |raw: &str| strings::decode_template(raw).0;
    let whole = select! { Token { kind: TokenKind::TemplatePart { raw, head: true, tail: true }, .. } => raw }
        .map_with(move |raw, e| {
            Expr::new(ExprKind::Template { quasis: vec![cooked(raw)], exprs: vec![] }, span(file, e.span()))
        });
    let head = select! { Token { kind: TokenKind::TemplatePart { raw, head: true, tail: false }, .. } => raw };
    let middle = select! { Token { kind: TokenKind::TemplatePart { raw, head: false, tail: false }, .. } => raw };
    let tail = select! { Token { kind: TokenKind::TemplatePart { raw, head: false, tail: true }, .. } => raw };
    // Each substitution and the piece after it, read once: a substitution
    // is not parsed again when the piece after it ends the literal.
    let substituted = head
        .then(seq.then(middle.or_not()).repeated().at_least(1).collect::<Vec<_>>())
        .then(tail)
        .validate(move |((head, parts), tail), e, emitter| {
            let mut quasis = vec![cooked(head)];
            let mut exprs = Vec::with_capacity(parts.len());
            let last = parts.len().saturating_sub(1);
            for (k, (expr, middle)) in parts.into_iter().enumerate() {
                let at = SimpleSpan::from(expr.span.end..expr.span.end);
                exprs.push(expr);
                match middle {
                    Some(raw) => quasis.push(cooked(raw)),
                    None if k < last => emitter.emit(SyntaxError::custom(
                        at,
                        Problem::Custom(
                            d::SYNTAX_ERROR,
                            "a template literal's substitution ends with `}`".to_string(),
                            "expected `}` here",
                            None,
                        ),
                    )),
                    None => {}
                }
            }
            quasis.resize(exprs.len(), String::new());
            quasis.push(cooked(tail));
            let s = e.span();
            cap_expr(Expr::new(ExprKind::Template { quasis, exprs }, span(file, s)), e.state(), s)
        });
    choice((whole.boxed(), substituted.boxed())).boxed()
}

/// `x => body`, `(a, b = 1, {c}) => body`: an arrow function, its body a
/// block or an expression (the `return` of it). Reported in CNC-Calc
/// posts.
fn arrow_function<'t, 's: 't, I, S>(file: FileId, assign: Boxed<'t, 's, I, Expr>, stmt: S) -> Boxed<'t, 's, I, Expr>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    #[derive(Clone)]
    enum Body {
        Block(Vec<Stmt>, SimpleSpan),
        Expr(Expr),
    }
    let single = name(file)
        .map_with(move |n, e| vec![Element { pattern: Pattern::Name(n), default: None, span: span(file, e.span()) }]);
    let params = choice((single.boxed(), parameter_list(file, assign.clone())));
    let body = choice((
        braced(stmt).map(|(b, s)| Body::Block(b, s)),
        punct(Punct::LBrace).not().ignore_then(assign).map(Body::Expr),
    ));
    params
        .then(punct(Punct::Arrow).map_with(|_, e| e.span()))
        .then(body)
        .validate(move |((params, arrow_at), body), e, emitter| {
            let whole = e.span();
            if !e.state().fusion() {
                emitter.emit(unsupported(Construct::Arrow, arrow_at));
                return Expr::error(span(file, whole));
            }
            let (stmts, body_span) = match body {
                Body::Block(stmts, s) => (stmts, span(file, s)),
                Body::Expr(value) => {
                    let at = value.span;
                    (vec![Stmt::new(StmtKind::Return(Some(value)), at)], at)
                }
            };
            let (params, body) = function_body(file, params, stmts, whole, e.state(), emitter);
            let f = Function { name: None, params, body, body_span, span: span(file, whole), arrow: true };
            cap_expr(Expr::new(ExprKind::Function(Box::new(f)), span(file, whole)), e.state(), whole)
        })
        .boxed()
}

/// What can follow an expression in a member/call chain.
#[derive(Clone)]
enum Suffix {
    Member(Ident),
    Index(Expr),
    Call(Vec<Expr>),
    /// A template literal after the function: a tagged template.
    Tagged(SimpleSpan),
}

/// `a.b`, `a[b]`, `a(b)` chains, and `new`.
fn call_chain<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
    primary: Boxed<'t, 's, I, Expr>,
    assign: Boxed<'t, 's, I, Expr>,
    seq: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Expr> {
    let property = select! {
        Token { kind: TokenKind::Ident(n), .. } => n,
        Token { kind: TokenKind::Keyword(k), .. } => k.as_str(),
    }
    .map_with(move |n, e| Ident { name: n.to_string(), span: span(file, e.span()) })
    .labelled("a property name");
    let tagged = template_literal(file, seq.clone()).map_with(|_, e| Suffix::Tagged(e.span()));
    let index = seq
        .delimited_by(punct(Punct::LBracket), punct(Punct::RBracket))
        .recover_with(via_parser(balanced(Punct::LBracket).map(move |at| Expr::error(span(file, at)))));
    let member = punct(Punct::Dot).ignore_then(property).map(Suffix::Member);
    // E4X's descendants (`xml..Row`, `xml..ss::Row`), named and read on as a member.
    let descendants = punct(Punct::Dot)
        .ignore_then(punct(Punct::Dot))
        .map_with(|_, e| e.span())
        .then_ignore(property.then(punct(Punct::Colon)).then(punct(Punct::Colon)).or_not())
        .then(property)
        .validate(|(at, property), _, emitter| {
            emitter.emit(unsupported(Construct::E4x, at));
            Suffix::Member(property)
        });
    let optional = punct(Punct::QuestionDot)
        .map_with(|_, e| e.span())
        .then(choice((
            property.map(Suffix::Member),
            index.clone().map(Suffix::Index),
            arguments(file, assign.clone()).map(Suffix::Call),
        )))
        .validate(|(at, suffix), _, emitter| {
            emitter.emit(unsupported(Construct::OptionalChaining, at));
            suffix
        });
    let member_suffix = choice((member.clone(), index.clone().map(Suffix::Index))).boxed();
    let suffix = choice((
        member,
        descendants.boxed(),
        optional.boxed(),
        index.map(Suffix::Index),
        arguments(file, assign.clone()).map(Suffix::Call),
        tagged.boxed(),
    ))
    .boxed();

    let apply = move |object: Expr, suffix: Suffix, e: &mut chumsky::input::MapExtra<'t, '_, I, Extra<'t, 's>>| {
        let at = span(file, e.span());
        let kind = match suffix {
            Suffix::Member(property) => ExprKind::Member { object: Box::new(object), property },
            Suffix::Index(index) => ExprKind::Index { object: Box::new(object), index: Box::new(index) },
            Suffix::Call(args) => ExprKind::Call { callee: Box::new(object), args },
            Suffix::Tagged(template) => {
                e.emit(unsupported(Construct::TaggedTemplate, template));
                ExprKind::Error
            }
        };
        let s = e.span();
        cap_expr(Expr::new(kind, at), e.state(), s)
    };
    let new_callee = primary.clone().foldl_with(member_suffix.repeated(), apply);
    let new = kw(Keyword::New).ignore_then(new_callee).then(arguments(file, assign).or_not()).map_with(
        move |(callee, args), e| {
            let kind = ExprKind::New { callee: Box::new(callee), args: args.unwrap_or_default() };
            Expr::new(kind, span(file, e.span()))
        },
    );
    choice((new.boxed(), primary)).foldl_with(suffix.repeated(), apply).boxed()
}

/// Postfix `++` / `--` (on the same line only).
fn postfix<'t, 's: 't, I: TokenInput<'t, 's>>(file: FileId, chain: Boxed<'t, 's, I, Expr>) -> Boxed<'t, 's, I, Expr> {
    let op = select! {
        Token { kind: TokenKind::Punct(Punct::PlusPlus), newline_before: false } => UpdateOp::Increment,
        Token { kind: TokenKind::Punct(Punct::MinusMinus), newline_before: false } => UpdateOp::Decrement,
    };
    chain
        .then(op.or_not())
        .validate(move |(target, op), e, emitter| match op {
            None => target,
            Some(op) => {
                check_target(&target, emitter);
                let kind = ExprKind::Update { op, prefix: false, target: Box::new(target) };
                Expr::new(kind, span(file, e.span()))
            }
        })
        .boxed()
}

/// Reports an assignment to something that cannot be assigned.
pub(super) fn check_target<'t, 's>(target: &Expr, emitter: &mut chumsky::input::Emitter<super::Error<'t, 's>>) {
    if !target.is_assignable() {
        let at = SimpleSpan::from(target.span.start..target.span.end);
        emitter.emit(SyntaxError::custom(
            at,
            Problem::Custom(
                d::INVALID_ASSIGNMENT,
                "only a variable, a property (`a.b`) or an element (`a[i]`) can be assigned or counted up and down"
                    .to_string(),
                "cannot be assigned",
                None,
            ),
        ));
    }
}

/// What a prefix operator does.
#[derive(Clone, Copy)]
enum Prefix {
    Unary(UnaryOp),
    Update(UpdateOp),
    Unsupported(Construct),
}

/// Prefix operators, folded right to left without recursion.
fn unary<'t, 's: 't, I: TokenInput<'t, 's>>(file: FileId, operand: Boxed<'t, 's, I, Expr>) -> Boxed<'t, 's, I, Expr> {
    let awaiting = word("await")
        .to(Construct::Async)
        .or(word("yield").to(Construct::Generator))
        .then_ignore(any().filter(|t: &Token<'s>| !t.newline_before && t.starts_expression()).rewind());
    let op = choice((
        punct(Punct::Bang).to(Prefix::Unary(UnaryOp::Not)),
        punct(Punct::Tilde).to(Prefix::Unary(UnaryOp::BitNot)),
        punct(Punct::Minus).to(Prefix::Unary(UnaryOp::Neg)),
        punct(Punct::Plus).to(Prefix::Unary(UnaryOp::Plus)),
        kw(Keyword::Typeof).to(Prefix::Unary(UnaryOp::Typeof)),
        punct(Punct::PlusPlus).to(Prefix::Update(UpdateOp::Increment)),
        punct(Punct::MinusMinus).to(Prefix::Update(UpdateOp::Decrement)),
        kw(Keyword::Delete).to(Prefix::Unsupported(Construct::Delete)),
        kw(Keyword::Void).to(Prefix::Unsupported(Construct::Void)),
        awaiting.map(Prefix::Unsupported),
    ))
    .map_with(|op, e| (op, e.span()));
    op.repeated()
        .foldr_with(operand, move |(op, at), operand: Expr, e| {
            let whole = span(file, at).to(operand.span);
            let node = match op {
                Prefix::Unary(op) => Expr::new(ExprKind::Unary { op, operand: Box::new(operand) }, whole),
                Prefix::Update(op) => {
                    if !operand.is_assignable() {
                        e.emit(SyntaxError::custom(
                            SimpleSpan::from(operand.span.start..operand.span.end),
                            Problem::Custom(
                                d::INVALID_ASSIGNMENT,
                                "only a variable, a property (`a.b`) or an element (`a[i]`) can be counted up and down"
                                    .to_string(),
                                "cannot be assigned",
                                None,
                            ),
                        ));
                    }
                    Expr::new(ExprKind::Update { op, prefix: true, target: Box::new(operand) }, whole)
                }
                Prefix::Unsupported(construct) => {
                    e.emit(unsupported(construct, at));
                    Expr::error(whole)
                }
            };
            cap_expr(node, e.state(), at)
        })
        .labelled("an expression")
        .boxed()
}
