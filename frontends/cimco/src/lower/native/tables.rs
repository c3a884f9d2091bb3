//! Reading look-up tables (`arcCodes[isCW ? 1 : 0]`, `coolantCodes[kind]`,
//! `cycleCodes.drill`) and `arguments[i]` in native code.
//!
//! A property key is text in JavaScript: `arcCodes[1]` and `arcCodes["1"]`
//! read the same entry. A key known at compile time reads its entry
//! there; `c ? a : b` reads both entries and chooses; any other key is
//! compared with each entry's key in turn, with `===` against the key's
//! text and, for keys that are numbers as JavaScript prints them ("1",
//! "2.5"), against the number. A missing entry is `undefined`: native
//! `null`, which is false to `||` and `!`, and which joins to text as
//! "undefined" when the lookup itself is a part of a `+` with text.

use postc_ir::{BinaryOp as IrBin, Expr as Ir, Stmt as IrStmt, UnaryOp as IrUn};

use crate::ast::*;

use super::super::layout;
use super::super::model::tables::{Entry, Table};
use super::super::scope::Symbol;
use super::{Native, R, breaks_switch, has_continue, why};

impl Native<'_, '_> {
    /// The table a name is.
    pub(super) fn table_info(&self, name: &str) -> Option<&Table> {
        let Symbol::Global(g) = self.model.scopes.resolve(name, self.at) else { return None };
        self.model.tables.get(&g)
    }

    /// The entries of the table a name is, as IR values; `None` also for
    /// a table of records (its entries are objects).
    pub(super) fn table(&self, name: &str) -> Option<Vec<(String, Ir)>> {
        let t = self.table_info(name)?;
        t.entries
            .iter()
            .map(|(k, e)| match e {
                Entry::Const(c) => Some((k.clone(), layout::const_expr(c))),
                Entry::Record(_) => None,
            })
            .collect()
    }

    /// `object[index]`: a table's entry, or an argument of a specialization.
    pub(super) fn index(&mut self, object: &Expr, index: &Expr, at: postc_ir::Span, missing: Ir) -> R<Ir> {
        if let ExprKind::Ident(o) = &object.kind {
            if o == "arguments" && self.model.scopes.funcs[self.at].uses_arguments {
                let n = self.arity.unwrap_or(0);
                let entries: Vec<(String, Ir)> = (0..n).map(|k| (k.to_string(), Ir::Local(self.arg_slot(k)))).collect();
                let i = self.expr(index)?;
                return lookup(i, &entries, &missing)
                    .ok_or_else(|| why(at, "indexes `arguments` with an expression that has effects"));
            }
            if let Some(entries) = self.table(o) {
                self.reshaped = true;
                let i = self.expr(index)?;
                return lookup(i, &entries, &missing)
                    .ok_or_else(|| why(at, format!("indexes table `{o}` with an expression that has effects")));
            }
            if self.table_info(o).is_some() {
                return Err(why(at, format!("uses an entry of table `{o}`, an object, as a value")));
            }
            if self.array_slot(o).is_some() {
                return Err(why(at, format!("indexes array `{o}`, which postc keeps as joined text")));
            }
        }
        Err(why(at, "indexing (`a[i]`)"))
    }

    /// `arguments.length`, `words.length` and `table.key`; `None` for any
    /// other property.
    pub(super) fn member_special(
        &mut self,
        object: &Expr,
        property: &str,
        at: postc_ir::Span,
        missing: Ir,
    ) -> R<Option<Ir>> {
        let ExprKind::Ident(o) = &object.kind else { return Ok(None) };
        if o == "arguments" && self.model.scopes.funcs[self.at].uses_arguments {
            return match (property, self.arity) {
                ("length", Some(n)) => Ok(Some(Ir::Number(n as f64))),
                _ => Err(why(at, format!("reads `arguments.{property}`"))),
            };
        }
        if let Some(slot) = self.array_slot(o) {
            return match property {
                "length" => Ok(Some(self.array_length(slot))),
                _ => Err(why(at, format!("reads `.{property}` of array `{o}`"))),
            };
        }
        if let Some(t) = self.table_info(o)
            && let (Some(n), "length") = (t.array, property)
        {
            self.reshaped = true;
            return Ok(Some(Ir::Number(n as f64)));
        }
        if let Some(entries) = self.table(o) {
            self.reshaped = true;
            return Ok(Some(entries.into_iter().find(|(k, _)| k == property).map_or(missing, |(_, v)| v)));
        }
        if self.table_info(o).is_some() {
            return Err(why(at, format!("uses an entry of table `{o}`, an object, as a value")));
        }
        Ok(None)
    }

    /// An operand of `+`: a table's missing entry reads as the text
    /// "undefined" when the other operand is surely text.
    pub(super) fn expr_in_text(&mut self, e: &Expr, other: &Expr) -> R<Ir> {
        let missing = if surely_text(other) { Ir::Text("undefined".into()) } else { Ir::Undefined };
        if self.agg_root(e) {
            if let Some(a) = self.agg_read_in_text(e, missing)? {
                return self.plain_of(a, e.span);
            }
            return self.expr(e);
        }
        match &e.kind {
            ExprKind::Index { object, index } => self.index(object, index, e.span, missing),
            ExprKind::Member { object, property } => {
                match self.member_special(object, &property.name, e.span, missing)? {
                    Some(v) => Ok(v),
                    None => self.expr(e),
                }
            }
            _ => self.expr(e),
        }
    }

