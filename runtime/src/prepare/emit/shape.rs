//! The shapes the fast path recognises: which parameter or local can be
//! kept as text in the output (a "region"), which functions always return
//! text, and the small analyses over IR statements they need.

use crate::exec::{Expr, Piece, Stmt};
use postc_ir::{BinaryOp, Builtin, LocalId, Place, UnaryOp};

/// The parts of a left-associated chain of `+`.
pub(super) fn concat_leaves<'e>(e: &'e Expr, out: &mut Vec<&'e Expr>) {
    match e {
        Expr::Binary(BinaryOp::Add, a, b) => {
            concat_leaves(a, out);
            out.push(b);
        }
        other => out.push(other),
    }
}

/// The one parameter that can be bound as a region: a text argument
/// (`returns_text`: the functions that surely return text), used only
/// where a region can be (see the module documentation).
pub(super) fn region_param(body: &[Stmt], params: usize, args: &[Expr], returns_text: &[bool]) -> Option<usize> {
    (0..params).find(|&k| {
        args.get(k).is_some_and(|a| is_text(a, returns_text) || matches!(a, Expr::Call(..)))
            && region_uses_ok(body, LocalId::new(k as u16))
            && reads(body, LocalId::new(k as u16))
    })
}

pub(super) fn region_uses_ok(body: &[Stmt], k: LocalId) -> bool {
    body.iter().all(|s| match s {
        Stmt::Return(Some(e)) => ret_ok(e, k),
        // `text = text == "" ? word : text + " " + word`
        Stmt::Assign(Place::Local(x), Expr::Choose(c, a, b)) if *x == k => {
            cond_ok(c, k) && leaf_only(a, k) && leaf_only(b, k)
        }
        Stmt::Assign(Place::Local(x), e) if *x == k => leaf_only(e, k),
        Stmt::Assign(_, e) | Stmt::Eval(e) => !expr_reads(e, k),
        Stmt::If { branches, otherwise } => {
            branches.iter().all(|(c, b)| cond_ok(c, k) && region_uses_ok(b, k)) && region_uses_ok(otherwise, k)
        }
        Stmt::Return(None) | Stmt::Origin(_) => true,
        _ => false,
    })
}

/// A returned value that may use region `k`: a concatenation with it as a
/// part, or a choice between such values.
pub(super) fn ret_ok(e: &Expr, k: LocalId) -> bool {
    match e {
        Expr::Choose(c, a, b) => cond_ok(c, k) && ret_ok(a, k) && ret_ok(b, k),
        // Passed on to a function as one of its arguments.
        Expr::Call(_, args) => {
            let with = args.iter().filter(|a| expr_reads(a, k)).count();
            with <= 1 && args.iter().all(|a| leaf_only(a, k))
        }
        other => leaf_only(other, k),
    }
}

/// A local that can be a region: its first mention, at the top of the
/// body, assigns it text (or a call's result), and every use fits.
pub(super) fn region_local(body: &[Stmt], params: usize, slots: usize) -> Option<usize> {
    (params..slots).find(|&k| {
        let k16 = LocalId::new(k as u16);
        let first = body.iter().find(|s| stmt_mentions(s, k16));
        let starts = matches!(first, Some(Stmt::Assign(Place::Local(x), e))
            if *x == k16 && !expr_reads(e, k16) && (is_text(e, &[]) || matches!(e, Expr::Call(..))));
        starts && region_uses_ok(body, k16) && reads(body, k16)
    })
}

pub(super) fn stmt_mentions(s: &Stmt, k: LocalId) -> bool {
    matches!(s, Stmt::Assign(Place::Local(x), _) if *x == k)
        || reads(std::slice::from_ref(s), k)
        || assigns(std::slice::from_ref(s), k)
}

pub(super) fn cond_ok(c: &Expr, k: LocalId) -> bool {
    let is_k = |e: &Expr| matches!(e, Expr::Local(x) if *x == k);
    let empty = |e: &Expr| matches!(e, Expr::Text(t) if t.is_empty());
    match c {
        Expr::Binary(
            BinaryOp::Eq | BinaryOp::JsEq | BinaryOp::StrictEq | BinaryOp::Ne | BinaryOp::JsNe | BinaryOp::StrictNe,
            a,
            b,
        ) if is_k(a) => empty(b),
        Expr::Unary(UnaryOp::Not, a) if is_k(a) => true,
        e if is_k(e) => true,
        other => !expr_reads(other, k),
    }
}

