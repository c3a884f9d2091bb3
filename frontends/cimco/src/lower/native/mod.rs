//! JavaScript to native IR statements.
//!
//! A function lowers to native IR when everything in it is something the
//! IR's statement language says the way JavaScript means it: locals,
//! plain globals, numbers, text and booleans, the operators, `if`,
//! simple loops and `switch`es, calls of post functions and host
//! functions (`getFeedrate`, `Math.*`, `parseFloat`, ...), and the
//! `format`/`getLast` methods of the output variables and formats bound
//! at compile time. Anything else (objects, arrays, closures, `this`,
//! `new`, `try`, regular expressions, a global that may hold an object)
//! makes the whole function run as a script instead; [`lower_function`]
//! says why then ([`Why`]: the construct and where it is), and
//! `postc inspect` shows it.

use std::collections::HashMap;

use postc_ir::{BinaryOp as IrBin, Builtin, Expr as Ir, LocalId, Place, Stmt as IrStmt, UnaryOp as IrUn};

use crate::ast::*;

mod aggregates;
mod arrays;
mod calls;
mod coalesce;
mod flow;
mod tables;
pub mod variadic;

use aggregates::Count;
pub use aggregates::{Lowered, RetShape, lower_top};

use super::builtins;
use super::consts::Const;
use super::layout::{self, Layout};
use super::model::Model;
use super::scope::{FnId, Symbol};
use super::setup::Setup;

/// Lowering context of one function.
pub struct Native<'c, 'a> {
    pub model: &'c Model<'a>,
    pub setup: &'c Setup,
    pub layout: &'c mut Layout,
    pub at: FnId,
    /// Slots in use (parameters, locals and temporaries).
    pub slots: u16,
    /// The function is an entry point CNC-Calc calls (`onLinear`, ...):
    /// each `return` is preceded by a [`IrStmt::Origin`], so that `--trace`
    /// names the statement that returned a line.
    pub entry: bool,
    /// `Some(n)`: the function reads `arguments`, and this is its form for
    /// calls with `n` arguments (`arguments.length` is `n`; argument `k`
    /// past the parameters is slot `k`, the `var`s move up to make room).
    pub arity: Option<usize>,
    /// The array locals kept as joined text and a count ([`arrays`]), by slot.
    arrays: HashMap<usize, arrays::ArrayLocal>,
    /// Loop counters of a loop being unrolled, by slot: their value now.
    unrolled: HashMap<usize, f64>,
    /// Arrays and objects kept in slots ([`aggregates`]).
    aggs: aggregates::Aggs,
    /// The function keeps an array or object in slots, reads a look-up
    /// table or hands an array to `apply`: its IR says what it does but
    /// not in the words it was written in, so the CIMCO backend prints it
    /// from its source text (`Function::source`).
    pub reshaped: bool,
}

/// Why a function cannot run as native IR: the first construct that has
/// no native form, and where it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Why {
    pub what: String,
    pub span: postc_ir::Span,
}

type R<T> = Result<T, Why>;

/// The reason at `span`.
fn why(span: postc_ir::Span, what: impl Into<String>) -> Why {
    Why { what: what.into(), span }
}

/// What a statement is, for a reason.
fn stmt_name(k: &StmtKind) -> &'static str {
    match k {
        StmtKind::ForIn { .. } => "a `for ... in` loop",
        StmtKind::Throw(_) => "`throw`",
        StmtKind::Try { .. } => "`try`",
        StmtKind::Function(_) => "a function declared inside a function",
        StmtKind::Error => "a statement that does not parse",
        _ => "a statement",
    }
}

/// What an expression is, for a reason.
fn expr_name(k: &ExprKind) -> &'static str {
    match k {
        ExprKind::This => "`this`",
        ExprKind::Regex { .. } => "a regular expression",
        ExprKind::Array(_) => "an array literal",
        ExprKind::Object(_) => "an object literal",
        ExprKind::Function(_) => "a function expression (a closure)",
        ExprKind::Index { .. } => "indexing (`a[i]`)",
        ExprKind::New { .. } => "`new`",
        ExprKind::Update { .. } => "`++`/`--` inside an expression",
        ExprKind::Assign { .. } => "an assignment inside an expression",
        ExprKind::Sequence(_) => "a comma expression",
        ExprKind::Error => "an expression that does not parse",
        _ => "an expression",
    }
}

