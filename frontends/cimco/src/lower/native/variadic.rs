//! Functions that read `arguments` (field posts' `writeBlock("G1", x, y)`),
//! specialized per number of arguments.
//!
//! Each distinct number of arguments a function that reads `arguments` is
//! called with gets its own IR function (the function's own IR index
//! serves calls with as many arguments as it has parameters): in it
//! `arguments.length` is a constant, `arguments[k]` is the slot of argument
//! `k`, and a `for` loop over the arguments unrolls. Native callers call the
//! form for their number of arguments; scripts call the Rhai function, which
//! takes any number. Entry points postc calls itself (`onLinear`, ...) keep
//! the general form.

use std::collections::BTreeSet;

use postc_ir::{Expr as Ir, LocalId, Place, Stmt as IrStmt};

use crate::ast::*;

use super::super::model::Model;
use super::super::scope::{FnId, Symbol, Visit, walk_stmt, walk_stmts};
use super::{Native, R, breaks_switch, has_continue, why};

/// At most this many arguments get a specialization of their own, and a
/// loop over the arguments unrolls at most this many times.
pub const MAX_ARITY: usize = 64;

/// Whether a name is one of the entry points postc calls (`onLinear`, ...).
pub fn is_entry(name: &str) -> bool {
    name.strip_prefix("on").and_then(|r| r.chars().next()).is_some_and(|c| c.is_ascii_uppercase())
}

/// Whether a function reads `arguments` and can be specialized per number
/// of arguments: a top-level function that is not an entry point, never
/// reassigned, without `this`, closures or nested functions.
pub fn specializable(model: &Model, id: FnId) -> bool {
    let info = &model.scopes.funcs[id];
    let Some(i) = model.scopes.top_fns.iter().position(|&t| t == id) else { return false };
    info.uses_arguments
        && !info.uses_this
        && !info.captures
        && info.nested.is_empty()
        && !model.fn_reassigned.contains(&i)
        && !info.name.as_deref().is_some_and(is_entry)
}

/// Every (function, number of arguments) that needs a specialization of
/// its own: calls `f(a, b, c)`, `f.apply(null, [a, b])`, and
/// `f.apply(null, arguments)` in a function with its own forms.
pub fn arities(model: &Model, program: &Program) -> Vec<(FnId, usize)> {
    let mut c = Calls { model, at: 0, found: BTreeSet::new(), forwards: Vec::new() };
    walk_stmts(&program.body, &mut c);
    for id in 1..model.scopes.funcs.len() {
        if let Some(f) = model.scopes.funcs[id].func {
            c.at = id;
            walk_stmts(&f.body, &mut c);
        }
    }
    let Calls { mut found, forwards, .. } = c;
    let params = |id: FnId| model.scopes.funcs[id].params.len();
    loop {
        let mut changed = false;
        for &(from, to) in &forwards {
            let counts: Vec<usize> =
                found.iter().filter(|(f, _)| *f == from).map(|(_, n)| *n).chain([params(from)]).collect();
            for n in counts {
                changed |= found.insert((to, n));
            }
        }
        if !changed {
            break;
        }
    }
    found.into_iter().filter(|&(id, n)| n != params(id) && n <= MAX_ARITY).collect()
}

struct Calls<'m, 'a> {
    model: &'m Model<'a>,
    at: FnId,
    found: BTreeSet<(FnId, usize)>,
    /// `f.apply(null, arguments)` in function `.0` calls `.1`.
    forwards: Vec<(FnId, FnId)>,
}

impl Calls<'_, '_> {
    fn target(&self, name: &str) -> Option<FnId> {
        match self.model.scopes.resolve(name, self.at) {
            Symbol::TopFn(i) => {
                let id = self.model.scopes.top_fns[i];
                specializable(self.model, id).then_some(id)
            }
            _ => None,
        }
    }
}

impl<'a> Visit<'a> for Calls<'_, 'a> {
    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Function(_) => return false,
            ExprKind::Call { callee, args } => match &callee.kind {
                ExprKind::Ident(name) => {
                    if let Some(id) = self.target(name) {
                        self.found.insert((id, args.len()));
                    }
                }
                ExprKind::Member { object, property } if property.name == "apply" && args.len() == 2 => {
                    if let ExprKind::Ident(name) = &object.kind
                        && let Some(id) = self.target(name)
                    {
                        match &args[1].kind {
                            ExprKind::Array(items) => {
                                self.found.insert((id, items.len()));
                            }
                            ExprKind::Ident(a) if a == "arguments" && specializable(self.model, self.at) => {
                                self.forwards.push((self.at, id));
                            }
                            _ => {}
                        }
                    }
                }
                _ => {}
            },
            _ => {}
        }
        true
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}