/// `k` appears at most once, and only as a whole part of the concatenation
/// (or as `k.substring(n)`, see [`region_part`]).
pub(super) fn leaf_only(e: &Expr, k: LocalId) -> bool {
    let mut leaves = Vec::new();
    concat_leaves(e, &mut leaves);
    let direct = leaves.iter().filter(|l| region_part(l, k).is_some()).count();
    direct <= 1 && leaves.iter().all(|l| region_part(l, k).is_some() || !expr_reads(l, k))
}

/// A part of a concatenation that is region `k`'s text: the local itself
/// (`Some(0)`), or `k.substring(n)` for a whole number `n` (`Some(n)`: its
/// first `n` characters cut, [`Stmt::Cut`]; a field post's `writeBlock`
/// dropping the blank before its first word).
pub(super) fn region_part(e: &Expr, k: LocalId) -> Option<usize> {
    match e {
        Expr::Local(x) if *x == k => Some(0),
        Expr::Builtin(Builtin::Substring, args) => match args.as_slice() {
            [Expr::Local(x), Expr::Number(n)] if *x == k && *n >= 0.0 && n.fract() == 0.0 && *n < 65536.0 => {
                Some(*n as usize)
            }
            _ => None,
        },
        _ => None,
    }
}

pub(super) fn reads(body: &[Stmt], k: LocalId) -> bool {
    body.iter().any(|s| match s {
        Stmt::Return(Some(e)) | Stmt::Assign(_, e) | Stmt::Eval(e) | Stmt::Write(e) => expr_reads(e, k),
        Stmt::If { branches, otherwise } => {
            branches.iter().any(|(c, b)| expr_reads(c, k) || reads(b, k)) || reads(otherwise, k)
        }
        Stmt::While { cond, body, .. } => expr_reads(cond, k) || reads(body, k),
        _ => false,
    })
}

pub(super) fn expr_reads(e: &Expr, k: LocalId) -> bool {
    match e {
        Expr::Local(x) => *x == k,
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => expr_reads(value, k),
        Expr::Binary(_, a, b) => expr_reads(a, k) || expr_reads(b, k),
        Expr::Choose(c, a, b) => expr_reads(c, k) || expr_reads(a, k) || expr_reads(b, k),
        Expr::Call(_, args) | Expr::Builtin(_, args) => args.iter().any(|a| expr_reads(a, k)),
        _ => false,
    }
}

pub(super) fn assigns(body: &[Stmt], k: LocalId) -> bool {
    body.iter().any(|s| match s {
        Stmt::Assign(Place::Local(x), _) => *x == k,
        Stmt::If { branches, otherwise } => branches.iter().any(|(_, b)| assigns(b, k)) || assigns(otherwise, k),
        Stmt::While { body, .. } => assigns(body, k),
        _ => false,
    })
}

/// Whether statements leave an enclosing loop (not counting loops in them).
pub(super) fn breaks(body: &[Stmt]) -> bool {
    body.iter().any(|s| match s {
        Stmt::Break => true,
        Stmt::If { branches, otherwise } => branches.iter().any(|(_, b)| breaks(b)) || breaks(otherwise),
        _ => false,
    })
}

/// The highest local slot statements use.
pub(crate) fn max_slot(body: &[Stmt]) -> Option<LocalId> {
    let mut m = None;
    for st in body {
        // The statement's walks are the exhaustive ones of `exec`; they
        // take it mutably, so a copy is walked (this runs once a post).
        let mut st = st.clone();
        st.for_each_named_local_mut(|_, k| m = m.max(Some(*k)));
        st.for_each_expr_mut(|x| x.for_each_local_mut(&mut |k: &mut LocalId| m = m.max(Some(*k))));
        st.for_each_body_mut(|b| m = m.max(max_slot(b)));
    }
    m
}