impl<'c, 'a> Native<'c, 'a> {
    pub fn new(model: &'c Model<'a>, setup: &'c Setup, layout: &'c mut Layout, at: FnId) -> Self {
        Native {
            model,
            setup,
            layout,
            at,
            slots: 0,
            entry: false,
            arity: None,
            arrays: HashMap::new(),
            unrolled: HashMap::new(),
            aggs: aggregates::Aggs::default(),
            reshaped: false,
        }
    }
}

impl Native<'_, '_> {
    /// The body of a function as native statements, or `None` when it must
    /// run as a script.
    pub fn lower_function(&mut self, body: &[Stmt], span: postc_ir::Span) -> R<Vec<IrStmt>> {
        let info = &self.model.scopes.funcs[self.at];
        if info.uses_arguments && self.arity.is_none() && variadic::specializable(self.model, self.at) {
            // The function's own IR form serves calls with as many
            // arguments as it has parameters.
            self.arity = Some(info.params.len());
        }
        let reason = if info.uses_this {
            Some("uses `this`")
        } else if info.uses_arguments && self.arity.is_none() {
            Some("reads `arguments` (takes a variable number of arguments) and is an entry point postc calls")
        } else if info.captures {
            Some("is a closure: it uses a local of the function around it")
        } else if !info.nested.is_empty() {
            Some("defines a function inside it")
        } else {
            None
        };
        if let Some(r) = reason {
            return Err(why(span, r));
        }
        let params = info.params.len();
        self.slots = (info.locals.len() + self.arity.map_or(0, |n| n.saturating_sub(params))) as u16;
        self.find_arrays(body)?;
        self.find_aggregates(body);
        self.aggs.returns = self.returns_aggregate(body);
        let mut out = self.stmts(body)?;
        coalesce::copies(&mut out, self.arity.unwrap_or(params).max(params));
        Ok(out)
    }

    /// The IR slot of local `slot` (parameters first, then `var`s): the
    /// `var`s of a specialization move past its extra arguments.
    fn local(&self, slot: usize) -> LocalId {
        let params = self.model.scopes.funcs[self.at].params.len();
        match self.arity {
            Some(n) if n > params && slot >= params => LocalId::new((slot + n - params) as u16),
            _ => LocalId::new(slot as u16),
        }
    }

    pub fn stmts(&mut self, body: &[Stmt]) -> R<Vec<IrStmt>> {
        let mut out = Vec::new();
        self.scoped(|n| n.stmts_into(body, &mut out))?;
        Ok(out)
    }

    /// A list of statements into `out`. An `if` whose branches leave an
    /// array with different counts may take the rest of the list into
    /// each branch ([`aggregates`]).
    fn stmts_into(&mut self, body: &[Stmt], out: &mut Vec<IrStmt>) -> R<()> {
        for (i, s) in body.iter().enumerate() {
            if let StmtKind::If { branches, otherwise } = &s.kind
                && !self.setup.done.contains(&s.span.start)
            {
                if self.lower_if(branches, otherwise.as_deref(), &body[i + 1..], out)? {
                    break;
                }
                continue;
            }
            self.stmt(s, out)?;
        }
        Ok(())
    }

    /// Whether the function returns an object or array through hidden
    /// globals ([`aggregates`]): a top-level function that is not an
    /// entry point, whose result may not be plain, and whose one `return`
    /// is its last statement.
    fn returns_aggregate(&self, body: &[Stmt]) -> bool {
        if self.entry || self.arity.is_some() || self.model.returns_plain[self.at] {
            return false;
        }
        if !self.model.scopes.top_fns.contains(&self.at) {
            return false;
        }
        matches!(body.last().map(|s| &s.kind), Some(StmtKind::Return(Some(_)))) && count_returns(body) == 1
    }

