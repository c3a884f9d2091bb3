//! Assignments, compound assignments and `++`/`--` in Rhai: locals are
//! Rhai variables, globals go through `__gs`, properties through `__set`
//! with the object evaluated once.

use crate::ast::*;
use crate::host_names as names;

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
                        self.w(&format!("{GLOBAL_SET}({i}, ", GLOBAL_SET = names::GLOBAL_SET));
                        self.combined(op, &format!("{GLOBAL_GET}({i})", GLOBAL_GET = names::GLOBAL_GET), value);
                        self.w(")");
                    }
                    Target::None => {
                        self.w(&format!("{ASSIGN_ERROR}({})", quote(name), ASSIGN_ERROR = names::ASSIGN_ERROR));
                    }
                }
            }
            ExprKind::Member { .. } if self.model.flattened_name(target).is_some() => {
                let flat = self.model.flattened_name(target).unwrap_or_default();
                match self.layout.global_index.get(&flat) {
                    Some(&i) => {
                        self.w(&format!("{GLOBAL_SET}({i}, ", GLOBAL_SET = names::GLOBAL_SET));
                        self.combined(op, &format!("{GLOBAL_GET}({i})", GLOBAL_GET = names::GLOBAL_GET), value);
                        self.w(")");
                    }
                    None => self.w("()"),
                }
            }
            ExprKind::Member { object, property } => {
                let o = self.temp("o");
                self.w(&format!("{{ let {o} = "));
                self.expr(object);
                self.w(&format!("; {SET}({o}, {}, ", quote(&property.name), SET = names::SET));
                self.combined(op, &format!("{GET}({o}, {})", quote(&property.name), GET = names::GET), value);
                self.w(") }");
            }
            ExprKind::Index { object, index } => {
                let (o, k) = (self.temp("o"), self.temp("k"));
                self.w(&format!("{{ let {o} = "));
                self.expr(object);
                self.w(&format!("; let {k} = "));
                self.expr(index);
                self.w(&format!("; {SET}({o}, {k}, ", SET = names::SET));
                self.combined(op, &format!("{GET}({o}, {k})", GET = names::GET), value);
                self.w(") }");
            }
            _ => self.w(&format!("{}(\"?\")", names::ASSIGN_ERROR)),
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
                    Target::Global(i) => (
                        format!("{GLOBAL_GET}({i})", GLOBAL_GET = names::GLOBAL_GET),
                        format!("{GLOBAL_SET}({i}, {new})", GLOBAL_SET = names::GLOBAL_SET),
                    ),
                    Target::None => {
                        return self.w(&format!("{ASSIGN_ERROR}({})", quote(name), ASSIGN_ERROR = names::ASSIGN_ERROR));
                    }
                };
                let result = if prefix { format!("{u} + {delta}") } else { u.clone() };
                self.w(&format!("{{ let {u} = {POS}({read}); {store}; {result} }}", POS = names::POS));
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
                self.w(&format!(
                    "; let {u} = {POS}({GET}({o}, {k})); {SET}({o}, {k}, {u} + {delta}); {result} }}",
                    POS = names::POS,
                    GET = names::GET,
                    SET = names::SET
                ));
            }
            _ => self.w(&format!("{}(\"?\")", names::ASSIGN_ERROR)),
        }
    }
}
