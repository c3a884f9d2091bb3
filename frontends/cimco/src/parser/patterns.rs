//! Destructuring (Fusion): binding patterns in `var`, parameters and arrow
//! parameters, assignment patterns (`[a.x, b] = list`), default values,
//! and what they mean written out in ES5.
//!
//! The parser reads the patterns whatever the dialect; read as CNC-Calc's
//! JavaScript each is reported by name where it stands, as before. Read
//! as Fusion's, a pattern is written out at once as the plain statements
//! and expressions it stands for, so nothing after the parser sees one:
//!
//! - `var [a, {b = 1}] = e` is `var __postc_d<o> = e, a = __postc_d<o>[0],
//!   __postc_d<p> = __postc_d<o>[1], b = __postc_d<p>.b === undefined ? 1 :
//!   __postc_d<p>.b` (one temporary per array or object pattern, named by
//!   the pattern's offset in the file);
//! - `[x.a, y] = e` as an expression is `(__postc_d<o> = e, x.a =
//!   __postc_d<o>[0], y = __postc_d<o>[1], __postc_d<o>)`, its temporaries
//!   declared by a `var` the function around it (or the program) starts
//!   with;
//! - a parameter `{a = false} = {}` is a parameter `__postc_p<o>` and a
//!   `var` at the start of the body binding the pattern to
//!   `__postc_p<o> === undefined ? {} : __postc_p<o>`; a parameter `a = 1`
//!   is `a = a === undefined ? 1 : a;` there.
//!
//! An array pattern reads elements by index, as destructuring an array
//! does (ECMAScript reads any iterable; a post destructures arrays). A
//! default applies when the value read is `undefined`.

use chumsky::prelude::*;
use postc_ir::{FileId, Span};

use super::literals::property_key;
use super::{Extra, ParseState, TokenInput, closed, guarded, name, punct, span, unsupported};
use crate::ast::{BinaryOp, Expr, ExprKind, Ident, KeyForm, PropertyKey, Stmt, StmtKind, VarDeclarator};
use crate::diagnostics::Construct;
use crate::token::Punct;

type Boxed<'t, 's, I, O> = chumsky::Boxed<'t, 't, I, O, Extra<'t, 's>>;

/// What a value is bound to.
#[derive(Clone, Debug)]
pub(crate) enum Pattern {
    /// A name being declared.
    Name(Ident),
    /// An assignment's target: a name, `a.b` or `a[i]`.
    Target(Expr),
    /// `[a, , b]`: each slot's element, or a hole.
    Array { items: Vec<Option<Element>>, span: Span },
    /// `{a, b: c}`: each property's key and element.
    Object { props: Vec<(PropertyKey, Element)>, span: Span },
}

/// A pattern and its default value.
#[derive(Clone, Debug)]
pub(crate) struct Element {
    pub pattern: Pattern,
    pub default: Option<Expr>,
    /// The pattern and its default.
    pub span: Span,
}

impl Pattern {
    /// The name, when the pattern is a plain name.
    pub fn as_name(&self) -> Option<&Ident> {
        match self {
            Pattern::Name(n) => Some(n),
            _ => None,
        }
    }

    pub fn span(&self) -> Span {
        match self {
            Pattern::Name(n) => n.span,
            Pattern::Target(e) => e.span,
            Pattern::Array { span, .. } | Pattern::Object { span, .. } => *span,
        }
    }
}

/// A binding element: a name, `[...]` or `{...}`, and `= default`.
pub(super) fn element<'t, 's: 't, I: TokenInput<'t, 's>>(
    file: FileId,
    assign: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Element> {
    recursive(move |element| {
        let element = guarded(element).boxed();
        let rest =
            punct(Punct::Ellipsis).map_with(|_, e| e.span()).then(element.clone()).validate(|(at, el), _, emitter| {
                emitter.emit(unsupported(Construct::Spread, at));
                el
            });
        let slot = choice((rest.boxed(), element.clone())).or_not().map_with(|el, e| (el, e.span()));
        let array = slot
            .separated_by(punct(Punct::Comma))
            .collect::<Vec<_>>()
            .delimited_by(punct(Punct::LBracket), punct(Punct::RBracket))
            .map_with(move |mut items: Vec<(Option<Element>, SimpleSpan)>, e| {
                if items.last().is_some_and(|(el, _)| el.is_none()) {
                    items.pop();
                }
                Pattern::Array { items: items.into_iter().map(|(el, _)| el).collect(), span: span(file, e.span()) }
            });
        let keyed = property_key(file).then_ignore(punct(Punct::Colon)).then(element.clone());
        let shorthand = name(file).then(punct(Punct::Assign).ignore_then(assign.clone()).or_not()).map_with(
            move |(n, default), e| {
                let key = PropertyKey { name: n.name.clone(), written: KeyForm::Ident, span: n.span };
                (key, Element { pattern: Pattern::Name(n), default, span: span(file, e.span()) })
            },
        );
        let object = choice((keyed.boxed(), shorthand.boxed()))
            .separated_by(punct(Punct::Comma))
            .allow_trailing()
            .collect::<Vec<_>>()
            .delimited_by(punct(Punct::LBrace), punct(Punct::RBrace))
            .map_with(move |props, e| Pattern::Object { props, span: span(file, e.span()) });
        let pattern = choice((
            name(file).map(Pattern::Name).boxed(),
            closed(Punct::LBracket).ignore_then(array).boxed(),
            closed(Punct::LBrace).ignore_then(object).boxed(),
        ));
        pattern
            .then(punct(Punct::Assign).ignore_then(assign.clone()).or_not())
            .map_with(move |(pattern, default), e| Element { pattern, default, span: span(file, e.span()) })
    })
    .boxed()
}

