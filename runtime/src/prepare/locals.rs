//! Locals that need no statement of their own.
//!
//! Once the fast path has inlined a handler's functions, its code is full
//! of statements whose only effect is a local: copies (`x = vx` of a
//! parameter, `a1 = x` of a word passed on), constants (`movement = 1` of a
//! known argument, then `switch (movement)`), and values set that nobody
//! reads (`var` locals start as `undefined` and are then assigned on every
//! path). A field post runs a dozen of them a move. Here:
//!
//! 1. a copy `d = s` or a constant `d = 3` is read through: the statements
//!    after it in its list, up to the first that writes `d` or `s`, read
//!    `s` (or the constant) where they read `d`;
//! 2. constants are folded again ([`super::fold`]), so a `switch` on a
//!    known value keeps its one arm;
//! 3. a store that no statement after it reads is dropped when computing
//!    its value has no effect (liveness, backwards over the structured
//!    code; a loop is taken to read, at its head, every local its body
//!    reads).
//!
//! What a post writes cannot change: only statements whose one effect is a
//! value nobody reads go. Like the other passes here, this makes a handler
//! run fewer statements, so it counts fewer steps against the post's step
//! budget.

use std::collections::HashSet;

use postc_ir::{BinaryOp, LocalId, Place};

use super::{emit, fold};
use crate::exec::{Expr, LocalUse, Stmt};

/// Locals whose value a later statement may read.
type Live = HashSet<LocalId>;

/// How many statements and expressions a copy is read through at most, so
/// that the pass stays linear on any post.
const READ_THROUGH_BUDGET: usize = 512;

/// A handler or function body with its copies and constants read through
/// and its dead stores dropped.
#[doc(hidden)]
pub fn tidy(mut body: Vec<Stmt>) -> Vec<Stmt> {
    // Twice: folding a branch away leaves copies to read through.
    for _ in 0..2 {
        read_through(&mut body);
        body = fold::stmts(body);
    }
    let mut body = emit::drop_truncates(body);
    drop_dead(&mut body, Live::new(), None);
    body
}

/// Reads every copy and constant of the statements, at any depth, through.
fn read_through(body: &mut [Stmt]) {
    for i in 0..body.len() {
        let (head, rest) = body.split_at_mut(i + 1);
        if let Stmt::Assign(Place::Local(d), value) = &head[i] {
            let by = match value {
                Expr::Local(s) if s != d => Some(value.clone()),
                Expr::Number(_) | Expr::Text(_) | Expr::Bool(_) | Expr::Null | Expr::Undefined => Some(value.clone()),
                _ => None,
            };
            if let Some(by) = by {
                read_through_after(*d, &by, rest);
            }
        }
        head[i].for_each_body_mut(|b| read_through(b));
    }
}

/// Makes the statements read `by` for `d`, up to the first that writes
/// `d` or the local `by` is.
fn read_through_after(d: LocalId, by: &Expr, rest: &mut [Stmt]) {
    let source = match by {
        Expr::Local(s) => Some(*s),
        _ => None,
    };
    let mut budget = READ_THROUGH_BUDGET;
    for s in rest {
        let mut size = 0;
        if writes(s, &|k| k == d || Some(k) == source, &mut size) || size > budget {
            return;
        }
        budget -= size;
        replace(s, d, by);
    }
}

/// Whether the statement writes a local `hit` picks, at any depth; `size`
/// counts the statements and expressions looked at.
fn writes(s: &mut Stmt, hit: &dyn Fn(LocalId) -> bool, size: &mut usize) -> bool {
    let mut found = false;
    *size += 1;
    s.for_each_named_local_mut(|u, k| found |= u != LocalUse::Read && hit(*k));
    s.for_each_expr_mut(|e| *size += e.size());
    s.for_each_body_mut(|b| {
        for s in b {
            found = found || writes(s, hit, size);
        }
    });
    found
}

/// Replaces reads of `d` by `by` in a statement, at any depth. A mark
/// read outside an expression (`Truncate(d)`) can take a local only.
fn replace(s: &mut Stmt, d: LocalId, by: &Expr) {
    s.for_each_expr_mut(|e| replace_in(e, d, by));
    if let Expr::Local(source) = by {
        s.for_each_named_local_mut(|u, k| {
            if u == LocalUse::Read && *k == d {
                *k = *source;
            }
        });
    }
    s.for_each_body_mut(|b| b.iter_mut().for_each(|s| replace(s, d, by)));
}

fn replace_in(e: &mut Expr, d: LocalId, by: &Expr) {
    match e {
        Expr::Local(k) if *k == d => *e = by.clone(),
        Expr::Written(k) if *k == d => {
            if let Expr::Local(source) = by {
                *k = *source;
            }
        }
        e => e.for_each_operand_mut(|a| replace_in(a, d, by)),
    }
}

/// Where `break` and `continue` go: the locals live after the loop and at
/// its head.
struct Loop<'a> {
    exit: &'a Live,
    head: &'a Live,
}

