//! Functions that take functions, specialised per call site: a call that
//! passes a function expression (or null) where the callee only calls it
//! runs a copy of the callee that calls the function directly.
//!
//! Field posts pass callbacks: `motionBlock(code, axes, function () {
//! return [getCompensation()]; }, null)`, `feedOf(movement, fWord.word)`.
//! As written, each call makes a closure (a function value holding its
//! captures) and the callee calls it as a value: a closure allocated per
//! move, and a call through the value. Here a call `F(..., function
//! expression, ...)` becomes a call of a copy of `F` in which each call of
//! that parameter is a direct call of the expression's function with its
//! captures, and the captures are passed to the copy in the closure's
//! place; a parameter given null or `undefined` is that constant in the
//! copy (so `before ? before() : []` folds to `[]`). The preconditions:
//!
//! - the post has no script (a script host calls functions by name);
//! - `F` is a function of the post in native code, reads no `arguments`,
//!   and the call passes it at most as many arguments as it has
//!   parameters;
//! - the parameter is called by `F` (`p(...)`): only such parameters are
//!   specialised, with a function expression (a closure whose captures are
//!   constants or the caller's locals, which nothing between the closure
//!   and the call can change: an expression assigns no local) or null or
//!   `undefined`;
//! - for a function expression, `F` uses the parameter only as a callee
//!   (`p(...)`) and as a condition (`p ? a : b`, `if (p)`, `!p`, `p &&
//!   ...`): a closure is always truthy, and a call of it is a call of its
//!   function with its captures first, as the engine makes that call
//!   (`this` undefined); the parameter is never assigned;
//! - for null or `undefined`, the parameter is never assigned.
//!
//! What the post writes is unchanged: the copy runs the statements of `F`
//! with the same values, and no code could tell the closure's identity,
//! since `F` only called it. A call site with the same specialisation as
//! another shares its copy; copies are made up to [`MAX_COPIES`].

use std::collections::HashMap;

use postc_ir::{FunctionId, LocalId, Place, UnaryOp};

use super::fields::each_expr;
use crate::exec::{self, Expr, Stmt};

/// At most this many specialised copies are made for a post.
const MAX_COPIES: usize = 256;

/// What an argument position of a specialised copy stands for.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Spec {
    /// The argument as it is.
    Keep,
    /// A function expression: its function and how many captures it has.
    Closure(FunctionId, usize),
    Null,
    Undefined,
}

/// Specialises the calls that meet the preconditions (module
/// documentation), adding a copy of the callee for each specialisation.
pub fn specialise(functions: &mut Vec<exec::Function>, handlers: &mut [Vec<Stmt>], init: &mut [Stmt]) {
    if functions.iter().any(|f| matches!(f.body, exec::Body::Script(_))) {
        return;
    }
    let mut copies: HashMap<(FunctionId, Vec<Spec>), Option<FunctionId>> = HashMap::new();
    // A copy may pass function expressions on: a few rounds.
    for _ in 0..8 {
        let called: Vec<Vec<bool>> = functions.iter().map(called_params).collect();
        // The specialisations the calls ask for.
        let mut wanted: Vec<(FunctionId, Vec<Spec>)> = Vec::new();
        each_expr(functions, handlers, init, &mut |e| {
            if let Some(key) = spec_of(e, &called)
                && !copies.contains_key(&key)
                && !wanted.contains(&key)
            {
                wanted.push(key);
            }
        });
        if wanted.is_empty() {
            break;
        }
        for key in wanted {
            let made =
                if copies.values().flatten().count() < MAX_COPIES { copy(functions, &key.0, &key.1) } else { None };
            let id = match made {
                Some(f) => match FunctionId::from_usize(functions.len()) {
                    Some(id) => {
                        functions.push(f);
                        Some(id)
                    }
                    None => None,
                },
                None => None,
            };
            copies.insert(key, id);
        }
        let called: Vec<Vec<bool>> = functions.iter().map(called_params).collect();
        let fills: Vec<Expr> = functions.iter().map(exec::Function::fill).collect();
        each_expr(functions, handlers, init, &mut |e| {
            let Some(key) = spec_of(e, &called) else { return };
            let Some(Some(id)) = copies.get(&key) else { return };
            let Expr::Call(_, args) = e else { return };
            let mut new_args = Vec::with_capacity(args.len());
            let mut caps = Vec::new();
            for (a, s) in std::mem::take(args).into_iter().zip(key.1.iter().chain(std::iter::repeat(&Spec::Keep))) {
                match (s, a) {
                    (Spec::Keep, a) => new_args.push(a),
                    (Spec::Closure(..), Expr::Closure { captures, .. }) => {
                        new_args.push(Expr::Undefined);
                        caps.extend(captures);
                    }
                    _ => new_args.push(Expr::Undefined),
                }
            }
            let params = key.1.len();
            let fill = fills.get(key.0.index()).cloned().unwrap_or(Expr::Undefined);
            while new_args.len() < params {
                new_args.push(fill.clone());
            }
            new_args.extend(caps);
            *e = Expr::Call(*id, new_args);
        });
    }
}

