//! Plain-ness inference: which globals, locals and function results can
//! only hold numbers, text, booleans or nothing, found by iterating to a
//! fixed point over every assignment, return and call argument.

use crate::ast::*;

use super::super::builtins;
use super::super::scope::{FnId, Symbol, Visit, walk_expr, walk_stmts};
use super::{FLATTENED, Model, object_literal_assignment};

impl<'a> Model<'a> {
    pub(super) fn infer_plain(&mut self, program: &'a Program) {
        loop {
            let mut changed = false;
            let mut inf = Infer { model: self, changes: Vec::new() };
            inf.run(program);
            let changes = inf.changes;
            for c in changes {
                changed |= self.apply(c);
            }
            if !changed {
                break;
            }
        }
    }

    fn apply(&mut self, c: Change) -> bool {
        let slot = match c {
            Change::Global(name) => {
                let Some(&i) = self.global_index.get(&name) else { return false };
                &mut self.globals[i].plain
            }
            Change::Local(f, s) => match self.local_plain.get_mut(f).and_then(|l| l.get_mut(s)) {
                Some(p) => p,
                None => return false,
            },
            Change::Return(f) => &mut self.returns_plain[f],
            Change::FnValue(i) => return self.fn_as_value.insert(i),
        };
        let was = *slot;
        *slot = false;
        was
    }

    /// The look-up table ([`super::tables`]) an expression names.
    fn table_named(&self, e: &Expr, at: FnId) -> Option<&super::tables::Table> {
        let ExprKind::Ident(n) = &e.kind else { return None };
        match self.scopes.resolve(n, at) {
            Symbol::Global(g) => self.tables.get(&g),
            _ => None,
        }
    }

    /// Whether an expression reads a record of a table (`quadrants[i]`).
    fn is_record(&self, e: &Expr, at: FnId) -> bool {
        match &e.kind {
            ExprKind::Index { object, .. } => self.table_named(object, at).is_some_and(|t| t.has_records()),
            ExprKind::Member { object, property } => {
                property.name != "length" && self.table_named(object, at).is_some_and(|t| t.has_records())
            }
            _ => false,
        }
    }

    /// Whether an expression can only be a number, text, boolean or nothing.
    pub fn plain(&self, e: &Expr, at: FnId) -> bool {
        match &e.kind {
            ExprKind::Number(_) | ExprKind::String(_) | ExprKind::Bool(_) | ExprKind::Null | ExprKind::Undefined => {
                true
            }
            ExprKind::Unary { .. } | ExprKind::Binary { .. } | ExprKind::Update { .. } => true,
            ExprKind::Logical { left, right, .. } => self.plain(left, at) && self.plain(right, at),
            ExprKind::Conditional { consequent, alternate, .. } => {
                self.plain(consequent, at) && self.plain(alternate, at)
            }
            ExprKind::Assign { op, value, .. } => *op != AssignOp::Assign || self.plain(value, at),
            ExprKind::Sequence(items) => items.last().is_none_or(|l| self.plain(l, at)),
            ExprKind::Ident(name) => match self.scopes.resolve(name, at) {
                Symbol::Local { func, slot } => {
                    self.local_plain.get(func).and_then(|l| l.get(slot)).copied().unwrap_or(false)
                }
                Symbol::TopFn(_) => false,
                Symbol::Global(name) => match self.global(&name) {
                    Some(g) => g.plain,
                    None => builtins::constant(&name).is_some() || !builtins::is_object(&name),
                },
            },
            // A look-up table's entries are constants, and so are the
            // fields of its records.
            ExprKind::Member { object, .. } if self.is_record(object, at) => true,
            ExprKind::Index { object, .. } | ExprKind::Member { object, .. }
                if self.table_named(object, at).is_some() =>
            {
                !self.is_record(e, at)
            }
            ExprKind::Member { object, property } => {
                if let Some(flat) = self.flattened_name(e) {
                    return self.global(&flat).is_none_or(|g| g.plain);
                }
                property.name == "length" || matches!(&object.kind, ExprKind::Ident(n) if n == "Math")
            }
            ExprKind::Call { callee, .. } => match &callee.kind {
                // `f.apply(null, args)` returns what `f` returns.
                ExprKind::Member { object, property }
                    if property.name == "apply"
                        && matches!(&object.kind, ExprKind::Ident(n) if matches!(self.scopes.resolve(n, at), Symbol::TopFn(_))) =>
                {
                    match &object.kind {
                        ExprKind::Ident(n) => match self.scopes.resolve(n, at) {
                            Symbol::TopFn(i) => self.returns_plain[self.scopes.top_fns[i]],
                            _ => false,
                        },
                        _ => false,
                    }
                }
                ExprKind::Member { object, property } => {
                    matches!(&object.kind, ExprKind::Ident(n) if n == "Math") || builtins::plain_method(&property.name)
                }
                ExprKind::Ident(name) => match self.scopes.resolve(name, at) {
                    Symbol::TopFn(i) => self.returns_plain[self.scopes.top_fns[i]],
                    Symbol::Global(n) if !self.global_index.contains_key(&n) => builtins::plain_function(&n),
                    _ => false,
                },
                _ => false,
            },
            _ => false,
        }
    }
}