    /// An `if`, with what the lowering knows of arrays joined where the
    /// branches meet; `rest` (the statements after it) is lowered into each
    /// branch instead when that keeps counts known. Returns whether it did.
    fn lower_if(
        &mut self,
        branches: &[IfBranch],
        otherwise: Option<&Stmt>,
        rest: &[Stmt],
        out: &mut Vec<IrStmt>,
    ) -> R<bool> {
        let before = self.counts();
        let mut conds = Vec::new();
        let mut bodies: Vec<Vec<IrStmt>> = Vec::new();
        let mut ends: Vec<(Vec<Count>, bool)> = Vec::new();
        for b in branches {
            self.set_counts(&before);
            conds.push(self.expr(&b.cond)?);
            let body = self.scoped(|n| {
                let mut v = Vec::new();
                n.stmt(&b.body, &mut v)?;
                Ok(v)
            })?;
            ends.push((self.counts(), leaves(&body)));
            bodies.push(body);
        }
        self.set_counts(&before);
        let other = match otherwise {
            Some(o) => self.scoped(|n| {
                let mut v = Vec::new();
                n.stmt(o, &mut v)?;
                Ok(v)
            })?,
            None => Vec::new(),
        };
        ends.push((self.counts(), leaves(&other)));
        bodies.push(other);
        let split = self.worth_splitting(&ends, &before, rest);
        if split {
            self.note_split();
            for (i, body) in bodies.iter_mut().enumerate() {
                if ends[i].1 {
                    continue;
                }
                self.set_counts(&ends[i].0);
                self.scoped(|n| n.stmts_into(rest, body))?;
                ends[i] = (self.counts(), leaves(body));
            }
        }
        {
            let mut arms: Vec<(&mut Vec<IrStmt>, Vec<Count>, bool)> =
                bodies.iter_mut().zip(ends).map(|(b, (c, l))| (b, c, l)).collect();
            self.join(&mut arms, &before);
        }
        let otherwise = bodies.pop().unwrap_or_default();
        out.push(IrStmt::If { branches: conds.into_iter().zip(bodies).collect(), otherwise });
        Ok(split)
    }

    /// A loop's body, with the arrays it pushes to prepared
    /// ([`aggregates`]): `passes` bounds how often it runs.
    fn loop_body(
        &mut self,
        body: &Stmt,
        passes: Option<usize>,
        at: postc_ir::Span,
        out: &mut Vec<IrStmt>,
    ) -> R<Vec<IrStmt>> {
        let after = self.enter_loop(&[body], passes, at, out)?;
        let r = self.scoped(|n| {
            let mut b = Vec::new();
            n.stmt(body, &mut b)?;
            Ok(b)
        });
        self.leave_loop(after);
        r
    }