/// An assignment's left side read as a pattern (`[a.x, b = 1] = ...`):
/// the array or object literal the parser read, element by element; the
/// span of a part that cannot be assigned when one cannot.
pub(super) fn from_expr(e: &Expr) -> Result<Pattern, Span> {
    match &e.kind {
        ExprKind::Array(items) => {
            let items = items.iter().map(|i| element_from_expr(i).map(Some)).collect::<Result<Vec<_>, _>>()?;
            Ok(Pattern::Array { items, span: e.span })
        }
        ExprKind::Object(props) => {
            let props = props
                .iter()
                .map(|p| Ok((p.key.clone(), element_from_expr(&p.value)?)))
                .collect::<Result<Vec<_>, Span>>()?;
            Ok(Pattern::Object { props, span: e.span })
        }
        ExprKind::Ident(_) | ExprKind::Member { .. } | ExprKind::Index { .. } => Ok(Pattern::Target(e.clone())),
        _ => Err(e.span),
    }
}

fn element_from_expr(e: &Expr) -> Result<Element, Span> {
    match &e.kind {
        ExprKind::Assign { op: crate::ast::AssignOp::Assign, target, value } => {
            Ok(Element { pattern: from_expr(target)?, default: Some((**value).clone()), span: e.span })
        }
        _ => Ok(Element { pattern: from_expr(e)?, default: None, span: e.span }),
    }
}

/// One binding a pattern stands for: `target = value`, and whether the
/// target is a temporary of the pattern's.
struct Binding {
    target: Expr,
    value: Expr,
    temp: bool,
}

fn ident(name: String, at: Span) -> Expr {
    Expr::new(ExprKind::Ident(name), at)
}

/// The temporary of the array or object pattern at `at`.
fn temp_name(at: Span) -> String {
    format!("__postc_d{}", at.start)
}

/// `value === undefined ? default : value`, or `value`.
fn defaulted(value: Expr, default: Option<&Expr>) -> Expr {
    let Some(default) = default else { return value };
    let at = value.span;
    let undefined = Expr::new(ExprKind::Undefined, at);
    let test = ExprKind::Binary { op: BinaryOp::StrictEq, left: Box::new(value.clone()), right: Box::new(undefined) };
    let kind = ExprKind::Conditional {
        test: Box::new(Expr::new(test, at)),
        consequent: Box::new(default.clone()),
        alternate: Box::new(value),
    };
    Expr::new(kind, default.span)
}

/// The bindings of `pattern = source`, in the order JavaScript makes them.
fn bind(pattern: &Pattern, source: Expr, out: &mut Vec<Binding>) {
    match pattern {
        Pattern::Name(n) => out.push(Binding { target: ident(n.name.clone(), n.span), value: source, temp: false }),
        Pattern::Target(e) => out.push(Binding { target: e.clone(), value: source, temp: false }),
        Pattern::Array { items, span } => {
            let temp = temp_name(*span);
            out.push(Binding { target: ident(temp.clone(), *span), value: source, temp: true });
            for (k, item) in items.iter().enumerate() {
                let Some(el) = item else { continue };
                let index = Expr::new(ExprKind::Number(k as f64), el.span);
                let kind = ExprKind::Index { object: Box::new(ident(temp.clone(), *span)), index: Box::new(index) };
                bind_element(el, Expr::new(kind, el.span), out);
            }
        }
        Pattern::Object { props, span } => {
            let temp = temp_name(*span);
            out.push(Binding { target: ident(temp.clone(), *span), value: source, temp: true });
            for (key, el) in props {
                let object = Box::new(ident(temp.clone(), *span));
                let kind = match key.written {
                    KeyForm::Ident => {
                        ExprKind::Member { object, property: Ident { name: key.name.clone(), span: key.span } }
                    }
                    KeyForm::String | KeyForm::Number => ExprKind::Index {
                        object,
                        index: Box::new(Expr::new(ExprKind::String(key.name.clone()), key.span)),
                    },
                };
                bind_element(el, Expr::new(kind, key.span), out);
            }
        }
    }
}