/// Which parameters a function calls as functions (`p(...)`).
fn called_params(f: &exec::Function) -> Vec<bool> {
    let mut called = vec![false; f.params];
    let mut body = match &f.body {
        exec::Body::Native(b) => b.clone(),
        exec::Body::Script(_) => return called,
    };
    fn expr(e: &mut Expr, called: &mut [bool]) {
        if let Expr::CallValue(callee, _) = e
            && let Expr::Local(l) = **callee
            && let Some(c) = called.get_mut(l.index())
        {
            *c = true;
        }
        e.for_each_operand_mut(|a| expr(a, called));
    }
    fn stmts(body: &mut [Stmt], called: &mut [bool]) {
        for s in body {
            s.for_each_expr_mut(|e| expr(e, called));
            s.for_each_body_mut(|b| stmts(b, called));
        }
    }
    stmts(&mut body, &mut called);
    called
}

/// The specialisation a call asks for, if it asks for one.
fn spec_of(e: &Expr, called: &[Vec<bool>]) -> Option<(FunctionId, Vec<Spec>)> {
    let Expr::Call(f, args) = e else { return None };
    let params = called.get(f.index())?;
    if args.len() > params.len() {
        return None;
    }
    let mut any = false;
    let specs: Vec<Spec> = (0..params.len())
        .map(|i| {
            let spec = match args.get(i) {
                Some(_) if !params[i] => Spec::Keep,
                Some(Expr::Closure { function, captures })
                    if captures.iter().all(|c| matches!(c, Expr::Local(_)) || constant(c)) =>
                {
                    Spec::Closure(*function, captures.len())
                }
                Some(Expr::Null) => Spec::Null,
                Some(Expr::Undefined) => Spec::Undefined,
                _ => Spec::Keep,
            };
            any |= spec != Spec::Keep;
            spec
        })
        .collect();
    any.then_some((*f, specs))
}

fn constant(e: &Expr) -> bool {
    matches!(e, Expr::Number(_) | Expr::Text(_) | Expr::Bool(_) | Expr::Null | Expr::Undefined | Expr::Output(_))
}

/// The copy of `f` specialised as `specs` say; `None` when a precondition
/// fails.
fn copy(functions: &[exec::Function], f: &FunctionId, specs: &[Spec]) -> Option<exec::Function> {
    let function = functions.get(f.index())?;
    let exec::Body::Native(body) = &function.body else { return None };
    if function.uses_arguments || specs.len() != function.params {
        return None;
    }
    let extra: usize = specs.iter().map(|s| if let Spec::Closure(_, k) = s { *k } else { 0 }).sum();
    let params = function.params;
    let slots = usize::from(function.slots).checked_add(extra)?;
    let slots = u16::try_from(slots).ok()?;
    // Where each closure's captures are, in the copy's frame.
    let mut first = params;
    let mut closures = Vec::new();
    for (i, s) in specs.iter().enumerate() {
        if let Spec::Closure(g, k) = s {
            let g_fn = functions.get(g.index())?;
            if g_fn.params < *k || matches!(g_fn.body, exec::Body::Script(_)) {
                return None;
            }
            closures.push((i, *g, first, *k));
            first += k;
        }
    }
    let mut body = body.clone();
    let mut ok = true;
    let mut r = Rewriter { specs, closures: &closures, params, extra, ok: &mut ok };
    r.stmts(&mut body);
    if !ok {
        return None;
    }
    Some(exec::Function {
        params: params + extra,
        uses_arguments: false,
        uses_this: function.uses_this,
        starts_undefined: function.starts_undefined,
        slots,
        body: exec::Body::Native(body),
        origin: function.origin,
        returns: None,
    })
}

