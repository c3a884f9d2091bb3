//! Splicing small value functions into handlers: `x = motion(motionCode(1))`
//! or `c = takeCompensation()` in a handler becomes the function's own
//! statements, run in fresh slots of the handler's frame, so that a move
//! pays no call for them (no frame, no call bookkeeping) and
//! [`super::locals`] can read their arguments through and fold what the
//! handler's constants decide (`motionCode(1)` is `"G1"`).
//!
//! A function is spliced when it is small and its statements are
//! assignments, `if`s, `return`s and evaluations only: no loop, no output
//! of its own (the calls it makes stay calls). Its body runs inside a
//! loop that runs once, each `return v` becoming `x = v; break`, so that
//! it leaves where the function would:
//!
//! ```text
//! a0 = "G1"; a1 = null                 // arguments, then the other locals
//! while (true) { if (a0 == last) { x = ""; break }  last = a0; x = a0; break }
//! ```
//!
//! A call that is one arm of a choice stored in a local (`h = z != "" ?
//! lengthOffset() : ""`) is spliced into the arm of an `if` the choice
//! becomes.
//!
//! The arguments are evaluated in their order before the body, as a call
//! evaluates them; the function's locals start as `null` at every splice,
//! as a call's frame does. The function itself stays, for every other
//! caller.

use postc_ir::{LocalId, Place};

use super::emit::max_slot;
use crate::exec::{Body, Expr, Function, Stmt};

/// Statements and expressions a spliced function has at most.
const MAX_NODES: usize = 64;

/// Splices the small functions a handler body calls.
#[doc(hidden)]
pub fn small_functions(functions: &[Function], body: &mut Vec<Stmt>) {
    let small: Vec<bool> = functions.iter().map(is_small).collect();
    if !small.contains(&true) {
        return;
    }
    let mut splicer = Splicer { functions, small, next: max_slot(body).map_or(0, |k| k.index() + 1) };
    *body = splicer.list(std::mem::take(body));
}

struct Splicer<'f> {
    functions: &'f [Function],
    small: Vec<bool>,
    /// The first slot no statement uses yet.
    next: usize,
}

impl Splicer<'_> {
    fn list(&mut self, body: Vec<Stmt>) -> Vec<Stmt> {
        let mut out = Vec::with_capacity(body.len());
        for mut s in body {
            s.for_each_body_mut(|b| *b = self.list(std::mem::take(b)));
            match s {
                Stmt::Assign(Place::Local(d), Expr::Call(f, args)) if self.fits(f.index(), args.len()) => {
                    self.splice(f.index(), args, Some(d), &mut out)
                }
                Stmt::Eval(Expr::Call(f, args)) if self.fits(f.index(), args.len()) => {
                    self.splice(f.index(), args, None, &mut out)
                }
                // `h = z != "" ? lengthOffset() : ""`: the choice as an
                // `if` of two stores, so that the call is spliced there.
                Stmt::Assign(Place::Local(d), Expr::Choose(c, a, b))
                    if [&*a, &*b]
                        .iter()
                        .any(|e| matches!(e, Expr::Call(f, args) if self.fits(f.index(), args.len()))) =>
                {
                    let choice = Stmt::If {
                        branches: vec![(*c, vec![Stmt::Assign(Place::Local(d), *a)])],
                        otherwise: vec![Stmt::Assign(Place::Local(d), *b)],
                    };
                    out.extend(self.list(vec![choice]));
                }
                s => out.push(s),
            }
        }
        out
    }

    /// Whether a call of `f` with `args` arguments can be spliced.
    fn fits(&self, f: usize, args: usize) -> bool {
        self.small.get(f).copied().unwrap_or(false) && {
            let slots = usize::from(self.functions[f].slots);
            args <= slots && self.next + slots <= usize::from(u16::MAX)
        }
    }

    /// Writes the statements of a call of `f` into `out`, its value going
    /// to `dest`.
    fn splice(&mut self, f: usize, args: Vec<Expr>, dest: Option<LocalId>, out: &mut Vec<Stmt>) {
        let function = &self.functions[f];
        let Body::Native(code) = &function.body else { return };
        let base = self.next;
        self.next += usize::from(function.slots);
        let slot = |i: usize| LocalId::new((base + i) as u16);
        let given = args.len();
        for (i, a) in args.into_iter().enumerate() {
            match a {
                Expr::Call(g, inner) if self.fits(g.index(), inner.len()) => {
                    self.splice(g.index(), inner, Some(slot(i)), out)
                }
                a => out.push(Stmt::Assign(Place::Local(slot(i)), a)),
            }
        }
        let fill = function.fill();
        for i in given..usize::from(function.slots) {
            out.push(Stmt::Assign(Place::Local(slot(i)), fill.clone()));
        }
        let mut body = code.clone();
        body.iter_mut().for_each(|s| shift(s, base));
        let mut body = returns(body, dest, &fill);
        if !matches!(body.last(), Some(Stmt::Break)) {
            if let Some(d) = dest {
                body.push(Stmt::Assign(Place::Local(d), fill));
            }
            body.push(Stmt::Break);
        }
        out.push(Stmt::While { cond: Expr::Bool(true), body, span: None, step: vec![] });
    }
}

/// Moves every local of a statement `by` slots up.
fn shift(s: &mut Stmt, by: usize) {
    let up = |k: &mut LocalId| *k = LocalId::new((k.index() + by) as u16);
    s.for_each_expr_mut(|e| e.for_each_local_mut(&mut |k| up(k)));
    s.for_each_named_local_mut(|_, k| up(k));
    s.for_each_body_mut(|b| b.iter_mut().for_each(|s| shift(s, by)));
}

/// `return v` as `dest = v; break` (or `v; break` when the value is not
/// kept), at any depth.
fn returns(body: Vec<Stmt>, dest: Option<LocalId>, fill: &Expr) -> Vec<Stmt> {
    let mut out = Vec::with_capacity(body.len());
    for mut s in body {
        match s {
            Stmt::Return(value) => {
                let value = value.unwrap_or_else(|| fill.clone());
                out.push(match dest {
                    Some(d) => Stmt::Assign(Place::Local(d), value),
                    None => Stmt::Eval(value),
                });
                out.push(Stmt::Break);
                break;
            }
            _ => {
                s.for_each_body_mut(|b| *b = returns(std::mem::take(b), dest, fill));
                out.push(s);
            }
        }
    }
    out
}

/// A native function of assignments, `if`s, `return`s and evaluations, at
/// most [`MAX_NODES`] big. The calls it makes stay calls (a function is
/// spliced one level deep, so recursion cannot splice without end).
fn is_small(f: &Function) -> bool {
    let Body::Native(body) = &f.body else { return false };
    // An expression function is better inlined as its expression.
    if super::inline::is_expression_function(f) {
        return false;
    }
    let mut nodes = 0;
    let mut body = body.clone();
    body.iter_mut().all(|s| plain(s, &mut nodes)) && nodes <= MAX_NODES
}

fn plain(s: &mut Stmt, nodes: &mut usize) -> bool {
    *nodes += 1;
    if !matches!(s, Stmt::Assign(..) | Stmt::If { .. } | Stmt::Return(_) | Stmt::Eval(_) | Stmt::Forget(_)) {
        return false;
    }
    s.for_each_expr_mut(|e| *nodes += e.size());
    let mut ok = true;
    s.for_each_body_mut(|b| ok &= b.iter_mut().all(|s| plain(s, nodes)));
    ok
}