/// Drops the dead stores of a statement list whose successor reads
/// `after`; returns the locals live at its start.
fn drop_dead(body: &mut Vec<Stmt>, after: Live, in_loop: Option<&Loop>) -> Live {
    let mut live = after;
    let mut kept = Vec::with_capacity(body.len());
    for mut s in std::mem::take(body).into_iter().rev() {
        if dead(&mut s, &live) {
            continue;
        }
        live = live_before(&mut s, live, in_loop);
        kept.push(s);
    }
    kept.reverse();
    *body = kept;
    live
}

/// A store of a value nobody reads, whose computing has no effect.
fn dead(s: &mut Stmt, live: &Live) -> bool {
    match s {
        Stmt::Assign(Place::Local(d), e) => !live.contains(d) && no_effect(e),
        Stmt::Mark(d) => !live.contains(d),
        _ => false,
    }
}

/// Computing the value changes nothing else: no call, no formatting
/// through a variable, no builtin, no `+` that may build a text past the
/// text budget.
fn no_effect(e: &mut Expr) -> bool {
    match e {
        Expr::Call(..) | Expr::Builtin(..) | Expr::FormatVar { .. } | Expr::Format { .. } => false,
        Expr::Binary(BinaryOp::Add | BinaryOp::Concat, ..) => false,
        e => {
            let mut none = true;
            e.for_each_operand_mut(|a| none &= no_effect(a));
            none
        }
    }
}

/// The locals live before a statement (dropping dead stores inside it).
fn live_before(s: &mut Stmt, after: Live, in_loop: Option<&Loop>) -> Live {
    match s {
        Stmt::If { branches, otherwise } => {
            let mut live = drop_dead(otherwise, after.clone(), in_loop);
            for (cond, body) in branches.iter_mut().rev() {
                live.extend(drop_dead(body, after.clone(), in_loop));
                reads(cond, &mut live);
            }
            live
        }
        // A body that ends in a jump and never continues runs at most
        // once: what is live at its start is live at the loop's.
        Stmt::While { cond, body, .. } if ends_in_jump(body) && !continues(body) => {
            let mut head = drop_dead(body, Live::new(), Some(&Loop { exit: &after, head: &Live::new() }));
            // `while (true)` always runs its body; another test may skip it.
            if !matches!(cond, Expr::Bool(true)) {
                head.extend(after);
            }
            reads(cond, &mut head);
            head
        }
        Stmt::While { cond, body, .. } => {
            let mut head = after.clone();
            reads(cond, &mut head);
            body.iter_mut().for_each(|s| all_reads(s, &mut head));
            drop_dead(body, head.clone(), Some(&Loop { exit: &after, head: &head }));
            head
        }
        // Out of a loop, `break` leaves the function: its frame is gone.
        Stmt::Break => in_loop.map_or_else(Live::new, |l| l.exit.clone()),
        Stmt::Continue => in_loop.map_or_else(Live::new, |l| l.head.clone()),
        Stmt::Return(value) => {
            let mut live = Live::new();
            if let Some(e) = value {
                reads(e, &mut live);
            }
            live
        }
        s => {
            let mut live = after;
            s.for_each_named_local_mut(|u, k| {
                if u == LocalUse::Write {
                    live.remove(k);
                }
            });
            own_reads(s, &mut live);
            live
        }
    }
}

/// Whether a statement list ends in `break`, `continue` or `return`.
fn ends_in_jump(body: &[Stmt]) -> bool {
    matches!(body.last(), Some(Stmt::Break | Stmt::Continue | Stmt::Return(_)))
}

/// Whether a loop body ends in `break` and never continues its loop: it
/// runs at most once (the loop a spliced function runs in).
pub(super) fn runs_once(body: &[Stmt]) -> bool {
    matches!(body.last(), Some(Stmt::Break)) && !continues(body)
}

/// Whether a loop body continues that loop (not a loop nested in it).
fn continues(body: &[Stmt]) -> bool {
    body.iter().any(|s| match s {
        Stmt::Continue => true,
        Stmt::If { branches, otherwise } => branches.iter().any(|(_, b)| continues(b)) || continues(otherwise),
        _ => false,
    })
}

/// Adds the locals an expression reads.
fn reads(e: &mut Expr, live: &mut Live) {
    e.for_each_local_mut(&mut |k| {
        live.insert(*k);
    });
}

/// Adds the locals a statement itself reads (not its nested statements).
fn own_reads(s: &mut Stmt, live: &mut Live) {
    s.for_each_named_local_mut(|u, k| {
        if u != LocalUse::Write {
            live.insert(*k);
        }
    });
    s.for_each_expr_mut(|e| reads(e, live));
}

/// Adds the locals a statement reads, at any depth.
fn all_reads(s: &mut Stmt, live: &mut Live) {
    own_reads(s, live);
    s.for_each_body_mut(|b| b.iter_mut().for_each(|s| all_reads(s, live)));
}
