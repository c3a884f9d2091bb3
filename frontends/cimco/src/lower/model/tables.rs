//! Look-up tables: globals set once, at the top of the post, to an object
//! literal of constants (`var coolantCodes = {off: "M09", flood: "M08"}`)
//! or an array literal of them (`var compensationCodes = ["G40", "G41",
//! "G42"]`), and only ever read as `table[key]`, `table.key`, `for (k in
//! table)`, an array's `.length`, or handed whole to `f.apply(null,
//! table)`. An entry may itself be an object literal of constants (a
//! record: `var quadrants = [{c: 1, s: 0}, ...]`), read as
//! `table[key].field` or through a local (`var q = table[key]; q.c`).
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

/// A look-up table.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// The entries, keys unique (the last value of a repeated key), in
    /// the order of the literal; an array's keys are its indices.
    pub entries: Vec<(String, Entry)>,
    /// An array literal: its length.
    pub array: Option<usize>,
}

/// The value of a table's entry.
#[derive(Clone, Debug, PartialEq)]
pub enum Entry {
    Const(Const),
    /// An object literal of constants, keys unique, in order.
    Record(Vec<(String, Const)>),
}

impl Table {
    /// Whether some entry is a record (the table's entries are then
    /// objects, not values).
    pub fn has_records(&self) -> bool {
        self.entries.iter().any(|(_, e)| matches!(e, Entry::Record(_)))
    }
}

/// The tables of a program.
pub fn find(model: &Model, program: &Program) -> HashMap<String, Table> {
    let mut candidates = HashMap::new();
    for g in &model.globals {
        if g.assignments != 1 || !g.declared || g.name.contains('.') {
            continue;
        }
        let Some(init) = g.init else { continue };
        let table = match &init.kind {
            ExprKind::Object(props) => object_entries(props).map(|entries| Table { entries, array: None }),
            ExprKind::Array(items) => items
                .iter()
                .enumerate()
                .map(|(i, item)| entry(item).map(|e| (i.to_string(), e)))
                .collect::<Option<Vec<_>>>()
                .map(|entries| Table { entries, array: Some(items.len()) }),
            _ => None,
        };
        // Entries all values or all records: a table that mixes them is
        // read as neither.
        if let Some(t) = table
            && (!t.has_records() || t.entries.iter().all(|(_, e)| matches!(e, Entry::Record(_))))
        {
            candidates.insert(g.name.clone(), t);
        }
    }
    if candidates.is_empty() {
        return candidates;
    }
    let mut u = Uses { model, at: 0, candidates: &mut candidates, aliases: Vec::new() };
    walk_stmts(&program.body, &mut u);
    for id in 1..model.scopes.funcs.len() {
        if let Some(f) = model.scopes.funcs[id].func {
            u.at = id;
            walk_stmts(&f.body, &mut u);
        }
    }
    let aliases = std::mem::take(&mut u.aliases);
    if !aliases.is_empty() {
        let mut a = AliasUses { model, at: 0, aliases: &aliases, dropped: Vec::new() };
        for id in 1..model.scopes.funcs.len() {
            if let Some(f) = model.scopes.funcs[id].func {
                a.at = id;
                walk_stmts(&f.body, &mut a);
            }
        }
        for t in a.dropped {
            candidates.remove(&t);
        }
    }
    candidates
}

/// The entries of an object literal of constants, or `None`.
fn object_entries(props: &[Property]) -> Option<Vec<(String, Entry)>> {
    let mut entries: Vec<(String, Entry)> = Vec::new();
    for p in props {
        let v = entry(&p.value)?;
        if AWKWARD_KEYS.contains(&p.key.name.as_str()) {
            return None;
        }
        match entries.iter_mut().find(|(k, _)| *k == p.key.name) {
            Some(e) => e.1 = v,
            None => entries.push((p.key.name.clone(), v)),
        }
    }
    Some(entries)
}

/// An entry: a literal constant, or an object literal of them.
fn entry(e: &Expr) -> Option<Entry> {
    match &e.kind {
        ExprKind::Object(props) => {
            let fields = object_entries(props)?
                .into_iter()
                .map(|(k, v)| match v {
                    Entry::Const(c) => Some((k, c)),
                    Entry::Record(_) => None,
                })
                .collect::<Option<Vec<_>>>()?;
            Some(Entry::Record(fields))
        }
        _ => literal(e).map(Entry::Const),
    }
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

/// Drops every candidate used other than by reading an entry. A record
/// (an entry that is an object) may only be read by `.field`, or kept in
/// a local that is itself only read by `.field` (`aliases`): nothing may
/// change it.
struct Uses<'m, 'a, 'c> {
    model: &'m Model<'a>,
    at: usize,
    candidates: &'c mut HashMap<String, Table>,
    /// Locals (function, slot) that hold a record of a table, and the table.
    aliases: Vec<(usize, usize, String)>,
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

    /// The table of records an expression reads an entry of (`t[i]`, `t.k`).
    fn record_of(&self, e: &Expr) -> Option<String> {
        let object = match &e.kind {
            ExprKind::Index { object, .. } => object,
            ExprKind::Member { object, property } if property.name != "length" => object,
            _ => return None,
        };
        self.table(object).filter(|t| self.candidates.get(t).is_some_and(Table::has_records))
    }

    /// A target of an assignment or update: a table's entry (or a
    /// record's field) is changed.
    fn drop_target(&mut self, target: &Expr) {
        let mut at = target;
        while let ExprKind::Member { object, .. } | ExprKind::Index { object, .. } = &at.kind {
            if let Some(t) = self.table(object) {
                self.candidates.remove(&t);
            }
            at = object;
        }
    }
}

