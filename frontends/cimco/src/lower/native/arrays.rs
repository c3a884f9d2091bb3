//! Array locals that are only filled, measured and joined: the words of a
//! block gathered with `push` and joined with blanks.
//!
//! Such an array never exists: its local holds the text `join(sep)` would
//! give (each element as `join` prints it, `undefined` and `null` as
//! nothing, the separator between elements) and a second slot counts the
//! elements. `var words = [a, b]` sets both, `words.push(c, d)` appends the
//! separator (when the array is not empty) and each element and counts
//! them, `words.unshift(a)` puts the element and a separator in front,
//! `words.length` is the count and `words.join(sep)` the text. A local
//! qualifies when it is declared at the top of its function with an array
//! literal before any other use, every use is one of these (a `push` or
//! `unshift` as a statement of its own), and every `join` has the same
//! constant separator.

use postc_ir::{BinaryOp as IrBin, Expr as Ir, LocalId, Place, Stmt as IrStmt};

use crate::ast::*;

use super::super::scope::{Symbol, Visit, walk_expr, walk_stmts};
use super::{Native, R, why};

/// An array local kept as its joined text.
pub(super) struct ArrayLocal {
    /// The slot of the element count.
    count: LocalId,
    /// The separator of its `join`s (`","` when it has none).
    sep: String,
}

impl Native<'_, '_> {
    /// The slot of a name that is an array local of this function.
    pub(super) fn array_slot(&self, name: &str) -> Option<usize> {
        match self.model.scopes.resolve(name, self.at) {
            Symbol::Local { func, slot } if func == self.at && self.arrays.contains_key(&slot) => Some(slot),
            _ => None,
        }
    }

    /// Finds the array locals of a function body.
    pub(super) fn find_arrays(&mut self, body: &[Stmt]) -> R<()> {
        let info = &self.model.scopes.funcs[self.at];
        let names: Vec<(usize, String)> =
            (info.params.len()..info.locals.len()).map(|s| (s, info.locals[s].clone())).collect();
        for (slot, name) in names {
            let Some(pos) = body.iter().position(|s| declares_array(s, &name)) else { continue };
            let mut before = Uses { name: &name, ok: true, sep: None, mentioned: false };
            walk_stmts(&body[..pos], &mut before);
            if before.mentioned {
                continue;
            }
            let mut uses = Uses { name: &name, ok: true, sep: None, mentioned: false };
            walk_stmts(body, &mut uses);
            if !uses.ok {
                continue;
            }
            let count = self.temp();
            self.arrays.insert(slot, ArrayLocal { count, sep: uses.sep.unwrap_or_else(|| ",".into()) });
        }
        Ok(())
    }

    /// `words = [a, b]`: the text of the elements and their count.
    pub(super) fn array_assign(&mut self, slot: usize, value: &Expr, out: &mut Vec<IrStmt>) -> R<()> {
        let ExprKind::Array(items) = &value.kind else {
            return Err(why(value.span, "assigns an array local something other than an array literal"));
        };
        let sep = self.arrays[&slot].sep.clone();
        let count = self.arrays[&slot].count;
        let mut text = Ir::Text(String::new());
        for (i, item) in items.iter().enumerate() {
            if i > 0 && !sep.is_empty() {
                text = Ir::Binary(IrBin::Add, Box::new(text), Box::new(Ir::Text(sep.clone())));
            }
            let item = self.join_element(item, out)?;
            text = Ir::Binary(IrBin::Add, Box::new(text), Box::new(item));
        }
        out.push(IrStmt::Assign(Place::Local(self.local(slot)), text));
        out.push(IrStmt::Assign(Place::Local(count), Ir::Number(items.len() as f64)));
        Ok(())
    }