impl Native<'_, '_> {
    /// The slot of argument `k` of a specialization.
    pub(super) fn arg_slot(&self, k: usize) -> LocalId {
        let params = self.model.scopes.funcs[self.at].params.len();
        if k < params { self.local(k) } else { LocalId::new(k as u16) }
    }

    /// The IR function a call of top-level function `i` with `n` arguments
    /// reaches. A function that reads `arguments` gets its form for `n`
    /// arguments here when no call seen before lowering needed it (a list
    /// whose length the lowering finds: `f.apply(null, words)`).
    pub(super) fn call_target(
        &mut self,
        i: usize,
        name: &str,
        n: usize,
        at: postc_ir::Span,
    ) -> R<postc_ir::FunctionId> {
        let id = self.model.scopes.top_fns[i];
        let info = &self.model.scopes.funcs[id];
        if self.model.fn_reassigned.contains(&i) {
            return Err(why(at, format!("calls `{name}`, which the post assigns another function to")));
        }
        let variadic = specializable(self.model, id);
        if n > info.params.len() && !variadic {
            return Err(why(
                at,
                format!(
                    "calls `{name}` with more arguments than its parameters (the extra ones are read through `arguments`)"
                ),
            ));
        }
        if !self.model.returns_plain[id] {
            return Err(why(at, format!("calls `{name}`, which may return an object, an array or a function")));
        }
        if variadic && n != info.params.len() {
            if let Some(f) = self.layout.variadic.get(&(id, n)) {
                return Ok(*f);
            }
            if n > MAX_ARITY {
                return Err(why(at, format!("calls `{name}` with {n} arguments, more than postc specializes")));
            }
            let f = self.layout.add_fn(&format!("{name}/{n}"));
            self.layout.variadic.insert((id, n), f);
            self.layout.clones.push((id, n));
            return Ok(f);
        }
        self.layout.top_fn.get(i).copied().ok_or_else(|| why(at, format!("calls `{name}`")))
    }

    /// `f.apply(null, [a, b])` and, in a specialization,
    /// `f.apply(null, arguments)`: a call with those arguments.
    pub(super) fn apply(&mut self, i: usize, name: &str, args: &[Expr], at: postc_ir::Span) -> R<Ir> {
        if !matches!(args[0].kind, ExprKind::Null | ExprKind::Undefined) {
            return Err(why(at, format!("calls `{name}.apply` with a `this` other than `null`")));
        }
        match &args[1].kind {
            ExprKind::Array(items) => {
                let f = self.call_target(i, name, items.len(), at)?;
                Ok(Ir::Call(f, self.args(items)?))
            }
            ExprKind::Ident(t) if self.table_info(t).is_some_and(|t| t.array.is_some()) => {
                let Some(items) = self.table(t) else {
                    return Err(why(at, format!("calls `{name}.apply` with table `{t}`, whose entries are objects")));
                };
                let f = self.call_target(i, name, items.len(), at)?;
                Ok(Ir::Call(f, items.into_iter().map(|(_, v)| v).collect()))
            }
            ExprKind::Ident(a) if self.agg_array(a).is_some() => self.apply_aggregate(i, name, a, at),
            ExprKind::Ident(a) if a == "arguments" && self.arity.is_some() => {
                let n = self.arity.unwrap_or(0);
                let f = self.call_target(i, name, n, at)?;
                Ok(Ir::Call(f, (0..n).map(|k| Ir::Local(self.arg_slot(k))).collect()))
            }
            _ => Err(why(
                at,
                format!("calls `{name}.apply` with an array whose length is known only when the post runs"),
            )),
        }
    }