/// Rewrites a body for [`copy`].
struct Rewriter<'a> {
    specs: &'a [Spec],
    /// Each closure parameter: its position, function, first capture's
    /// local in the copy, and capture count.
    closures: &'a [(usize, FunctionId, usize, usize)],
    params: usize,
    extra: usize,
    ok: &'a mut bool,
}

impl Rewriter<'_> {
    /// A local of the original in the copy's frame: locals after the
    /// parameters move up past the captures.
    fn moved(&mut self, l: &mut LocalId) {
        if l.index() >= self.params {
            match LocalId::from_usize(l.index() + self.extra) {
                Some(n) => *l = n,
                None => *self.ok = false,
            }
        }
    }

    fn spec(&self, l: LocalId) -> &Spec {
        self.specs.get(l.index()).unwrap_or(&Spec::Keep)
    }

    /// `truthy`: the expression is only tested for truth where it is.
    fn expr(&mut self, e: &mut Expr, truthy: bool) {
        match e {
            Expr::CallValue(callee, args) if matches!(**callee, Expr::Local(l) if matches!(self.spec(l), Spec::Closure(..))) =>
            {
                let Expr::Local(l) = **callee else { return };
                let Some(&(_, g, first, k)) = self.closures.iter().find(|c| c.0 == l.index()) else {
                    *self.ok = false;
                    return;
                };
                for a in args.iter_mut() {
                    self.expr(a, false);
                }
                let mut all: Vec<Expr> = (first..first + k)
                    .map(|c| LocalId::from_usize(c).map(Expr::Local).unwrap_or(Expr::Undefined))
                    .collect();
                all.append(args);
                *e = Expr::Call(g, all);
            }
            Expr::Local(l) => match self.spec(*l).clone() {
                Spec::Keep => self.moved(l),
                Spec::Closure(..) if truthy => *e = Expr::Bool(true),
                Spec::Closure(..) => *self.ok = false,
                Spec::Null => *e = Expr::Null,
                Spec::Undefined => *e = Expr::Undefined,
            },
            Expr::Written(l) | Expr::LocalEmpty { local: l, .. } | Expr::LocalIsText { local: l, .. } => {
                if *self.spec(*l) != Spec::Keep {
                    *self.ok = false;
                }
                self.moved(l);
            }
            Expr::Arguments => *self.ok = false,
            Expr::Choose(c, a, b) => {
                self.expr(c, true);
                self.expr(a, truthy);
                self.expr(b, truthy);
            }
            Expr::Unary(UnaryOp::Not, a) => self.expr(a, true),
            Expr::Binary(postc_ir::BinaryOp::And, a, b) => {
                self.expr(a, true);
                self.expr(b, truthy);
            }
            e => e.for_each_operand_mut(|a| self.expr(a, false)),
        }
    }

    fn stmts(&mut self, body: &mut [Stmt]) {
        for s in body {
            match s {
                Stmt::If { branches, otherwise } => {
                    for (c, b) in branches.iter_mut() {
                        self.expr(c, true);
                        self.stmts(b);
                    }
                    self.stmts(otherwise);
                    continue;
                }
                Stmt::While { cond, body, step, .. } => {
                    self.expr(cond, true);
                    self.stmts(body);
                    self.stmts(step);
                    continue;
                }
                _ => {}
            }
            if let Stmt::Assign(Place::Local(l), _) = s
                && *self.spec(*l) != Spec::Keep
            {
                *self.ok = false;
            }
            s.for_each_named_local_mut(|_, l| {
                if *self.spec(*l) != Spec::Keep {
                    *self.ok = false;
                }
                self.moved(l);
            });
            s.for_each_expr_mut(|e| self.expr(e, false));
            s.for_each_body_mut(|b| self.stmts(b));
        }
    }
}
