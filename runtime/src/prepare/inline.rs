//! Inlining of expression functions: a native function that only computes
//! a value (`function getFeedrateValue() { var f = getFeedrate(1); return
//! parseFloat(f.substring(1)); }`, `getFeedrate` itself) becomes that
//! expression at each call in a handler whose arguments are cheap and free
//! of effects, so that the hot path pays no call (a frame, the call's
//! bookkeeping). The functions themselves keep their calls, which are what
//! the post says (lints count them).
//!
//! A function qualifies when its body is `if (c) return a;`... then
//! `return e;` (a chain of choices), optionally after one `var v = x;`
//! whose `v` the rest reads exactly once and not under a choice (so `x` is
//! evaluated exactly when and as often as before), and when it reads no
//! other local than its parameters.

use crate::exec::{Body, Expr, Function, Piece, Stmt};
use postc_ir::{BinaryOp, LocalId, Place};

/// Inlines expression functions into a body (a handler's, after the fast
/// path has inlined the functions it writes).
pub fn expression_functions(functions: &[Function], body: &mut [Stmt]) {
    let templates: Vec<Option<(usize, Expr, Expr)>> = functions.iter().map(template).collect();
    if templates.iter().all(Option::is_none) {
        return;
    }
    // A template may call another: three rounds reach three levels.
    for _ in 0..3 {
        body.iter_mut().for_each(|s| stmt(s, &templates, None));
    }
}

/// Whether calls of the function become its expression here.
pub(super) fn is_expression_function(f: &Function) -> bool {
    template(f).is_some()
}

/// The expression a function is, over its parameters, and their number.
fn template(f: &Function) -> Option<(usize, Expr, Expr)> {
    let Body::Native(body) = &f.body else { return None };
    let params = f.params;
    let (local, rest) = match body.first() {
        Some(Stmt::Assign(Place::Local(k), e)) if k.index() >= params && !reads(e, *k) => (Some((*k, e)), &body[1..]),
        _ => (None, &body[..]),
    };
    let mut chain = None;
    for s in rest.iter().rev() {
        chain = Some(match (s, chain) {
            (Stmt::Return(Some(e)), None) => e.clone(),
            (Stmt::If { branches, otherwise }, Some(next)) if branches.len() == 1 && otherwise.is_empty() => {
                let (c, b) = &branches[0];
                let [Stmt::Return(Some(e))] = b.as_slice() else { return None };
                Expr::Choose(Box::new(c.clone()), Box::new(e.clone()), Box::new(next))
            }
            _ => return None,
        });
    }
    let mut e = chain?;
    if let Some((k, x)) = local {
        if count_reads(&e, k) != 1 || !unconditional(&e, k) {
            return None;
        }
        substitute(&mut e, &|j| (j == k).then(|| x.clone()));
    }
    if max_local(&e).is_some_and(|m| m >= params) {
        return None;
    }
    Some((params, e, f.fill()))
}

fn stmt(s: &mut Stmt, templates: &[Option<(usize, Expr, Expr)>], at: Option<usize>) {
    match s {
        Stmt::Line { pieces, .. } | Stmt::Emit(pieces) => pieces.iter_mut().for_each(|p| {
            if let Piece::Expr(e) | Piece::Joined(e) = p {
                expr(e, templates, at)
            }
        }),
        Stmt::Write(e) | Stmt::Assign(_, e) | Stmt::Eval(e) | Stmt::Return(Some(e)) => expr(e, templates, at),
        Stmt::If { branches, otherwise } => {
            for (c, b) in branches {
                expr(c, templates, at);
                b.iter_mut().for_each(|s| stmt(s, templates, at));
            }
            otherwise.iter_mut().for_each(|s| stmt(s, templates, at));
        }
        Stmt::While { cond, body, .. } => {
            expr(cond, templates, at);
            body.iter_mut().for_each(|s| stmt(s, templates, at));
        }
        _ => {}
    }
}