    /// A `for` loop that unrolls: `for (var i = K; i < arguments.length;
    /// i++)` in a specialization, or over the length of an array kept in
    /// slots whose count is known, or up to a number when the body reads
    /// or fills such an array; its body neither assigns `i` nor leaves
    /// with `break` or `continue`. The counter's slot and its first and
    /// end values.
    pub(super) fn unrollable(
        &mut self,
        init: &Option<ForInit>,
        test: &Option<Expr>,
        update: &Option<Expr>,
        body: &Stmt,
    ) -> Option<(usize, f64, f64)> {
        let CountedLoop { name, from, op, to: right } = counted_loop(init, test, update)?;
        let Symbol::Local { func, slot } = self.model.scopes.resolve(name, self.at) else { return None };
        if op != BinaryOp::Lt || func != self.at || self.arrays.contains_key(&slot) {
            return None;
        }
        let is_arguments = matches!(&right.kind, ExprKind::Member { object, property }
            if property.name == "length" && matches!(&object.kind, ExprKind::Ident(a) if a == "arguments"));
        let n = if is_arguments {
            self.arity?
        } else {
            let to = match right.kind {
                ExprKind::Number(n) if n.is_finite() && n >= 0.0 && n == n.trunc() => n as usize,
                ExprKind::Number(_) => return None,
                _ => self.known_length(right)?,
            };
            if !self.mentions_aggregate(body) {
                return None;
            }
            to
        };
        let to = n as f64;
        if has_continue(body) || breaks_switch(body) || assigns(body, name) || to - from > MAX_ARITY as f64 {
            return None;
        }
        Some((slot, from, to))
    }

    /// The body once per value of the counter, then the counter at its end.
    pub(super) fn unroll(&mut self, slot: usize, from: f64, to: f64, body: &Stmt, out: &mut Vec<IrStmt>) -> R<()> {
        let mut k = from;
        while k < to {
            self.unrolled.insert(slot, k);
            let r = self.stmt(body, out);
            self.unrolled.remove(&slot);
            r?;
            k += 1.0;
        }
        out.push(IrStmt::Assign(Place::Local(self.local(slot)), Ir::Number(k)));
        Ok(())
    }
}

/// Whether a statement assigns (or declares) a name.
pub(super) fn assigns(body: &Stmt, name: &str) -> bool {
    struct A<'n> {
        name: &'n str,
        found: bool,
    }
    impl<'a> Visit<'a> for A<'_> {
        fn expr(&mut self, e: &'a Expr) -> bool {
            match &e.kind {
                ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } => {
                    if matches!(&target.kind, ExprKind::Ident(x) if x == self.name) {
                        self.found = true;
                    }
                }
                ExprKind::Function(_) => return false,
                _ => {}
            }
            true
        }
        fn stmt(&mut self, s: &'a Stmt) -> bool {
            match &s.kind {
                StmtKind::Var(ds) if ds.iter().any(|d| d.name.name == self.name && d.init.is_some()) => {
                    self.found = true
                }
                StmtKind::ForIn { name, .. } if name.name == self.name => self.found = true,
                _ => {}
            }
            true
        }
        fn function_decl(&mut self, _f: &'a Function) {}
    }
    let mut a = A { name, found: false };
    walk_stmt(body, &mut a);
    a.found
}

/// A counted `for` loop: `for (var i = FROM; i OP TO; i++)` (or `i =
/// FROM`, `i += 1`) with `FROM` a number and `OP` `<` or `<=`.
pub(super) struct CountedLoop<'e> {
    pub name: &'e str,
    pub from: f64,
    pub op: BinaryOp,
    pub to: &'e Expr,
}

/// The counted loop a `for` statement's head is, if it is one.
pub(super) fn counted_loop<'e>(
    init: &'e Option<ForInit>,
    test: &'e Option<Expr>,
    update: &'e Option<Expr>,
) -> Option<CountedLoop<'e>> {
    let number = |e: &Expr| match e.kind {
        ExprKind::Number(x) => Some(x),
        _ => None,
    };
    let (name, from) = match init {
        Some(ForInit::Var(ds)) if ds.len() == 1 => (&ds[0].name.name, number(ds[0].init.as_ref()?)?),
        Some(ForInit::Expr(Expr { kind: ExprKind::Assign { op: AssignOp::Assign, target, value }, .. })) => {
            match &target.kind {
                ExprKind::Ident(name) => (name, number(value)?),
                _ => return None,
            }
        }
        _ => return None,
    };
    let is_i = |e: &Expr| matches!(&e.kind, ExprKind::Ident(x) if x == name);
    let ExprKind::Binary { op: op @ (BinaryOp::Lt | BinaryOp::Le), left, right } = &test.as_ref()?.kind else {
        return None;
    };
    let steps = match &update.as_ref()?.kind {
        ExprKind::Update { op: UpdateOp::Increment, target, .. } => is_i(target),
        ExprKind::Assign { op: AssignOp::Add, target, value } => is_i(target) && number(value) == Some(1.0),
        _ => false,
    };
    (is_i(left) && steps).then_some(CountedLoop { name, from, op: *op, to: right })
}