    /// `words.push(a, b)` and `words = [...]` as statements.
    pub(super) fn array_stmt(&mut self, e: &Expr) -> R<Option<IrStmt>> {
        let mut out = Vec::new();
        match &e.kind {
            ExprKind::Assign { op: AssignOp::Assign, target, value } => {
                let ExprKind::Ident(name) = &target.kind else { return Ok(None) };
                let Some(slot) = self.array_slot(name) else { return Ok(None) };
                self.array_assign(slot, value, &mut out)?;
            }
            ExprKind::Call { callee, args } => {
                let ExprKind::Member { object, property } = &callee.kind else { return Ok(None) };
                let ExprKind::Ident(name) = &object.kind else { return Ok(None) };
                let Some(slot) = self.array_slot(name) else { return Ok(None) };
                let (count, sep) = (self.arrays[&slot].count, self.arrays[&slot].sep.clone());
                let w = self.local(slot);
                let more = || {
                    let more = Ir::Binary(IrBin::JsGt, Box::new(Ir::Local(count)), Box::new(Ir::Number(0.0)));
                    Ir::Choose(Box::new(more), Box::new(Ir::Text(sep.clone())), Box::new(Ir::Text("".into())))
                };
                match property.name.as_str() {
                    "push" => {}
                    "unshift" if !args.is_empty() => {
                        // The new elements, joined, go in front.
                        let mut front = Ir::Text(String::new());
                        for (i, a) in args.iter().enumerate() {
                            if i > 0 && !sep.is_empty() {
                                front = Ir::Binary(IrBin::Add, Box::new(front), Box::new(Ir::Text(sep.clone())));
                            }
                            let a = self.join_element(a, &mut out)?;
                            front = Ir::Binary(IrBin::Add, Box::new(front), Box::new(a));
                        }
                        if !sep.is_empty() {
                            front = Ir::Binary(IrBin::Add, Box::new(front), Box::new(more()));
                        }
                        let text = Ir::Binary(IrBin::Add, Box::new(front), Box::new(Ir::Local(w)));
                        out.push(IrStmt::Assign(Place::Local(w), text));
                        out.push(IrStmt::Assign(
                            Place::Local(count),
                            Ir::Binary(IrBin::Add, Box::new(Ir::Local(count)), Box::new(Ir::Number(args.len() as f64))),
                        ));
                        return Ok(Some(IrStmt::If { branches: vec![(Ir::Bool(true), out)], otherwise: vec![] }));
                    }
                    _ => return Ok(None),
                }
                for a in args {
                    let v = self.join_element(a, &mut out)?;
                    let mut text = Ir::Local(w);
                    if !sep.is_empty() {
                        text = Ir::Binary(IrBin::Add, Box::new(text), Box::new(more()));
                    }
                    out.push(IrStmt::Assign(Place::Local(w), Ir::Binary(IrBin::Add, Box::new(text), Box::new(v))));
                    out.push(IrStmt::Assign(
                        Place::Local(count),
                        Ir::Binary(IrBin::Add, Box::new(Ir::Local(count)), Box::new(Ir::Number(1.0))),
                    ));
                }
            }
            _ => return Ok(None),
        }
        Ok(Some(IrStmt::If { branches: vec![(Ir::Bool(true), out)], otherwise: vec![] }))
    }

    /// `words.join(sep)` (the separator is the array's, checked when it was
    /// found) and `words.length`.
    pub(super) fn array_method(&mut self, slot: usize, name: &str, method: &str, at: postc_ir::Span) -> R<Ir> {
        match method {
            "join" => Ok(Ir::Local(self.local(slot))),
            _ => Err(why(at, format!("calls `.{method}()` of array `{name}`, which has no native form"))),
        }
    }

    /// `words.length`.
    pub(super) fn array_length(&self, slot: usize) -> Ir {
        Ir::Local(self.arrays[&slot].count)
    }
}

/// An element as `join` prints it: `undefined` and `null` as nothing,
/// anything else as `+` joins it to text. `v` is read twice unless it is
/// surely neither: it must be [`super::tables::repeatable`].
pub(super) fn join_part(v: Ir) -> Ir {
    match v {
        Ir::Null | Ir::Undefined => Ir::Text(String::new()),
        v if never_absent(&v) => v,
        v => {
            let absent = Ir::Binary(IrBin::JsEq, Box::new(v.clone()), Box::new(Ir::Null));
            Ir::Choose(Box::new(absent), Box::new(Ir::Text(String::new())), Box::new(v))
        }
    }
}