    fn stmt(&mut self, s: &Stmt, out: &mut Vec<IrStmt>) -> R<()> {
        if self.setup.done.contains(&s.span.start) {
            return Ok(());
        }
        match &s.kind {
            StmtKind::Var(ds) => {
                for d in ds {
                    if let (Symbol::Local { func, slot }, Some(init)) =
                        (self.model.scopes.resolve(&d.name.name, self.at), &d.init)
                        && func == self.at
                        && self.agg_candidate(slot)
                    {
                        self.reshaped = true;
                        self.agg_declare(slot, init, out)?;
                        continue;
                    }
                    if let Some(slot) = self.array_slot(&d.name.name) {
                        if let Some(init) = &d.init {
                            self.array_assign(slot, init, out)?;
                        }
                        continue;
                    }
                    if let Some(init) = &d.init {
                        let target = Expr::new(ExprKind::Ident(d.name.name.clone()), d.name.span);
                        out.push(IrStmt::Assign(self.place(&target)?, self.expr(init)?));
                    }
                }
            }
            StmtKind::Expr(e) => {
                if self.agg_stmt(e, out)? {
                    self.reshaped = true;
                } else {
                    out.push(self.expr_stmt(e)?)
                }
            }
            StmtKind::Block(b) => self.scoped(|n| n.stmts_into(b, out))?,
            StmtKind::Empty => {}
            StmtKind::If { branches, otherwise } => {
                self.lower_if(branches, otherwise.as_deref(), &[], out)?;
            }
            StmtKind::While { cond, body } => {
                let b = self.loop_body(body, None, s.span, out)?;
                out.push(IrStmt::While { cond: self.expr(cond)?, body: b, span: Some(s.span), step: vec![] });
            }
            StmtKind::DoWhile { body, cond } => {
                if has_continue(body) {
                    return Err(why(s.span, "`continue` in a `do ... while` loop"));
                }
                let mut b = self.loop_body(body, None, s.span, out)?;
                let c = self.expr(cond)?;
                b.push(IrStmt::If {
                    branches: vec![(Ir::Unary(IrUn::Not, Box::new(c)), vec![IrStmt::Break])],
                    otherwise: vec![],
                });
                out.push(IrStmt::While { cond: Ir::Bool(true), body: b, span: Some(s.span), step: vec![] });
            }
            StmtKind::For { init, test, update, body } => {
                if let Some((slot, from, to)) = self.unrollable(init, test, update, body) {
                    return self.unroll(slot, from, to, body, out);
                }
                if has_continue(body) {
                    return Err(why(s.span, "`continue` in a `for` loop"));
                }
                match init {
                    Some(ForInit::Var(ds)) => {
                        let v = Stmt::new(StmtKind::Var(ds.clone()), s.span);
                        self.stmt(&v, out)?;
                    }
                    Some(ForInit::Expr(e)) => out.push(self.expr_stmt(e)?),
                    None => {}
                }
                let passes = self.passes(init, test, update, body);
                let mut b = self.loop_body(body, passes, s.span, out)?;
                if let Some(u) = update {
                    b.push(self.expr_stmt(u)?);
                }
                let cond = match test {
                    Some(t) => self.expr(t)?,
                    None => Ir::Bool(true),
                };
                out.push(IrStmt::While { cond, body: b, span: Some(s.span), step: vec![] });
            }
            StmtKind::Switch { discriminant, cases } => {
                let before = self.counts();
                let mut simple = Vec::new();
                let slots = self.slots;
                match self.switch(discriminant, cases, &mut simple) {
                    Ok(()) => out.extend(simple),
                    Err(w) if w.what.contains("falls through") || w.what.contains("`default` is not the last") => {
                        self.slots = slots;
                        self.set_counts(&before);
                        self.switch_fallthrough(discriminant, cases, s.span, out)?
                    }
                    Err(w) => return Err(w),
                }
                if self.counts()[..before.len()] != before[..] {
                    return Err(why(s.span, "adds to an array inside a `switch`"));
                }
            }
            StmtKind::ForIn { declared: _, name, object, body } => {
                let before = self.counts();
                self.for_in(name, object, body, s.span, out)?;
                if breaks_switch(body) && self.counts()[..before.len()] != before[..] {
                    return Err(why(s.span, "adds to an array in a `for ... in` loop that may `break`"));
                }
            }
            StmtKind::Break => out.push(IrStmt::Break),
            StmtKind::Continue => out.push(IrStmt::Continue),
            StmtKind::Return(Some(e)) if self.aggs.returns => {
                self.reshaped = true;
                self.agg_return(e, out)?
            }
            StmtKind::Return(e) => {
                if self.entry {
                    out.push(IrStmt::Origin(s.span));
                }
                // `return;` gives `undefined`, as falling off the end does.
                out.push(IrStmt::Return(Some(match e {
                    Some(e) => self.expr(e)?,
                    None => Ir::Undefined,
                })))
            }
            other => return Err(why(s.span, stmt_name(other))),
        }
        Ok(())
    }

