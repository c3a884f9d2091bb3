//! Literals with structure: function expressions (and the parts a
//! declaration shares), array and object literals, call arguments.
//! Newer forms (`...`, default parameters, shorthand properties, methods,
//! getters, computed keys, trailing commas, array holes) are parsed far
//! enough to be named in a diagnostic.

use chumsky::prelude::*;
use postc_ir::FileId;

use super::patterns::{self, Element, Pattern, element};
use super::{Extra, ParseState, TokenInput, balanced, kw, name, punct, span, unsupported, word};
use crate::ast::{Expr, ExprKind, Function, Ident, KeyForm, Property, PropertyKey, Stmt};
use crate::diagnostics::Construct;
use crate::print::js_number;
use crate::strings;
use crate::token::{Keyword, Punct, Token, TokenKind};

use super::stmt::braced;

type Boxed<'t, 's, I, O> = chumsky::Boxed<'t, 't, I, O, Extra<'t, 's>>;

/// `function name?(params) { body }`; also used for declarations.
pub(super) fn function_parts<'t, 's: 't, I, S>(
    file: FileId,
    stmt: S,
    assign: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Function>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    let params = parameter_list(file, assign);
    kw(Keyword::Function)
        .ignore_then(punct(Punct::Star).map_with(|_, e| e.span()).or_not())
        .then(name(file).or_not())
        .then(params)
        .then(braced(stmt))
        .validate(move |(((star, name), params), (body, body_span)), e, emitter| {
            if let Some(at) = star {
                emitter.emit(unsupported(Construct::Generator, at));
            }
            let whole = e.span();
            let (params, body) = function_body(file, params, body, whole, e.state(), emitter);
            Function { name, params, body, body_span: span(file, body_span), span: span(file, whole), arrow: false }
        })
        .boxed()
}

/// `(a, b = 1, {c})`: parameters as elements; a rest parameter, and what
/// the element grammar does not read, reported.
pub(super) fn parameter_list<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
    assign: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Vec<Element>> {
    let rest =
        punct(Punct::Ellipsis).map_with(|_, e| e.span()).then(name(file)).validate(move |(at, n), e, emitter| {
            emitter.emit(unsupported(Construct::Spread, at));
            Element { pattern: Pattern::Name(n), default: None, span: span(file, e.span()) }
        });
    // What the element grammar does not read, reported as destructuring.
    let destructured = balanced(Punct::LBrace).or(balanced(Punct::LBracket)).validate(move |at, _, emitter| {
        emitter.emit(unsupported(Construct::Destructuring, at));
        let name = Ident { name: String::new(), span: span(file, at) };
        Element { pattern: Pattern::Name(name), default: None, span: span(file, at) }
    });
    choice((rest.boxed(), element(file, assign), destructured.boxed()))
        .labelled("a parameter name")
        .separated_by(punct(Punct::Comma))
        .collect::<Vec<_>>()
        .then(trailing_comma())
        .map(|(params, _)| params)
        .delimited_by(punct(Punct::LParen), punct(Punct::RParen))
        .boxed()
}

/// A function's parameter names and body. Read as Fusion's JavaScript,
/// parameters with defaults or patterns become plain names and statements
/// the body starts with, and the temporaries of assignment patterns in the
/// body are declared ([`super::patterns`]); read as CNC-Calc's, they are
/// reported.
pub(super) fn function_body<'t, 's>(
    file: FileId,
    params: Vec<Element>,
    body: Vec<Stmt>,
    whole: SimpleSpan,
    state: &mut ParseState,
    emitter: &mut chumsky::input::Emitter<super::Error<'t, 's>>,
) -> (Vec<Ident>, Vec<Stmt>) {
    if !state.fusion() {
        let names = params
            .into_iter()
            .map(|el| {
                if let Some(n) = el.pattern.as_name() {
                    if el.default.is_some() {
                        emitter.emit(unsupported(Construct::DefaultParam, to_simple(el.span)));
                    }
                    return n.clone();
                }
                let at = el.pattern.span();
                emitter.emit(unsupported(Construct::Destructuring, to_simple(at)));
                if el.default.is_some() {
                    emitter.emit(unsupported(Construct::DefaultParam, to_simple(el.span)));
                }
                Ident { name: String::new(), span: at }
            })
            .collect();
        return (names, body);
    }
    let (names, prologue) = patterns::parameters(params);
    let mut stmts: Vec<Stmt> = patterns::declare_temps(state, whole, file).into_iter().collect();
    stmts.extend(prologue);
    stmts.extend(body);
    (names, stmts)
}

fn to_simple(s: postc_ir::Span) -> SimpleSpan {
    SimpleSpan::from(s.start..s.end)
}

/// An optional comma before a closing bracket, reported when present.
fn trailing_comma<'t, 's: 't, I: TokenInput<'t, 's>>() -> impl Parser<'t, I, (), Extra<'t, 's>> + Clone {
    // Fusion's JavaScript allows it.
    punct(Punct::Comma).map_with(|_, e| e.span()).or_not().validate(|at, e, emitter| {
        if let Some(at) = at
            && !e.state().fusion()
        {
            emitter.emit(unsupported(Construct::TrailingComma, at));
        }
    })
}

/// `...x` where only `x` is allowed: reported, and `x` kept.
fn spread_or<'t, 's: 't, I: TokenInput<'t, 's>>(assign: Boxed<'t, 's, I, Expr>) -> Boxed<'t, 's, I, Expr> {
    punct(Punct::Ellipsis)
        .map_with(|_, e| e.span())
        .or_not()
        .then(assign)
        .validate(|(spread, value), _, emitter| {
            if let Some(at) = spread {
                emitter.emit(unsupported(Construct::Spread, at));
            }
            value
        })
        .boxed()
}