    /// `for (k in table)`: the body once per key, in JavaScript's order
    /// (keys that are array indices ascending, then the others as
    /// written), with `k` the key's text. A `break` leaves; `continue` has
    /// no native form here.
    pub(super) fn for_in(
        &mut self,
        name: &Ident,
        object: &Expr,
        body: &Stmt,
        at: postc_ir::Span,
        out: &mut Vec<IrStmt>,
    ) -> R<()> {
        let table = match &object.kind {
            ExprKind::Ident(o) => {
                self.table_info(o).map(|t| t.entries.iter().map(|(k, _)| (k.clone(), ())).collect::<Vec<_>>())
            }
            _ => None,
        };
        let Some(entries) = table else { return Err(why(at, "a `for ... in` loop over something other than a table")) };
        if has_continue(body) {
            return Err(why(at, "`continue` in a `for ... in` loop"));
        }
        let mut keys: Vec<&String> = entries.iter().map(|(k, _)| k).collect();
        let index = |k: &str| k.parse::<u32>().ok().filter(|n| n.to_string() == k && *n != u32::MAX);
        keys.sort_by_key(|k| index(k).map_or((1, 0), |n| (0, n)));
        let target = Expr::new(ExprKind::Ident(name.name.clone()), name.span);
        let place = self.place(&target)?;
        let mut b = Vec::new();
        for k in keys {
            b.push(IrStmt::Assign(place, Ir::Text(k.clone())));
            self.stmt(body, &mut b)?;
        }
        if breaks_switch(body) {
            b.push(IrStmt::Break);
            out.push(IrStmt::While { cond: Ir::Bool(true), body: b, span: Some(at), step: vec![] });
        } else {
            out.extend(b);
        }
        Ok(())
    }
}

/// The entry of `entries` key `i` reads; `None` when `i` would be
/// evaluated more than once and has effects.
pub(super) fn lookup(i: Ir, entries: &[(String, Ir)], missing: &Ir) -> Option<Ir> {
    let i = super::super::fold::expr(i);
    if let Some(key) = const_key(&i) {
        return Some(entries.iter().find(|(k, _)| *k == key).map_or_else(|| missing.clone(), |(_, v)| v.clone()));
    }
    if let Ir::Choose(c, a, b) = i {
        let a = lookup(*a, entries, missing)?;
        let b = lookup(*b, entries, missing)?;
        return Some(Ir::Choose(c, Box::new(a), Box::new(b)));
    }
    if entries.len() > 1 && !repeatable(&i) {
        return None;
    }
    let number = surely_number(&i);
    let mut acc = missing.clone();
    for (k, v) in entries.iter().rev() {
        let eq = |b: Ir| Ir::Binary(IrBin::StrictEq, Box::new(i.clone()), Box::new(b));
        let test = match numeric_key(k) {
            Some(n) if number => eq(Ir::Number(n)),
            Some(n) => Ir::Binary(IrBin::Or, Box::new(eq(Ir::Number(n))), Box::new(eq(Ir::Text(k.clone())))),
            None => eq(Ir::Text(k.clone())),
        };
        acc = Ir::Choose(Box::new(test), Box::new(v.clone()), Box::new(acc));
    }
    Some(acc)
}

/// The property key a constant names (JavaScript's `ToString`).
pub(super) fn const_key(i: &Ir) -> Option<String> {
    Some(match i {
        Ir::Number(n) => postc_ir::js::number_to_string(*n),
        Ir::Text(s) => s.clone(),
        Ir::Bool(b) => b.to_string(),
        Ir::Null => "null".into(),
        Ir::Undefined => "undefined".into(),
        _ => return None,
    })
}

/// A key that is a number as JavaScript prints it ("1", "2.5", "-3").
fn numeric_key(k: &str) -> Option<f64> {
    let n: f64 = k.parse().ok()?;
    (n.is_finite() && postc_ir::js::number_to_string(n) == k).then_some(n)
}

/// Cheap and free of effects: may be evaluated once per entry.
pub(super) fn repeatable(e: &Ir) -> bool {
    match e {
        Ir::Number(_)
        | Ir::Text(_)
        | Ir::Bool(_)
        | Ir::Null
        | Ir::Undefined
        | Ir::Local(_)
        | Ir::Global(_)
        | Ir::Quantity(_) => true,
        Ir::Var(_) | Ir::Previous(_) => true,
        Ir::Unary(_, a) => repeatable(a),
        Ir::Binary(_, a, b) => repeatable(a) && repeatable(b),
        Ir::Choose(c, a, b) => repeatable(c) && repeatable(a) && repeatable(b),
        _ => false,
    }
}

/// Surely a number.
fn surely_number(e: &Ir) -> bool {
    match e {
        Ir::Number(_) => true,
        Ir::Unary(IrUn::Neg | IrUn::Plus, _) => true,
        Ir::Binary(IrBin::Sub | IrBin::Mul | IrBin::Div | IrBin::Rem | IrBin::Pow, ..) => true,
        Ir::Choose(_, a, b) => surely_number(a) && surely_number(b),
        _ => false,
    }
}

/// Surely text, as written: a string literal or a `+` with one.
fn surely_text(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::String(_) => true,
        ExprKind::Binary { op: BinaryOp::Add, left, right } => surely_text(left) || surely_text(right),
        _ => false,
    }
}
