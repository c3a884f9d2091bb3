//! Look-up tables: globals set once, at the top of the post, to an object
//! literal of constants (`var coolantCodes = {off: "M09", flood: "M08"}`),
//! and only ever read as `table[key]`, `table.key` or `for (k in table)`.
//! Native code reads them at compile time or through a chain of key
//! comparisons (`native::tables`); nothing can change them, since nothing
//! else ever sees the object.

use std::collections::HashMap;

use crate::ast::*;

use super::super::consts::Const;
use super::super::scope::{Symbol, Visit, walk_expr, walk_stmt, walk_stmts};
use super::Model;

/// Keys a native lookup does not handle: values that are not text turn
/// into these keys (`table[true]`, `table[undefined]`), and `__proto__`
/// sets the prototype instead.
const AWKWARD_KEYS: &[&str] = &["true", "false", "null", "undefined", "NaN", "Infinity", "-Infinity", "__proto__"];

/// The tables of a program: each one's entries, keys unique (the last
/// value of a repeated key), in the order of the literal.
pub fn find(model: &Model, program: &Program) -> HashMap<String, Vec<(String, Const)>> {
    let mut candidates = HashMap::new();
    for g in &model.globals {
        if g.assignments != 1 || !g.declared || g.name.contains('.') {
            continue;
        }
        let Some(init) = g.init else { continue };
        let ExprKind::Object(props) = &init.kind else { continue };
        let mut entries: Vec<(String, Const)> = Vec::new();
        let mut ok = true;
        for p in props {
            let Some(v) = literal(&p.value) else {
                ok = false;
                break;
            };
            if AWKWARD_KEYS.contains(&p.key.name.as_str()) {
                ok = false;
                break;
            }
            match entries.iter_mut().find(|(k, _)| *k == p.key.name) {
                Some(e) => e.1 = v,
                None => entries.push((p.key.name.clone(), v)),
            }
        }
        if ok {
            candidates.insert(g.name.clone(), entries);
        }
    }
    if candidates.is_empty() {
        return candidates;
    }
    let mut u = Uses { model, at: 0, candidates: &mut candidates };
    walk_stmts(&program.body, &mut u);
    for id in 1..model.scopes.funcs.len() {
        if let Some(f) = model.scopes.funcs[id].func {
            u.at = id;
            walk_stmts(&f.body, &mut u);
        }
    }
    candidates
}

/// A constant written as a literal.
fn literal(e: &Expr) -> Option<Const> {
    Some(match &e.kind {
        ExprKind::Number(n) => Const::Num(*n),
        ExprKind::String(s) => Const::Str(s.clone()),
        ExprKind::Bool(b) => Const::Bool(*b),
        ExprKind::Null => Const::Null,
        ExprKind::Undefined => Const::Undefined,
        ExprKind::Unary { op: UnaryOp::Neg, operand } => match operand.kind {
            ExprKind::Number(n) => Const::Num(-n),
            _ => return None,
        },
        _ => return None,
    })
}

/// Drops every candidate used other than by reading an entry.
struct Uses<'m, 'a, 'c> {
    model: &'m Model<'a>,
    at: usize,
    candidates: &'c mut HashMap<String, Vec<(String, Const)>>,
}

impl Uses<'_, '_, '_> {
    /// The candidate an expression names.
    fn table(&self, e: &Expr) -> Option<String> {
        let ExprKind::Ident(n) = &e.kind else { return None };
        match self.model.scopes.resolve(n, self.at) {
            Symbol::Global(g) if self.candidates.contains_key(&g) => Some(g),
            _ => None,
        }
    }

    /// A target of an assignment or update: a table's entry is changed.
    fn drop_target(&mut self, target: &Expr) {
        if let ExprKind::Member { object, .. } | ExprKind::Index { object, .. } = &target.kind
            && let Some(t) = self.table(object)
        {
            self.candidates.remove(&t);
        }
    }
}

impl<'a> Visit<'a> for Uses<'_, 'a, '_> {
    fn stmt(&mut self, s: &'a Stmt) -> bool {
        if let StmtKind::ForIn { object, body, .. } = &s.kind
            && self.table(object).is_some()
        {
            walk_stmt(body, self);
            return false;
        }
        true
    }

    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } => self.drop_target(target),
            ExprKind::Member { object, .. } if self.table(object).is_some() => return false,
            ExprKind::Index { object, index } if self.table(object).is_some() => {
                walk_expr(index, self);
                return false;
            }
            ExprKind::Call { callee, .. } => {
                // A method of the table (`hasOwnProperty`, ...).
                if let ExprKind::Member { object, .. } = &callee.kind
                    && let Some(t) = self.table(object)
                {
                    self.candidates.remove(&t);
                }
            }
            ExprKind::Ident(_) => {
                if let Some(t) = self.table(e) {
                    self.candidates.remove(&t);
                }
            }
            _ => {}
        }
        true
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}