fn bind_element(el: &Element, value: Expr, out: &mut Vec<Binding>) {
    bind(&el.pattern, defaulted(value, el.default.as_ref()), out);
}

/// `var pattern = init` as declarators.
pub(super) fn declarators(pattern: &Pattern, init: Expr, at: Span) -> Vec<VarDeclarator> {
    let mut out = Vec::new();
    bind(pattern, init, &mut out);
    // A declared pattern binds names only (`Pattern::Target` is made by
    // `from_expr` alone, for assignments).
    out.into_iter()
        .filter_map(|b| {
            let ExprKind::Ident(name) = b.target.kind else { return None };
            Some(VarDeclarator { name: Ident { name, span: b.target.span }, init: Some(b.value), span: at })
        })
        .collect()
}

/// `pattern = value` as an expression: the bindings in order, then the
/// value. The temporaries are left in `state` for the function around
/// to declare.
pub(super) fn assignment(pattern: &Pattern, value: Expr, at: Span, state: &mut ParseState) -> Expr {
    let mut out = Vec::new();
    bind(pattern, value, &mut out);
    let mut items = Vec::with_capacity(out.len() + 1);
    let mut result = None;
    for b in out {
        if let (true, ExprKind::Ident(name)) = (b.temp, &b.target.kind) {
            state.temps.push((b.target.span.start, name.clone()));
            result.get_or_insert_with(|| b.target.clone());
        }
        let kind =
            ExprKind::Assign { op: crate::ast::AssignOp::Assign, target: Box::new(b.target), value: Box::new(b.value) };
        items.push(Expr::new(kind, at));
    }
    items.extend(result);
    Expr::new(ExprKind::Sequence(items), at)
}

/// Parameters written as elements: the names the function takes, and the
/// statements its body starts with (defaults, patterns).
pub(super) fn parameters(elements: Vec<Element>) -> (Vec<Ident>, Vec<Stmt>) {
    let mut names = Vec::with_capacity(elements.len());
    let mut prologue = Vec::new();
    for el in elements {
        match (&el.pattern, &el.default) {
            (Pattern::Name(n), None) => names.push(n.clone()),
            (Pattern::Name(n), Some(default)) => {
                // `a = a === undefined ? default : a;`
                let value = defaulted(ident(n.name.clone(), n.span), Some(default));
                let kind = ExprKind::Assign {
                    op: crate::ast::AssignOp::Assign,
                    target: Box::new(ident(n.name.clone(), n.span)),
                    value: Box::new(value),
                };
                prologue.push(Stmt::new(StmtKind::Expr(Expr::new(kind, el.span)), el.span));
                names.push(n.clone());
            }
            (pattern, default) => {
                let at = pattern.span();
                let param = Ident { name: format!("__postc_p{}", at.start), span: at };
                let source = defaulted(ident(param.name.clone(), at), default.as_ref());
                let decls = declarators(pattern, source, el.span);
                prologue.push(Stmt::new(StmtKind::Var(decls), el.span));
                names.push(param);
            }
        }
    }
    (names, prologue)
}

/// The temporaries of assignment patterns inside `within` that no
/// function inside it declared, as a `var` statement to start a body with.
pub(super) fn declare_temps(state: &mut ParseState, within: SimpleSpan, file: FileId) -> Option<Stmt> {
    let mut names: Vec<(usize, String)> = Vec::new();
    state.temps.retain(|(at, name)| {
        let inside = (within.start..within.end).contains(at);
        if inside && !names.iter().any(|(_, n)| n == name) {
            names.push((*at, name.clone()));
        }
        !inside
    });
    if names.is_empty() {
        return None;
    }
    let decls = names
        .into_iter()
        .map(|(at, name)| {
            let s = Span::new(file, at, at);
            VarDeclarator { name: Ident { name, span: s }, init: None, span: s }
        })
        .collect();
    Some(Stmt::new(StmtKind::Var(decls), span(file, SimpleSpan::from(within.start..within.start))))
}