/// `[a, b, c]`. Each element is parsed once (no backtracking over
/// nested arrays); empty slots are reported, a trailing comma is not.
pub(super) fn array<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
    assign: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Expr> {
    spread_or(assign)
        .or_not()
        .map_with(|item, e| (item, e.span()))
        .separated_by(punct(Punct::Comma))
        .collect::<Vec<_>>()
        .delimited_by(punct(Punct::LBracket), punct(Punct::RBracket))
        .validate(move |mut slots, e, emitter| {
            if slots.last().is_some_and(|(item, _)| item.is_none()) {
                slots.pop();
            }
            let mut items = Vec::with_capacity(slots.len());
            for (item, at) in slots {
                match item {
                    Some(item) => items.push(item),
                    None => emitter.emit(unsupported(Construct::ArrayHole, at)),
                }
            }
            Expr::new(ExprKind::Array(items), span(file, e.span()))
        })
        .recover_with(via_parser(balanced(Punct::LBracket).map(move |at| Expr::error(span(file, at)))))
        .boxed()
}

/// A property name: a name, a keyword, a string or a number.
pub(super) fn property_key<'t, 's: 't, I: TokenInput<'t, 's>>(file: FileId) -> Boxed<'t, 's, I, PropertyKey> {
    select! {
        Token { kind: TokenKind::Ident(n), .. } => (n.to_string(), KeyForm::Ident),
        Token { kind: TokenKind::Keyword(k), .. } => (k.as_str().to_string(), KeyForm::Ident),
        Token { kind: TokenKind::String(s), .. } => (strings::decode(s).0, KeyForm::String),
        Token { kind: TokenKind::Number(n), .. } => (js_number(n), KeyForm::Number),
    }
    .map_with(move |(name, written), e| PropertyKey { name, written, span: span(file, e.span()) })
    .labelled("a property name")
    .boxed()
}

/// `{ key: value, ... }`, with the newer property forms reported.
pub(super) fn object<'t, 's: 't, I, S>(file: FileId, assign: Boxed<'t, 's, I, Expr>, stmt: S) -> Boxed<'t, 's, I, Expr>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    let key = property_key(file);
    let method_tail = balanced(Punct::LParen).then(braced(stmt)).map_with(|_, e| e.span());
    let error_value = move |key: PropertyKey, construct: Construct, at, emitter: &mut chumsky::input::Emitter<_>| {
        emitter.emit(unsupported(construct, at));
        let value = Expr::error(key.span);
        Property { span: key.span, key, value }
    };
    let accessor = word("get")
        .or(word("set"))
        .ignore_then(key.clone())
        .then(method_tail.clone())
        .validate(move |(key, _), e, emitter| error_value(key, Construct::GetterSetter, e.span(), emitter));
    let computed = balanced(Punct::LBracket).then_ignore(punct(Punct::Colon)).then(assign.clone()).validate(
        move |(at, value), _, emitter| {
            emitter.emit(unsupported(Construct::ComputedKey, at));
            let key = PropertyKey { name: String::new(), written: KeyForm::String, span: span(file, at) };
            Property { span: key.span.to(value.span), key, value }
        },
    );
    let spread = punct(Punct::Ellipsis).map_with(|_, e| e.span()).then(assign.clone()).validate(
        move |(at, value), _, emitter| {
            emitter.emit(unsupported(Construct::Spread, at));
            let key = PropertyKey { name: String::new(), written: KeyForm::String, span: span(file, at) };
            Property { span: key.span.to(value.span), key, value }
        },
    );
    // After a key: `: value`, or (reported) a method or a shorthand.
    #[derive(Clone)]
    enum Tail {
        Value(Expr),
        Method,
        Shorthand,
    }
    let tail = choice((
        punct(Punct::Colon).ignore_then(assign).map(Tail::Value),
        method_tail.to(Tail::Method),
        punct(Punct::Comma).or(punct(Punct::RBrace)).rewind().to(Tail::Shorthand),
    ))
    .labelled("`:`");
    let keyed = key.then(tail).validate(move |(key, tail), e, emitter| match tail {
        Tail::Value(value) => Property { span: key.span.to(value.span), key, value },
        Tail::Method => error_value(key, Construct::Method, e.span(), emitter),
        // `{ x }` is `{ x: x }` in Fusion's JavaScript.
        Tail::Shorthand
            if e.state().fusion() && key.written == KeyForm::Ident && Keyword::from_word(&key.name).is_none() =>
        {
            let value = Expr::new(ExprKind::Ident(key.name.clone()), key.span);
            Property { span: key.span, key, value }
        }
        Tail::Shorthand => error_value(key, Construct::Shorthand, e.span(), emitter),
    });
    choice((accessor.boxed(), computed.boxed(), spread.boxed(), keyed.boxed()))
        .separated_by(punct(Punct::Comma))
        .allow_trailing()
        .collect::<Vec<_>>()
        .delimited_by(punct(Punct::LBrace), punct(Punct::RBrace))
        .map_with(move |props, e| Expr::new(ExprKind::Object(props), span(file, e.span())))
        .recover_with(via_parser(balanced(Punct::LBrace).map(move |at| Expr::error(span(file, at)))))
        .boxed()
}

/// `(a, b)` call arguments; a group that does not parse becomes one error
/// argument.
pub(super) fn arguments<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
    assign: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Vec<Expr>> {
    spread_or(assign)
        .separated_by(punct(Punct::Comma))
        .collect::<Vec<_>>()
        .then_ignore(trailing_comma())
        .delimited_by(punct(Punct::LParen), punct(Punct::RParen))
        .recover_with(via_parser(balanced(Punct::LParen).map(move |at| vec![Expr::error(span(file, at))])))
        .boxed()
}