    /// A `switch` whose cases each end in `break` or `return` (or are
    /// empty and share the next case's body), with `default` last.
    fn switch(&mut self, disc: &Expr, cases: &[SwitchCase], out: &mut Vec<IrStmt>) -> R<()> {
        let t = self.temp();
        out.push(IrStmt::Assign(Place::Local(t), self.expr(disc)?));
        let mut branches = Vec::new();
        let mut otherwise = Vec::new();
        let mut tests: Vec<Ir> = Vec::new();
        for (i, c) in cases.iter().enumerate() {
            let last = i + 1 == cases.len();
            match &c.test {
                Some(test) => {
                    let v = self.expr(test)?;
                    tests.push(Ir::Binary(IrBin::StrictEq, Box::new(Ir::Local(t)), Box::new(v)));
                }
                None if !last => return Err(why(disc.span, "a `switch` whose `default` is not the last case")),
                None => {}
            }
            if c.body.is_empty() && !last {
                continue;
            }
            let mut body = c.body.as_slice();
            let ends = matches!(body.last().map(|s| &s.kind), Some(StmtKind::Break));
            if ends {
                body = &body[..body.len() - 1];
            } else if !last && !matches!(body.last().map(|s| &s.kind), Some(StmtKind::Return(_))) {
                return Err(why(disc.span, "a `switch` case that falls through to the next"));
            }
            if body.iter().any(breaks_switch) {
                return Err(why(disc.span, "a `break` out of a `switch` from inside an `if` or block"));
            }
            let lowered = self.stmts(body)?;
            if c.test.is_none() {
                if !tests.is_empty() {
                    // `case x: default:` share a body with the default.
                    tests.clear();
                }
                otherwise = lowered;
            } else {
                let cond = tests
                    .drain(..)
                    .reduce(|a, b| Ir::Binary(IrBin::Or, Box::new(a), Box::new(b)))
                    .ok_or_else(|| why(disc.span, "a `switch` case without a test"))?;
                branches.push((cond, lowered));
            }
        }
        if !branches.is_empty() || !otherwise.is_empty() {
            out.push(IrStmt::If { branches, otherwise });
        }
        Ok(())
    }

    fn temp(&mut self) -> LocalId {
        self.slots += 1;
        LocalId::new(self.slots - 1)
    }

    /// An expression evaluated for its effect.
    fn expr_stmt(&mut self, e: &Expr) -> R<IrStmt> {
        if let Some(s) = self.array_stmt(e)? {
            return Ok(s);
        }
        match &e.kind {
            ExprKind::Assign { op, target, value } => {
                let place = self.place(target)?;
                let v = self.expr(value)?;
                let v = match op.binary() {
                    None => v,
                    Some(b) => binary_op(b, self.expr(target)?, v),
                };
                Ok(IrStmt::Assign(place, v))
            }
            ExprKind::Update { op, target, .. } => {
                let place = self.place(target)?;
                let cur = Ir::Unary(IrUn::Plus, Box::new(self.expr(target)?));
                let op = if *op == UpdateOp::Increment { IrBin::Add } else { IrBin::Sub };
                Ok(IrStmt::Assign(place, Ir::Binary(op, Box::new(cur), Box::new(Ir::Number(1.0)))))
            }
            ExprKind::Call { callee, args } if args.is_empty() => match self.reset_of(callee) {
                Some(var) => Ok(IrStmt::Forget(var)),
                None => Ok(IrStmt::Eval(self.expr(e)?)),
            },
            _ => Ok(IrStmt::Eval(self.expr(e)?)),
        }
    }

    /// Where an assignment stores.
    fn place(&mut self, target: &Expr) -> R<Place> {
        let at = target.span;
        let name = match &target.kind {
            ExprKind::Ident(n) => match self.model.scopes.resolve(n, self.at) {
                Symbol::Local { func, slot } if func == self.at && self.local_plain(slot) => {
                    return Ok(Place::Local(self.local(slot)));
                }
                Symbol::Global(g) => g,
                Symbol::Local { .. } => {
                    return Err(why(
                        at,
                        format!("assigns `{n}`, a local that holds an object, an array or a function"),
                    ));
                }
                _ => return Err(why(at, format!("assigns `{n}`, which is not a local or a global of the post"))),
            },
            _ => self
                .model
                .flattened_name(target)
                .ok_or_else(|| why(at, "assigns a property of an object or an array element"))?,
        };
        let g =
            self.model.global(&name).ok_or_else(|| why(at, format!("assigns `{name}`, which is never declared")))?;
        if !g.plain {
            return Err(why(at, format!("assigns global `{name}`, which may hold an object, an array or a function")));
        }
        if self.setup.bindings.contains_key(&name) {
            return Err(why(at, format!("assigns `{name}`, an output variable or format")));
        }
        self.layout
            .global_index
            .get(&name)
            .map(|g| Place::Global(*g))
            .ok_or_else(|| why(at, format!("assigns `{name}`")))
    }