impl<'a> Uses<'_, 'a, '_> {
    /// `q = t[i]` into a local: the local holds a record of `t`.
    fn alias(&mut self, name: &str, value: &'a Expr) -> bool {
        let Some(t) = self.record_of(value) else { return false };
        match self.model.scopes.resolve(name, self.at) {
            Symbol::Local { func, slot } if func == self.at => {
                self.aliases.push((func, slot, t));
                if let ExprKind::Index { index, .. } = &value.kind {
                    walk_expr(index, self);
                }
                true
            }
            _ => {
                self.candidates.remove(&t);
                false
            }
        }
    }
}

impl<'a> Visit<'a> for Uses<'_, 'a, '_> {
    fn stmt(&mut self, s: &'a Stmt) -> bool {
        match &s.kind {
            StmtKind::ForIn { object, body, .. } if self.table(object).is_some() => {
                walk_stmt(body, self);
                false
            }
            StmtKind::Var(ds) => {
                for d in ds {
                    if let Some(init) = &d.init
                        && !self.alias(&d.name.name, init)
                    {
                        walk_expr(init, self);
                    }
                }
                false
            }
            _ => true,
        }
    }

    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Assign { op: AssignOp::Assign, target, value } if matches!(&target.kind, ExprKind::Ident(n) if self.alias(n, value)) =>
            {
                return false;
            }
            ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } => self.drop_target(target),
            // A record's field.
            ExprKind::Member { object, .. } if self.record_of(object).is_some() => {
                if let ExprKind::Index { index, .. } = &object.kind {
                    walk_expr(index, self);
                }
                return false;
            }
            // A record anywhere else may be changed or kept.
            ExprKind::Member { .. } | ExprKind::Index { .. } if self.record_of(e).is_some() => {
                if let Some(t) = self.record_of(e) {
                    self.candidates.remove(&t);
                }
            }
            ExprKind::Member { object, .. } if self.table(object).is_some() => return false,
            ExprKind::Index { object, index } if self.table(object).is_some() => {
                walk_expr(index, self);
                return false;
            }
            ExprKind::Call { callee, args } => {
                // `f.apply(null, table)` of an array table reads its entries.
                if let ExprKind::Member { property, .. } = &callee.kind
                    && property.name == "apply"
                    && let [this, list] = args.as_slice()
                    && let Some(t) = self.table(list)
                    && self.candidates.get(&t).is_some_and(|t| t.array.is_some() && !t.has_records())
                {
                    walk_expr(callee, self);
                    walk_expr(this, self);
                    return false;
                }
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

/// Drops the tables whose records are kept in a local that is used other
/// than by reading `.field` (changed, passed on, returned, compared).
struct AliasUses<'m, 'a, 'c> {
    model: &'m Model<'a>,
    at: usize,
    aliases: &'c [(usize, usize, String)],
    dropped: Vec<String>,
}

impl AliasUses<'_, '_, '_> {
    fn alias(&self, e: &Expr) -> Option<&String> {
        let ExprKind::Ident(n) = &e.kind else { return None };
        match self.model.scopes.resolve(n, self.at) {
            Symbol::Local { func, slot } => {
                self.aliases.iter().find(|(f, s, _)| *f == func && *s == slot).map(|(_, _, t)| t)
            }
            _ => None,
        }
    }
}

impl<'a> Visit<'a> for AliasUses<'_, 'a, '_> {
    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            // The local itself assigned: it holds something else now.
            ExprKind::Assign { op: AssignOp::Assign, target, value } if self.alias(target).is_some() => {
                walk_expr(value, self);
                false
            }
            ExprKind::Assign { target, value, .. } => {
                let mut at = &**target;
                while let ExprKind::Member { object, .. } | ExprKind::Index { object, .. } = &at.kind {
                    at = object;
                }
                if let Some(t) = self.alias(at) {
                    self.dropped.push(t.clone());
                }
                walk_expr(value, self);
                false
            }
            ExprKind::Member { object, .. } if self.alias(object).is_some() => false,
            ExprKind::Ident(_) => {
                if let Some(t) = self.alias(e) {
                    self.dropped.push(t.clone());
                }
                true
            }
            _ => true,
        }
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}