fn expr(e: &mut Expr, templates: &[Option<(usize, Expr, Expr)>], at: Option<usize>) {
    match e {
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => {
            expr(value, templates, at)
        }
        Expr::Binary(_, a, b) => {
            expr(a, templates, at);
            expr(b, templates, at);
        }
        Expr::Choose(c, a, b) => {
            expr(c, templates, at);
            expr(a, templates, at);
            expr(b, templates, at);
        }
        Expr::Builtin(_, args) => args.iter_mut().for_each(|a| expr(a, templates, at)),
        Expr::Call(f, args) => {
            args.iter_mut().for_each(|a| expr(a, templates, at));
            let i = f.index();
            if Some(i) == at {
                return;
            }
            let Some(Some((params, t, fill))) = templates.get(i) else { return };
            if args.len() > *params || !args.iter().all(cheap) {
                return;
            }
            let mut body = t.clone();
            let args = args.clone();
            substitute(&mut body, &|k: LocalId| Some(args.get(k.index()).cloned().unwrap_or_else(|| fill.clone())));
            *e = super::fold::expr(body);
        }
        _ => {}
    }
}

/// Cheap and free of effects: may be read any number of times.
fn cheap(e: &Expr) -> bool {
    matches!(
        e,
        Expr::Number(_)
            | Expr::Text(_)
            | Expr::Bool(_)
            | Expr::Null
            | Expr::Undefined
            | Expr::Local(_)
            | Expr::Global(_)
            | Expr::Quantity(_)
    )
}

fn substitute(e: &mut Expr, by: &dyn Fn(LocalId) -> Option<Expr>) {
    match e {
        Expr::Local(k) => {
            if let Some(v) = by(*k) {
                *e = v;
            }
        }
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => substitute(value, by),
        Expr::Binary(_, a, b) => {
            substitute(a, by);
            substitute(b, by);
        }
        Expr::Choose(c, a, b) => {
            substitute(c, by);
            substitute(a, by);
            substitute(b, by);
        }
        Expr::Call(_, args) | Expr::Builtin(_, args) => args.iter_mut().for_each(|a| substitute(a, by)),
        _ => {}
    }
}

fn reads(e: &Expr, k: LocalId) -> bool {
    count_reads(e, k) > 0
}

fn count_reads(e: &Expr, k: LocalId) -> usize {
    match e {
        Expr::Local(x) | Expr::Written(x) => usize::from(*x == k),
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => count_reads(value, k),
        Expr::Binary(_, a, b) => count_reads(a, k) + count_reads(b, k),
        Expr::Choose(c, a, b) => count_reads(c, k) + count_reads(a, k) + count_reads(b, k),
        Expr::Call(_, args) | Expr::Builtin(_, args) => args.iter().map(|a| count_reads(a, k)).sum(),
        _ => 0,
    }
}

/// `k` is read where evaluation always reaches (not in an arm of a
/// choice, nor right of `&&`/`||`), and everything evaluated before it is
/// free of effects.
fn unconditional(e: &Expr, k: LocalId) -> bool {
    match e {
        Expr::Local(x) => *x == k,
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => unconditional(value, k),
        Expr::Binary(BinaryOp::And | BinaryOp::Or, a, _) => unconditional(a, k),
        Expr::Binary(_, a, b) => unconditional(a, k) || (pure(a) && unconditional(b, k)),
        Expr::Choose(c, ..) => unconditional(c, k),
        Expr::Builtin(_, args) => {
            let Some(i) = args.iter().position(|a| reads(a, k)) else { return false };
            args[..i].iter().all(pure) && unconditional(&args[i], k)
        }
        _ => false,
    }
}

/// Free of effects (no call, no formatting through a variable).
fn pure(e: &Expr) -> bool {
    match e {
        Expr::Call(..) | Expr::FormatVar { .. } => false,
        Expr::Format { value, .. } | Expr::Unary(_, value) => pure(value),
        Expr::Binary(_, a, b) => pure(a) && pure(b),
        Expr::Choose(c, a, b) => pure(c) && pure(a) && pure(b),
        Expr::Builtin(_, args) => args.iter().all(pure),
        _ => true,
    }
}

fn max_local(e: &Expr) -> Option<usize> {
    match e {
        Expr::Local(k) | Expr::Written(k) => Some(k.index()),
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => max_local(value),
        Expr::Binary(_, a, b) => max_local(a).max(max_local(b)),
        Expr::Choose(c, a, b) => max_local(c).max(max_local(a)).max(max_local(b)),
        Expr::Call(_, args) | Expr::Builtin(_, args) => args.iter().filter_map(max_local).max(),
        _ => None,
    }
}