    fn local_plain(&self, slot: usize) -> bool {
        // A specialization is called from native code only, which passes
        // numbers, text, booleans and nothing.
        // Its other locals hold what native code assigns them: an
        // assignment of anything else has no native form itself.
        if self.arity.is_some() {
            return !self.arrays.contains_key(&slot) && !self.aggs_bound(slot);
        }
        self.aggs.plain.contains(&slot)
            || self.model.local_plain.get(self.at).and_then(|l| l.get(slot)).copied().unwrap_or(false)
    }

    /// The value of a global by name, as native code reads it.
    fn global_value(&mut self, name: &str, at: postc_ir::Span) -> R<Ir> {
        match self.model.global(name) {
            Some(g) => {
                if let Some(c) = &g.constant {
                    return Ok(layout::const_expr(c));
                }
                if !g.plain {
                    return Err(why(
                        at,
                        format!("reads global `{name}`, which may hold an object, an array or a function"),
                    ));
                }
                if self.setup.bindings.contains_key(name) {
                    return Err(why(at, format!("uses output variable or format `{name}` as a value")));
                }
                self.layout
                    .global_index
                    .get(name)
                    .map(|g| Ir::Global(*g))
                    .ok_or_else(|| why(at, format!("reads `{name}`")))
            }
            None => match builtins::constant(name) {
                Some(Const::Num(n)) => Ok(Ir::Number(n)),
                Some(c) => Ok(layout::const_expr(&c)),
                None => Err(why(at, format!("reads `{name}`, which postc's host gives no native value"))),
            },
        }
    }

    pub fn expr(&mut self, e: &Expr) -> R<Ir> {
        Ok(match &e.kind {
            ExprKind::Number(n) => Ir::Number(*n),
            ExprKind::String(s) => Ir::Text(s.clone()),
            ExprKind::Bool(b) => Ir::Bool(*b),
            ExprKind::Null => Ir::Null,
            ExprKind::Undefined => Ir::Undefined,
            ExprKind::Ident(name) if name == "arguments" && self.model.scopes.funcs[self.at].uses_arguments => {
                return Err(why(
                    e.span,
                    "uses `arguments` other than as `arguments.length`, `arguments[i]` or `f.apply(null, arguments)`",
                ));
            }
            ExprKind::Ident(name) if self.array_slot(name).is_some() => {
                return Err(why(e.span, format!("uses array `{name}` other than by `push`, `length` and `join`")));
            }
            ExprKind::Ident(name) if self.is_bound(name) => {
                return Err(why(
                    e.span,
                    format!(
                        "uses `{name}`, an object or array postc keeps in slots, as a value (passes, compares or returns it)"
                    ),
                ));
            }
            ExprKind::Index { .. } | ExprKind::Member { .. } if self.agg_root(e) => {
                if let Some(a) = self.agg_read(e)? {
                    self.reshaped = true;
                    return self.plain_of(a, e.span);
                }
                match &e.kind {
                    ExprKind::Index { object, index } => return self.index(object, index, e.span, Ir::Undefined),
                    _ => return self.member(e),
                }
            }
            ExprKind::Index { object, index } => return self.index(object, index, e.span, Ir::Undefined),
            ExprKind::Ident(name) => match self.model.scopes.resolve(name, self.at) {
                Symbol::Local { func, slot } if func == self.at && self.unrolled.contains_key(&slot) => {
                    Ir::Number(self.unrolled[&slot])
                }
                Symbol::Local { func, slot } if func == self.at && self.local_plain(slot) => {
                    Ir::Local(self.local(slot))
                }
                Symbol::Global(g) => self.global_value(&g, e.span)?,
                Symbol::Local { .. } => {
                    return Err(why(
                        e.span,
                        format!("reads `{name}`, a local that holds an object, an array or a function"),
                    ));
                }
                _ => return Err(why(e.span, format!("reads `{name}`, a variable of the function around it"))),
            },
            ExprKind::Member { .. } => return self.member(e),
            ExprKind::Call { callee, args } => return self.call(callee, args),
            ExprKind::Unary { op, operand } => {
                if *op == UnaryOp::Typeof
                    && let ExprKind::Ident(n) = &operand.kind
                    && matches!(self.model.scopes.resolve(n, self.at), Symbol::Global(_))
                    && self.model.global(n).is_none()
                    && builtins::constant(n).is_none()
                {
                    return Ok(Ir::Text(if builtins::knows(n) { "function" } else { "undefined" }.into()));
                }
                let a = Box::new(self.expr(operand)?);
                match op {
                    UnaryOp::Neg => Ir::Unary(IrUn::Neg, Box::new(to_number(*a))),
                    UnaryOp::Plus => Ir::Unary(IrUn::Plus, a),
                    UnaryOp::Not => Ir::Unary(IrUn::Not, a),
                    UnaryOp::BitNot => Ir::Unary(IrUn::BitNot, a),
                    UnaryOp::Typeof => Ir::Unary(IrUn::Typeof, a),
                }
            }
            // A table's missing entry joins to text as "undefined".
            ExprKind::Binary { op: BinaryOp::Add, left, right } => {
                binary_js(IrBin::Add, self.expr_in_text(left, right)?, self.expr_in_text(right, left)?)
            }
            ExprKind::Binary { op, left, right } => binary_op(*op, self.expr(left)?, self.expr(right)?),
            ExprKind::Logical { op, left, right } => {
                let op = if *op == LogicalOp::And { IrBin::And } else { IrBin::Or };
                Ir::Binary(op, Box::new(self.expr(left)?), Box::new(self.expr(right)?))
            }
            ExprKind::Conditional { test, consequent, alternate } => Ir::Choose(
                Box::new(self.expr(test)?),
                Box::new(self.expr(consequent)?),
                Box::new(self.expr(alternate)?),
            ),
            other => return Err(why(e.span, expr_name(other))),
        })
    }
}

