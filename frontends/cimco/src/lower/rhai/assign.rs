//! Assignments, compound assignments and `++`/`--` in Rhai: locals are
//! Rhai variables, globals go through `__gs`, properties through `__set`
//! with the object evaluated once.

use crate::ast::*;

use super::expr::{Target, binary_fn};
use super::{Gen, quote};

impl Gen<'_, '_> {
    /// `target op= value` as an expression whose value is the new value.
    pub(super) fn assign_expr(&mut self, target: &Expr, op: AssignOp, value: &Expr) {
        self.mark(target.span);
        match &target.kind {
            ExprKind::Ident(name) => {
                let t = self.target_of(name);
                match t {
                    Target::Local(v) => {
                        self.w(&format!("{{ {v} = "));
                        self.combined(op, &v, value);
                        self.w(&format!("; {v} }}"));
                    }
                    Target::Global(i) => {
                        self.w(&format!("__gs({i}, "));
                        self.combined(op, &format!("__gg({i})"), value);
                        self.w(")");
                    }
                    Target::None => {
                        self.w(&format!("__assign_error({})", quote(name)));
                    }
                }
            }
            ExprKind::Member { .. } if self.model.flattened_name(target).is_some() => {
                let flat = self.model.flattened_name(target).unwrap_or_default();
                match self.layout.global_index.get(&flat) {
                    Some(&i) => {
                        self.w(&format!("__gs({i}, "));
                        self.combined(op, &format!("__gg({i})"), value);
                        self.w(")");
                    }
                    None => self.w("()"),
                }
            }
            ExprKind::Member { object, property } => {
                let o = self.temp("o");
                self.w(&format!("{{ let {o} = "));
                self.expr(object);
                self.w(&format!("; __set({o}, {}, ", quote(&property.name)));
                self.combined(op, &format!("__get({o}, {})", quote(&property.name)), value);
                self.w(") }");
            }
            ExprKind::Index { object, index } => {
                let (o, k) = (self.temp("o"), self.temp("k"));
                self.w(&format!("{{ let {o} = "));
                self.expr(object);
                self.w(&format!("; let {k} = "));
                self.expr(index);
                self.w(&format!("; __set({o}, {k}, "));
                self.combined(op, &format!("__get({o}, {k})"), value);
                self.w(") }");
            }
            _ => self.w("__assign_error(\"?\")"),
        }
    }

    /// The value stored by `op=`: the value itself, or `current op value`.
    fn combined(&mut self, op: AssignOp, current: &str, value: &Expr) {
        match op.binary() {
            None => self.expr(value),
            Some(b) => {
                self.w(&format!("{}({current}, ", binary_fn(b)));
                self.expr(value);
                self.w(")");
            }
        }
    }

    pub(super) fn update(&mut self, op: UpdateOp, prefix: bool, target: &Expr) {
        let delta = if op == UpdateOp::Increment { "1.0" } else { "-1.0" };
        let u = self.temp("u");
        self.mark(target.span);
        match &target.kind {
            ExprKind::Ident(name) => {
                let new = format!("{u} + {delta}");
                let (read, store) = match self.target_of(name) {
                    Target::Local(v) => (v.clone(), format!("{v} = {new}")),
                    Target::Global(i) => (format!("__gg({i})"), format!("__gs({i}, {new})")),
                    Target::None => return self.w(&format!("__assign_error({})", quote(name))),
                };
                let result = if prefix { format!("{u} + {delta}") } else { u.clone() };
                self.w(&format!("{{ let {u} = __pos({read}); {store}; {result} }}"));
            }
            ExprKind::Member { .. } | ExprKind::Index { .. } => {
                let o = self.temp("o");
                let k = self.temp("k");
                self.w(&format!("{{ let {o} = "));
                match &target.kind {
                    ExprKind::Member { object, property } => {
                        self.expr(object);
                        self.w(&format!("; let {k} = {}", quote(&property.name)));
                    }
                    ExprKind::Index { object, index } => {
                        self.expr(object);
                        self.w(&format!("; let {k} = "));
                        self.expr(index);
                    }
                    _ => {}
                }
                let result = if prefix { format!("{u} + {delta}") } else { u.clone() };
                self.w(&format!("; let {u} = __pos(__get({o}, {k})); __set({o}, {k}, {u} + {delta}); {result} }}"));
            }
            _ => self.w("__assign_error(\"?\")"),
        }
    }
}