/// Surely neither `undefined` nor `null`: a constant, a format's text, a
/// number an operator or `Number()` makes.
fn never_absent(v: &Ir) -> bool {
    match v {
        Ir::Number(_) | Ir::Text(_) | Ir::Bool(_) | Ir::Quantity(_) => true,
        Ir::FormatVar { .. } | Ir::Format { .. } | Ir::Unary(..) => true,
        Ir::Binary(op, ..) => !matches!(op, IrBin::And | IrBin::Or),
        Ir::Choose(_, a, b) => never_absent(a) && never_absent(b),
        _ => false,
    }
}

/// An element of a push or an array literal as `join` prints it, kept in
/// a slot first when it is read twice and has effects.
impl Native<'_, '_> {
    fn join_element(&mut self, e: &Expr, out: &mut Vec<IrStmt>) -> R<Ir> {
        let v = self.expr(e)?;
        if never_absent(&v) || super::tables::repeatable(&v) {
            return Ok(join_part(v));
        }
        let t = self.temp();
        out.push(IrStmt::Assign(Place::Local(t), v));
        Ok(join_part(Ir::Local(t)))
    }
}

/// `var name = [...]` at the top of a body.
fn declares_array(s: &Stmt, name: &str) -> bool {
    matches!(&s.kind, StmtKind::Var(ds)
        if ds.iter().any(|d| d.name.name == name && matches!(d.init.as_ref().map(|i| &i.kind), Some(ExprKind::Array(_)))))
}

/// Checks every use of an array local.
struct Uses<'n> {
    name: &'n str,
    ok: bool,
    sep: Option<String>,
    /// Any mention at all.
    mentioned: bool,
}

impl Uses<'_> {
    fn is_name(&self, e: &Expr) -> bool {
        matches!(&e.kind, ExprKind::Ident(n) if n == self.name)
    }
}

impl<'a> Visit<'a> for Uses<'_> {
    fn stmt(&mut self, s: &'a Stmt) -> bool {
        match &s.kind {
            StmtKind::Var(ds) => {
                for d in ds {
                    match &d.init {
                        Some(init) if d.name.name == self.name => {
                            self.mentioned = true;
                            match &init.kind {
                                ExprKind::Array(items) => items.iter().for_each(|i| walk_expr(i, self)),
                                _ => self.ok = false,
                            }
                        }
                        Some(init) => walk_expr(init, self),
                        None => {}
                    }
                }
                false
            }
            StmtKind::Expr(e) => match &e.kind {
                ExprKind::Assign { op: AssignOp::Assign, target, value } if self.is_name(target) => {
                    self.mentioned = true;
                    match &value.kind {
                        ExprKind::Array(items) => items.iter().for_each(|i| walk_expr(i, self)),
                        _ => self.ok = false,
                    }
                    false
                }
                ExprKind::Call { callee, args } => match &callee.kind {
                    ExprKind::Member { object, property }
                        if (property.name == "push" || property.name == "unshift") && self.is_name(object) =>
                    {
                        self.mentioned = true;
                        args.iter().for_each(|a| walk_expr(a, self));
                        false
                    }
                    _ => true,
                },
                _ => true,
            },
            StmtKind::ForIn { name, .. } if name.name == self.name => {
                self.ok = false;
                true
            }
            _ => true,
        }
    }

    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Member { object, property } if property.name == "length" && self.is_name(object) => {
                self.mentioned = true;
                false
            }
            ExprKind::Call { callee, args } => match &callee.kind {
                ExprKind::Member { object, property } if property.name == "join" && self.is_name(object) => {
                    self.mentioned = true;
                    let sep = match args.as_slice() {
                        [] => ",".to_string(),
                        [Expr { kind: ExprKind::String(s), .. }] => s.clone(),
                        _ => {
                            self.ok = false;
                            return false;
                        }
                    };
                    if self.sep.get_or_insert_with(|| sep.clone()) != &sep {
                        self.ok = false;
                    }
                    false
                }
                _ => true,
            },
            ExprKind::Ident(n) if n == self.name => {
                self.mentioned = true;
                self.ok = false;
                true
            }
            ExprKind::Function(_) => false,
            _ => true,
        }
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}