impl Native<'_, '_> {
    /// `object.property` outside objects and arrays kept in slots.
    fn member(&mut self, e: &Expr) -> R<Ir> {
        let ExprKind::Member { object, property } = &e.kind else { return Err(why(e.span, "reads a property")) };
        if let Some(flat) = self.model.flattened_name(e) {
            return self.global_value(&flat, e.span);
        }
        if let ExprKind::Ident(o) = &object.kind
            && o == "Math"
            && self.is_host("Math")
        {
            return builtins::math_constant(&property.name)
                .map(Ir::Number)
                .ok_or_else(|| why(e.span, format!("`Math.{}`", property.name)));
        }
        if let Some(v) = self.member_special(object, &property.name, e.span, Ir::Undefined)? {
            return Ok(v);
        }
        if property.name == "length" {
            return Ok(Ir::Builtin(Builtin::Len, vec![self.expr(object)?]));
        }
        Err(why(e.span, format!("reads property `.{}` of an object", property.name)))
    }

    fn aggs_bound(&self, slot: usize) -> bool {
        let name = &self.model.scopes.funcs[self.at].locals[slot];
        self.is_bound(name)
    }
}

/// How many `return` statements a body has (not counting nested functions).
fn count_returns(body: &[Stmt]) -> usize {
    struct C(usize);
    impl<'a> super::scope::Visit<'a> for C {
        fn expr(&mut self, _e: &'a Expr) -> bool {
            false
        }
        fn stmt(&mut self, s: &'a Stmt) -> bool {
            if matches!(s.kind, StmtKind::Return(_)) {
                self.0 += 1;
            }
            true
        }
        fn function_decl(&mut self, _f: &'a Function) {}
    }
    let mut c = C(0);
    super::scope::walk_stmts(body, &mut c);
    c.0
}

/// Whether lowered statements never reach their end: they return, break or
/// continue (on every path through a last `if`).
fn leaves(body: &[IrStmt]) -> bool {
    match body.last() {
        Some(IrStmt::Return(_) | IrStmt::Break | IrStmt::Continue) => true,
        Some(IrStmt::If { branches, otherwise }) => {
            !otherwise.is_empty() && leaves(otherwise) && branches.iter().all(|(_, b)| leaves(b))
        }
        _ => false,
    }
}

/// A value as a number, unless it surely is one.
pub fn to_number(v: Ir) -> Ir {
    match v {
        Ir::Number(_) | Ir::Quantity(_) => v,
        Ir::Binary(IrBin::Sub | IrBin::Mul | IrBin::Div | IrBin::Rem | IrBin::Pow, ..) => v,
        Ir::Unary(IrUn::Neg | IrUn::Plus, _) => v,
        other => Ir::Unary(IrUn::Plus, Box::new(other)),
    }
}

/// A JavaScript binary operator over IR operands: arithmetic reads its
/// operands as JavaScript numbers (`UnaryOp::Plus`: text that is not a
/// number is NaN, not 0 as in BASIC).
pub fn binary_js(op: IrBin, a: Ir, b: Ir) -> Ir {
    match op {
        IrBin::Sub | IrBin::Mul | IrBin::Div | IrBin::Rem => {
            Ir::Binary(op, Box::new(to_number(a)), Box::new(to_number(b)))
        }
        _ => Ir::Binary(op, Box::new(a), Box::new(b)),
    }
}

/// A JavaScript binary operator applied to two operands: an IR operator,
/// or for `in` the built-in that asks an object for a property.
pub fn binary_op(op: BinaryOp, a: Ir, b: Ir) -> Ir {
    match bin(op) {
        Some(op) => binary_js(op, a, b),
        // The caller gives `instanceof` the constructor's `prototype` as `b`.
        None if op == BinaryOp::Instanceof => Ir::Builtin(postc_ir::Builtin::InstanceOf, vec![a, b]),
        None => Ir::Builtin(postc_ir::Builtin::HasProperty, vec![a, b]),
    }
}

/// The IR operator of a JavaScript binary operator (`in` and `instanceof`
/// have none).
fn bin(op: BinaryOp) -> Option<IrBin> {
    Some(match op {
        BinaryOp::Add => IrBin::Add,
        BinaryOp::Sub => IrBin::Sub,
        BinaryOp::Mul => IrBin::Mul,
        BinaryOp::Div => IrBin::Div,
        BinaryOp::Rem => IrBin::Rem,
        BinaryOp::Shl => IrBin::Shl,
        BinaryOp::Shr => IrBin::Shr,
        BinaryOp::UShr => IrBin::UShr,
        BinaryOp::BitAnd => IrBin::BitAnd,
        BinaryOp::BitOr => IrBin::BitOr,
        BinaryOp::BitXor => IrBin::BitXor,
        BinaryOp::Eq => IrBin::JsEq,
        BinaryOp::Ne => IrBin::JsNe,
        BinaryOp::StrictEq => IrBin::StrictEq,
        BinaryOp::StrictNe => IrBin::StrictNe,
        BinaryOp::Lt => IrBin::JsLt,
        BinaryOp::Le => IrBin::JsLe,
        BinaryOp::Gt => IrBin::JsGt,
        BinaryOp::Ge => IrBin::JsGe,
        BinaryOp::In | BinaryOp::Instanceof => return None,
    })
}

/// Whether a loop body has a `continue` for this loop (not a nested one).
fn has_continue(s: &Stmt) -> bool {
    match &s.kind {
        StmtKind::Continue => true,
        StmtKind::Block(b) => b.iter().any(has_continue),
        StmtKind::If { branches, otherwise } => {
            branches.iter().any(|b| has_continue(&b.body)) || otherwise.as_ref().is_some_and(|o| has_continue(o))
        }
        StmtKind::Switch { cases, .. } => cases.iter().any(|c| c.body.iter().any(has_continue)),
        StmtKind::Try { .. } => true,
        _ => false,
    }
}

/// Whether a statement has a `break` that leaves an enclosing `switch`.
fn breaks_switch(s: &Stmt) -> bool {
    match &s.kind {
        StmtKind::Break => true,
        StmtKind::Block(b) => b.iter().any(breaks_switch),
        StmtKind::If { branches, otherwise } => {
            branches.iter().any(|b| breaks_switch(&b.body)) || otherwise.as_ref().is_some_and(|o| breaks_switch(o))
        }
        StmtKind::Switch { .. }
        | StmtKind::While { .. }
        | StmtKind::DoWhile { .. }
        | StmtKind::For { .. }
        | StmtKind::ForIn { .. } => false,
        StmtKind::Try { .. } => true,
        _ => false,
    }
}