/// A fact learnt in one pass of the inference.
enum Change {
    Global(String),
    Local(FnId, usize),
    Return(FnId),
    FnValue(usize),
}

struct Infer<'m, 'a> {
    model: &'m Model<'a>,
    changes: Vec<Change>,
}

impl<'a> Infer<'_, 'a> {
    fn run(&mut self, program: &'a Program) {
        for s in &program.body {
            // The flattened literals are plain when each value is.
            for &name in FLATTENED {
                if self.model.flattened.contains(name)
                    && let Some(props) = object_literal_assignment(s, name)
                {
                    for p in props {
                        if !self.model.plain(&p.value, 0) {
                            self.changes.push(Change::Global(format!("{name}.{}", p.key.name)));
                        }
                    }
                }
            }
        }
        let mut v = InferBody { inf: self, at: 0 };
        walk_stmts(&program.body, &mut v);
        for id in 1..self.model.scopes.funcs.len() {
            let info = &self.model.scopes.funcs[id];
            let Some(func) = info.func else { continue };
            // Parameters of functions that are not top-level (closures,
            // methods) or whose function is used as a value can be anything.
            let top = self.model.scopes.top_fns.iter().position(|&t| t == id);
            let dynamic = top.is_none_or(|i| self.model.fn_as_value.contains(&i));
            let entry_object = info.name.as_deref().is_some_and(builtins::entry_takes_object);
            if dynamic || entry_object || info.uses_arguments {
                for s in 0..info.params.len() {
                    self.changes.push(Change::Local(id, s));
                }
            }
            let mut v = InferBody { inf: self, at: id };
            walk_stmts(&func.body, &mut v);
        }
    }
}

struct InferBody<'i, 'm, 'a> {
    inf: &'i mut Infer<'m, 'a>,
    at: FnId,
}

impl InferBody<'_, '_, '_> {
    fn assign_to(&mut self, target: &Expr, plain: bool) {
        if plain {
            return;
        }
        let model = self.inf.model;
        match &target.kind {
            ExprKind::Ident(name) => match model.scopes.resolve(name, self.at) {
                Symbol::Local { func, slot } => self.inf.changes.push(Change::Local(func, slot)),
                Symbol::Global(n) => self.inf.changes.push(Change::Global(n)),
                Symbol::TopFn(_) => {}
            },
            _ => {
                if let Some(flat) = model.flattened_name(target) {
                    self.inf.changes.push(Change::Global(flat));
                }
            }
        }
    }
}

impl<'a> Visit<'a> for InferBody<'_, '_, 'a> {
    fn stmt(&mut self, s: &'a Stmt) -> bool {
        let model = self.inf.model;
        match &s.kind {
            StmtKind::Var(ds) => {
                for d in ds {
                    if let Some(init) = &d.init {
                        let ident = Expr::new(ExprKind::Ident(d.name.name.clone()), d.name.span);
                        let plain = model.plain(init, self.at);
                        self.assign_to(&ident, plain);
                    }
                }
            }
            StmtKind::Return(Some(e)) if !model.plain(e, self.at) => {
                self.inf.changes.push(Change::Return(self.at));
            }
            StmtKind::Try { handler: Some(h), .. } => {
                let ident = Expr::new(ExprKind::Ident(h.param.name.clone()), h.param.span);
                self.assign_to(&ident, false);
            }
            _ => {}
        }
        true
    }

    fn expr(&mut self, e: &'a Expr) -> bool {
        let model = self.inf.model;
        match &e.kind {
            ExprKind::Assign { op: AssignOp::Assign, target, value } => {
                let plain = model.plain(value, self.at);
                self.assign_to(target, plain);
            }
            ExprKind::Ident(name) => {
                if let Symbol::TopFn(i) = model.scopes.resolve(name, self.at) {
                    self.inf.changes.push(Change::FnValue(i));
                }
            }
            ExprKind::Call { callee, args } => {
                if let ExprKind::Ident(name) = &callee.kind
                    && let Symbol::TopFn(i) = model.scopes.resolve(name, self.at)
                {
                    let id = model.scopes.top_fns[i];
                    for (k, a) in args.iter().enumerate() {
                        if k < model.scopes.funcs[id].params.len() && !model.plain(a, self.at) {
                            self.inf.changes.push(Change::Local(id, k));
                        }
                    }
                    for a in args {
                        walk_expr(a, self);
                    }
                    return false;
                }
            }
            ExprKind::Function(_) => return false,
            _ => {}
        }
        true
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}