pub(super) fn has_loop(body: &[Stmt]) -> bool {
    body.iter().any(|s| match s {
        Stmt::While { .. } | Stmt::Break | Stmt::Continue => true,
        Stmt::If { branches, otherwise } => branches.iter().any(|(_, b)| has_loop(b)) || has_loop(otherwise),
        _ => false,
    })
}

pub(super) fn count(body: &[Stmt]) -> usize {
    body.iter()
        .map(|s| match s {
            Stmt::If { branches, otherwise } => {
                1 + branches.iter().map(|(_, b)| count(b)).sum::<usize>() + count(otherwise)
            }
            Stmt::While { body, .. } => 1 + count(body),
            _ => 1,
        })
        .sum()
}

/// Cheap and free of effects: safe to evaluate where it is used instead.
pub(super) fn is_pure(e: &Expr) -> bool {
    matches!(e, Expr::Number(_) | Expr::Text(_) | Expr::Bool(_) | Expr::Null | Expr::Undefined | Expr::Quantity(_))
}

/// Whether an expression is surely text.
pub(super) fn is_text(e: &Expr, returns_text: &[bool]) -> bool {
    match e {
        Expr::Text(_) | Expr::FormatVar { .. } | Expr::Format { .. } => true,
        Expr::Binary(BinaryOp::Add, a, b) => is_text(a, returns_text) || is_text(b, returns_text),
        Expr::Choose(_, a, b) => is_text(a, returns_text) && is_text(b, returns_text),
        Expr::Call(f, _) => returns_text.get(f.index()).copied().unwrap_or(false),
        Expr::Builtin(
            Builtin::Str | Builtin::JsString | Builtin::Upper | Builtin::Lower | Builtin::ToFixed | Builtin::Substring,
            _,
        ) => true,
        _ => false,
    }
}

/// Whether every path through a body ends in `return`.
pub(super) fn always_returns(body: &[Stmt]) -> bool {
    body.iter().any(|s| match s {
        Stmt::Return(Some(_)) => true,
        Stmt::If { branches, otherwise } => {
            !otherwise.is_empty() && always_returns(otherwise) && branches.iter().all(|(_, b)| always_returns(b))
        }
        _ => false,
    })
}

pub(super) fn all_returns(body: &[Stmt], ok: &dyn Fn(&Expr) -> bool) -> bool {
    body.iter().all(|s| match s {
        Stmt::Return(Some(e)) => ok(e),
        Stmt::Return(None) => false,
        Stmt::If { branches, otherwise } => {
            branches.iter().all(|(_, b)| all_returns(b, ok)) && all_returns(otherwise, ok)
        }
        Stmt::While { body, .. } => all_returns(body, ok),
        _ => true,
    })
}

/// Joins neighbouring `Emit`s.
pub(super) fn merge(stmts: Vec<Stmt>) -> Vec<Stmt> {
    let mut out: Vec<Stmt> = Vec::with_capacity(stmts.len());
    for s in stmts {
        // Nothing after a `break` runs; a truncation right after its mark
        // drops nothing.
        if matches!(out.last(), Some(Stmt::Break)) {
            break;
        }
        // (An `Origin` between them writes nothing.)
        if let (Some(Stmt::Mark(m)), Stmt::Truncate(t)) = (out.iter().rev().find(|s| !matches!(s, Stmt::Origin(_))), &s)
            && m == t
        {
            continue;
        }
        match (out.last_mut(), s) {
            (Some(Stmt::Emit(prev)), Stmt::Emit(next)) => {
                for p in next {
                    match (prev.last_mut(), p) {
                        (Some(Piece::Text(a)), Piece::Text(b)) => a.extend_from_slice(&b),
                        (_, p) => prev.push(p),
                    }
                }
            }
            (_, Stmt::If { branches, otherwise }) => out.push(Stmt::If {
                branches: branches.into_iter().map(|(c, b)| (c, merge(b))).collect(),
                otherwise: merge(otherwise),
            }),
            (_, Stmt::While { cond, body, span, step }) => {
                out.push(Stmt::While { cond, body: merge(body), span, step: merge(step) })
            }
            (_, s) => out.push(s),
        }
    }
    out
}
