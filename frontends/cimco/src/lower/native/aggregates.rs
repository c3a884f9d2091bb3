//! Arrays and objects that native code keeps in slots: the
//! words of a block gathered in an array and handed to
//! `writeBlock.apply(null, words)`, an array of axis words read by index,
//! the pieces of an arc gathered as objects and returned in an object.
//!
//! Such a value never exists as a whole. An object literal is its
//! properties, each a slot (or a constant); an array is one slot per
//! element (an element that is an object: one slot per property) and its
//! element count. The count is known while the lowering can follow it
//! (`Count::Known`: straight code, `if`s that push the same number of
//! elements, loops that unroll); where it cannot (an `if` that pushes in
//! one branch only, a loop whose number of passes is not known but
//! bounded) a slot counts the elements when the post runs
//! (`Count::Between`: what the lowering knows is a range). A push stores
//! into the slot of the next element (when the count is a range: the
//! slot the count names, tested in turn); `a[i]` reads the element's slot
//! (an index known only when the post runs is compared with each
//! position); `a.length` is the count; `f.apply(null, a)` calls `f`'s
//! form for the number of elements (a range: the count chooses the
//! form).
//!
//! Where the lowering would have to forget a count (an `if` whose
//! branches push different numbers of elements) it lowers the rest of
//! the statements once after each branch instead, so that the count stays
//! known in each copy (at most [`MAX_SPLITS`] times per function).
//!
//! A local qualifies when it is declared with `var` and assigned nowhere
//! else; its value lives from its declaration to the end of the block
//! that declares it. Objects are never changed after they are made (a
//! property assignment has no native form), so reading one element
//! through a local (`var p = pieces[i]`) may copy it. Arrays are shared
//! by reference, as in JavaScript (`{pieces: pieces}` holds the same
//! array). An array holds at most [`MAX_ELEMENTS`] elements; a push in a
//! loop needs a loop whose number of passes the lowering can bound
//! (`for (var i = 0; i < 4; i++)`, `break` allowed).
//!
//! A function that returns an object or array (`return {radius: r,
//! pieces: pieces}`, its one `return` and last statement) hands it back
//! natively in hidden globals (`RetShape`), which the caller copies into
//! its own slots right after the call.

use std::collections::{HashMap, HashSet};

use postc_ir::{BinaryOp as IrBin, Expr as Ir, GlobalId, LocalId, Place, Stmt as IrStmt};

use crate::ast::*;

use super::super::layout::Layout;
use super::super::scope::{FnId, Symbol, Visit, walk_stmts};
use super::tables::{const_key, lookup, repeatable};
use super::{Native, R, why};

/// The name of an array made by a literal, until a local holds it.
const ARRAY_LITERAL: &str = "an array literal";

/// An array kept in slots holds at most this many elements.
pub const MAX_ELEMENTS: usize = 64;

/// A function lowers the statements after an `if` once per branch at
/// most this many times (each time at most doubles them).
pub const MAX_SPLITS: usize = 3;

/// The most statements lowered again after each branch of an `if`.
const MAX_SPLIT_STATEMENTS: usize = 48;

/// A value kept in slots.
#[derive(Clone, Debug)]
pub(super) enum Agg {
    /// A number, text, boolean or nothing: how to read it (a slot, a
    /// constant, or a choice over slots made with an index that no longer
    /// changes).
    Plain(Ir),
    /// An object: its properties.
    Object(Vec<(String, Agg)>),
    /// An array: its index in [`Native::aggs`].
    Array(usize),
}

/// What the lowering knows of an array's element count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Count {
    Known(usize),
    /// Between the two, inclusive; the array's count slot holds it.
    Between(usize, usize),
}

impl Count {
    fn lo(self) -> usize {
        match self {
            Count::Known(n) | Count::Between(n, _) => n,
        }
    }

    fn hi(self) -> usize {
        match self {
            Count::Known(n) | Count::Between(_, n) => n,
        }
    }
}

/// One array kept in slots.
#[derive(Debug)]
pub(super) struct ArrayAgg {
    /// The name it was made under, for reasons.
    name: String,
    /// The slots of each position filled so far.
    elems: Vec<Agg>,
    /// `None` before the first element; then `Some(None)` for elements
    /// that are values, `Some(Some(keys))` for objects of those keys.
    shape: Option<Option<Vec<String>>>,
    count: Count,
    /// The slot counting the elements while the count is a range.
    runtime: Option<LocalId>,
    /// How many loops were open when the array was made.
    depth: usize,
}

/// An object or array a function returns, as the hidden globals that
/// hold it after the call.
#[derive(Clone, Debug)]
pub enum RetShape {
    Plain(GlobalId),
    Object(Vec<(String, RetShape)>),
    Array { elems: Vec<RetShape>, keys: Option<Vec<String>>, count: RetCount },
}

/// The element count of a returned array.
#[derive(Clone, Copy, Debug)]
pub enum RetCount {
    Known(usize),
    /// Between the two; the global holds it.
    Between(usize, usize, GlobalId),
}

/// A top-level function lowered ahead of its turn (a caller needed the
/// shape of the object it returns): its body, slots and returned shape.
pub struct Lowered {
    pub body: Result<Vec<IrStmt>, super::Why>,
    pub slots: u16,
    /// [`Native::reshaped`].
    pub reshaped: bool,
}

/// The aggregate state of one function's lowering.
#[derive(Default)]
pub(super) struct Aggs {
    pub(super) arrays: Vec<ArrayAgg>,
    /// Locals bound to an object or array, by slot, and the order they
    /// were bound in (for scopes).
    bound: HashMap<usize, Agg>,
    order: Vec<usize>,
    /// Locals that may hold an object or array: declared with `var` and
    /// assigned nowhere else.
    candidates: HashSet<usize>,
    /// Such locals whose one value turned out to be plain.
    pub(super) plain: HashSet<usize>,
    /// The arrays each open loop was prepared to push to.
    loops: Vec<HashSet<usize>>,
    splits: usize,
    /// The function returns an object or array through hidden globals.
    pub(super) returns: bool,
    pub(super) ret: Option<RetShape>,
    /// What an element past the end or a missing property reads as: null,
    /// or the text "undefined" as a part of `+` with text.
    missing: Option<Ir>,
}

impl Native<'_, '_> {
    /// Finds the locals that may hold an object or array.
    pub(super) fn find_aggregates(&mut self, body: &[Stmt]) {
        let info = &self.model.scopes.funcs[self.at];
        let plain = self.model.local_plain.get(self.at);
        let mut counts =
            Assignments { model: self.model, at: self.at, counts: HashMap::new(), declared: HashSet::new() };
        walk_stmts(body, &mut counts);
        for slot in info.params.len()..info.locals.len() {
            if self.arrays.contains_key(&slot) || plain.and_then(|p| p.get(slot)).copied().unwrap_or(true) {
                continue;
            }
            if counts.counts.get(&slot) == Some(&1) && counts.declared.contains(&slot) {
                self.aggs.candidates.insert(slot);
            }
        }
    }

    /// Whether a local of the function may hold an object or array.
    pub(super) fn agg_candidate(&self, slot: usize) -> bool {
        self.aggs.candidates.contains(&slot)
    }

    /// `var name = init` of such a local.
    pub(super) fn agg_declare(&mut self, slot: usize, init: &Expr, out: &mut Vec<IrStmt>) -> R<()> {
        match self.agg_expr(init, out)? {
            Agg::Plain(v) => {
                out.push(IrStmt::Assign(Place::Local(self.local(slot)), v));
                self.aggs.plain.insert(slot);
            }
            a => {
                if let Agg::Array(id) = a
                    && self.aggs.arrays[id].name == ARRAY_LITERAL
                {
                    self.aggs.arrays[id].name = self.model.scopes.funcs[self.at].locals[slot].clone();
                }
                self.aggs.bound.insert(slot, a);
                self.aggs.order.push(slot);
            }
        }
        Ok(())
    }

    /// Lowers with a scope: the objects and arrays bound inside are
    /// forgotten after.
    pub(super) fn scoped<T>(&mut self, f: impl FnOnce(&mut Self) -> R<T>) -> R<T> {
        let mark = self.aggs.order.len();
        let r = f(self);
        for slot in self.aggs.order.split_off(mark) {
            self.aggs.bound.remove(&slot);
        }
        r
    }

    /// The object or array a name is bound to here.
    fn bound(&self, name: &str) -> Option<&Agg> {
        match self.model.scopes.resolve(name, self.at) {
            Symbol::Local { func, slot } if func == self.at => self.aggs.bound.get(&slot),
            _ => None,
        }
    }

    /// The array a name is bound to here.
    pub(super) fn agg_array(&self, name: &str) -> Option<usize> {
        match self.bound(name) {
            Some(Agg::Array(id)) => Some(*id),
            _ => None,
        }
    }

    /// Whether a name is bound to an object or array here.
    pub(super) fn is_bound(&self, name: &str) -> bool {
        self.bound(name).is_some()
    }

    fn describe(&self, a: &Agg) -> &'static str {
        match a {
            Agg::Plain(_) => "a value",
            Agg::Object(_) => "an object",
            Agg::Array(_) => "an array",
        }
    }

    /// An aggregate read where a value is needed.
    pub(super) fn plain_of(&self, a: Agg, at: postc_ir::Span) -> R<Ir> {
        match a {
            Agg::Plain(v) => Ok(v),
            other => Err(why(
                at,
                format!(
                    "uses {} that postc keeps in slots as a value (passes, compares or joins it)",
                    self.describe(&other)
                ),
            )),
        }
    }

    /// [`Self::agg_read`] as a part of `+` with text: what is missing
    /// reads as `missing` (the text "undefined", as JavaScript joins it).
    pub(super) fn agg_read_in_text(&mut self, e: &Expr, missing: Ir) -> R<Option<Agg>> {
        let old = self.aggs.missing.replace(missing);
        let r = self.agg_read(e);
        self.aggs.missing = old;
        r
    }

    fn missing(&self) -> Ir {
        self.aggs.missing.clone().unwrap_or(Ir::Undefined)
    }

    /// Reads an element, property or length of an object or array, with
    /// no statement: `None` when `e` reads none.
    pub(super) fn agg_read(&mut self, e: &Expr) -> R<Option<Agg>> {
        match &e.kind {
            ExprKind::Ident(n) => Ok(self.bound(n).cloned()),
            ExprKind::Index { object, index } => {
                if let ExprKind::Ident(o) = &object.kind
                    && self.table_info(o).is_some_and(|t| t.has_records())
                {
                    let i = self.expr(index)?;
                    return self.record(o, i, e.span).map(Some);
                }
                let Some(base) = self.agg_read(object)? else { return Ok(None) };
                let i = super::super::fold::expr(self.expr(index)?);
                self.index_of(base, i, e.span).map(Some)
            }
            ExprKind::Member { object, property } => {
                if let ExprKind::Ident(o) = &object.kind
                    && self.table_info(o).is_some_and(|t| t.has_records())
                    && property.name != "length"
                {
                    return self.record(o, Ir::Text(property.name.clone()), e.span).map(Some);
                }
                let Some(base) = self.agg_read(object)? else { return Ok(None) };
                self.index_of(base, Ir::Text(property.name.clone()), e.span).map(Some)
            }
            _ => Ok(None),
        }
    }

    /// `base[i]` (or `base.name`, `i` the name's text).
    fn index_of(&mut self, base: Agg, i: Ir, at: postc_ir::Span) -> R<Agg> {
        match base {
            Agg::Array(id) => {
                if matches!(&i, Ir::Text(t) if t == "length") {
                    return Ok(Agg::Plain(self.count_expr(id)));
                }
                self.element(id, i, at)
            }
            Agg::Object(fields) => match const_key(&i) {
                Some(k) => {
                    let missing = self.missing();
                    Ok(fields.into_iter().rev().find(|(n, _)| *n == k).map_or(Agg::Plain(missing), |(_, a)| a))
                }
                None => Err(why(at, "reads a property of an object by a name known only when the post runs")),
            },
            Agg::Plain(_) => Err(why(at, "reads an element or property of a value that postc keeps in slots")),
        }
    }

    /// The record of table `t` that key `i` names: an object whose
    /// properties compare the key with each entry's (`quadrants[k].c`).
    fn record(&mut self, t: &str, i: Ir, at: postc_ir::Span) -> R<Agg> {
        let Some(table) = self.table_info(t) else { return Err(why(at, format!("reads table `{t}`"))) };
        let mut keys: Vec<String> = Vec::new();
        for (_, e) in &table.entries {
            if let super::super::model::tables::Entry::Record(fields) = e {
                for (k, _) in fields {
                    if !keys.contains(k) {
                        keys.push(k.clone());
                    }
                }
            }
        }
        let entries = table.entries.clone();
        let i = super::super::fold::expr(i);
        let mut fields = Vec::new();
        for k in keys {
            let column: Vec<(String, Ir)> = entries
                .iter()
                .map(|(key, e)| {
                    let v = match e {
                        super::super::model::tables::Entry::Record(fs) => fs
                            .iter()
                            .find(|(f, _)| *f == k)
                            .map_or(Ir::Undefined, |(_, c)| super::super::layout::const_expr(c)),
                        super::super::model::tables::Entry::Const(_) => Ir::Undefined,
                    };
                    (key.clone(), v)
                })
                .collect();
            let v = lookup(i.clone(), &column, &Ir::Undefined)
                .ok_or_else(|| why(at, format!("reads a record of table `{t}` with a key that has effects")))?;
            fields.push((k, Agg::Plain(v)));
        }
        Ok(Agg::Object(fields))
    }

    /// The count of an array as an expression.
    fn count_expr(&self, id: usize) -> Ir {
        match (self.aggs.arrays[id].count, self.aggs.arrays[id].runtime) {
            (Count::Known(n), _) => Ir::Number(n as f64),
            (Count::Between(..), Some(r)) => Ir::Local(r),
            (Count::Between(lo, _), None) => Ir::Number(lo as f64),
        }
    }

    /// Element `i` of an array: its slots when `i` is known, else a
    /// comparison of `i` with each position; `undefined` past the count.
    fn element(&mut self, id: usize, i: Ir, at: postc_ir::Span) -> R<Agg> {
        let count = self.aggs.arrays[id].count;
        self.fill_to(id, count.hi(), at)?;
        let missing = self.missing();
        let guarded = |s: &Self, k: usize| -> Agg {
            let e = s.aggs.arrays[id].elems[k].clone();
            if k < count.lo() {
                return e;
            }
            let Some(r) = s.aggs.arrays[id].runtime else { return Agg::Plain(missing.clone()) };
            let filled = Ir::Binary(IrBin::JsGt, Box::new(Ir::Local(r)), Box::new(Ir::Number(k as f64)));
            map_plain(e, &|v| Ir::Choose(Box::new(filled.clone()), Box::new(v), Box::new(missing.clone())))
        };
        if let Some(k) = const_key(&i) {
            let Some(k) = array_index(&k) else { return Ok(Agg::Plain(missing)) };
            if k >= count.hi() {
                return Ok(self.undefined_element(id));
            }
            return Ok(guarded(self, k));
        }
        if !repeatable(&i) {
            return Err(why(
                at,
                format!("indexes array `{}` with an expression that has effects", self.aggs.arrays[id].name),
            ));
        }
        let positions: Vec<Agg> = (0..count.hi()).map(|k| guarded(self, k)).collect();
        let keys = match &self.aggs.arrays[id].shape {
            Some(Some(keys)) => Some(keys.clone()),
            _ => None,
        };
        let pick = |column: Vec<(String, Ir)>| {
            lookup(i.clone(), &column, &missing)
                .ok_or_else(|| why(at, "indexes an array with an expression that has effects"))
        };
        match keys {
            None => {
                let column = positions
                    .iter()
                    .enumerate()
                    .map(|(k, a)| {
                        (
                            k.to_string(),
                            match a {
                                Agg::Plain(v) => v.clone(),
                                _ => Ir::Null,
                            },
                        )
                    })
                    .collect();
                Ok(Agg::Plain(pick(column)?))
            }
            Some(keys) => {
                let mut fields = Vec::new();
                for key in keys {
                    let column =
                        positions.iter().enumerate().map(|(k, a)| (k.to_string(), field_ir(a, &key))).collect();
                    fields.push((key, Agg::Plain(pick(column)?)));
                }
                Ok(Agg::Object(fields))
            }
        }
    }

    /// What reading past the last element gives: `undefined` (reading a
    /// property of it, a TypeError in JavaScript, has no native form).
    fn undefined_element(&self, _id: usize) -> Agg {
        Agg::Plain(self.missing())
    }

    /// An expression as an object or array, with the statements that make
    /// it: literals, locals bound to one, elements and properties, calls
    /// of functions that return one. Anything else is a plain value.
    pub(super) fn agg_expr(&mut self, e: &Expr, out: &mut Vec<IrStmt>) -> R<Agg> {
        match &e.kind {
            ExprKind::Array(items) => {
                let id = self.new_array(ARRAY_LITERAL);
                for item in items {
                    self.push_item(id, item, e.span, out)?;
                }
                Ok(Agg::Array(id))
            }
            ExprKind::Object(props) => {
                let mut fields: Vec<(String, Agg)> = Vec::new();
                for p in props {
                    if p.key.name == "__proto__" {
                        return Err(why(p.span, "an object literal that sets `__proto__`"));
                    }
                    let a = match self.agg_expr(&p.value, out)? {
                        Agg::Plain(v) => Agg::Plain(self.keep(v, out)),
                        other => other,
                    };
                    fields.retain(|(k, _)| *k != p.key.name);
                    fields.push((p.key.name.clone(), a));
                }
                Ok(Agg::Object(fields))
            }
            ExprKind::Call { callee, args } => {
                if let ExprKind::Ident(name) = &callee.kind
                    && let Symbol::TopFn(i) = self.model.scopes.resolve(name, self.at)
                    && !self.model.returns_plain[self.model.scopes.top_fns[i]]
                {
                    return self.agg_call(i, name, args, e.span, out);
                }
                Ok(Agg::Plain(self.expr(e)?))
            }
            ExprKind::Index { object, index } if self.agg_root(object) => {
                // The index is computed once, before the element is read.
                let i = super::super::fold::expr(self.expr(index)?);
                let i = if matches!(i, Ir::Number(_) | Ir::Text(_) | Ir::Bool(_) | Ir::Null | Ir::Undefined) {
                    i
                } else {
                    let t = self.temp();
                    out.push(IrStmt::Assign(Place::Local(t), i));
                    Ir::Local(t)
                };
                let a = if let ExprKind::Ident(o) = &object.kind
                    && self.table_info(o).is_some_and(|t| t.has_records())
                {
                    self.record(o, i, e.span)?
                } else {
                    let Some(base) = self.agg_read(object)? else { return Ok(Agg::Plain(self.expr(e)?)) };
                    self.index_of(base, i, e.span)?
                };
                // An element chosen by a run-time index is copied now: the
                // array may grow before the copy is read.
                Ok(self.freeze(a, out))
            }
            _ => match self.agg_read(e)? {
                Some(a) => Ok(a),
                None => Ok(Agg::Plain(self.expr(e)?)),
            },
        }
    }

    /// Whether an expression reads from an object or array kept in slots
    /// or from a table of records.
    pub(super) fn agg_root(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Ident(n) => self.is_bound(n) || self.table_info(n).is_some_and(|t| t.has_records()),
            ExprKind::Member { object, .. } | ExprKind::Index { object, .. } => self.agg_root(object),
            _ => false,
        }
    }

    /// A value kept in a slot of its own, unless it is a constant.
    fn keep(&mut self, v: Ir, out: &mut Vec<IrStmt>) -> Ir {
        if matches!(v, Ir::Number(_) | Ir::Text(_) | Ir::Bool(_) | Ir::Null | Ir::Undefined) {
            return v;
        }
        let t = self.temp();
        out.push(IrStmt::Assign(Place::Local(t), v));
        Ir::Local(t)
    }

    /// An object's properties copied into slots of their own.
    fn freeze(&mut self, a: Agg, out: &mut Vec<IrStmt>) -> Agg {
        match a {
            Agg::Object(fields) => Agg::Object(
                fields
                    .into_iter()
                    .map(|(k, f)| {
                        let f = match f {
                            Agg::Plain(v) => Agg::Plain(self.keep(v, out)),
                            other => other,
                        };
                        (k, f)
                    })
                    .collect(),
            ),
            other => other,
        }
    }

    fn new_array(&mut self, name: &str) -> usize {
        self.aggs.arrays.push(ArrayAgg {
            name: name.to_string(),
            elems: Vec::new(),
            shape: None,
            count: Count::Known(0),
            runtime: None,
            depth: self.aggs.loops.len(),
        });
        self.aggs.arrays.len() - 1
    }

    /// The slot counting an array's elements.
    fn runtime(&mut self, id: usize) -> LocalId {
        if let Some(r) = self.aggs.arrays[id].runtime {
            return r;
        }
        let r = self.temp();
        self.aggs.arrays[id].runtime = Some(r);
        r
    }

    /// The slots of position `k`, made when first needed.
    fn slots_at(&mut self, id: usize, k: usize) -> Agg {
        while self.aggs.arrays[id].elems.len() <= k {
            let e = match self.aggs.arrays[id].shape.clone().flatten() {
                Some(keys) => {
                    Agg::Object(keys.into_iter().map(|key| (key, Agg::Plain(Ir::Local(self.temp())))).collect())
                }
                None => Agg::Plain(Ir::Local(self.temp())),
            };
            self.aggs.arrays[id].elems.push(e);
        }
        self.aggs.arrays[id].elems[k].clone()
    }

    /// Makes the slots of the first `n` positions: a loop's body may read
    /// a position that a later statement of the body fills.
    fn fill_to(&mut self, id: usize, n: usize, at: postc_ir::Span) -> R<()> {
        if self.aggs.arrays[id].elems.len() >= n {
            return Ok(());
        }
        if self.aggs.arrays[id].shape.is_none() {
            return Err(why(
                at,
                format!(
                    "reads array `{}` in a loop before the loop has put an element in it",
                    self.aggs.arrays[id].name
                ),
            ));
        }
        self.slots_at(id, n - 1);
        Ok(())
    }

    /// Checks that a push in the loops open now was planned for.
    fn check_loops(&self, id: usize, at: postc_ir::Span) -> R<()> {
        let a = &self.aggs.arrays[id];
        if self.aggs.loops.get(a.depth..).unwrap_or(&[]).iter().any(|l| !l.contains(&id)) {
            return Err(why(at, format!("adds to array `{}` in a loop through a name postc does not follow", a.name)));
        }
        Ok(())
    }

    /// Sets the kind of an array's elements, or checks it.
    fn shape(&mut self, id: usize, keys: Option<Vec<String>>, at: postc_ir::Span) -> R<()> {
        let a = &mut self.aggs.arrays[id];
        match &a.shape {
            None => {
                a.shape = Some(keys);
                Ok(())
            }
            Some(old) => {
                let same = match (old, &keys) {
                    (None, None) => true,
                    (Some(x), Some(y)) => x.len() == y.len() && x.iter().all(|k| y.contains(k)),
                    _ => false,
                };
                if same {
                    Ok(())
                } else {
                    Err(why(
                        at,
                        format!(
                            "puts elements of different kinds (values, objects of other properties) in array `{}`",
                            a.name
                        ),
                    ))
                }
            }
        }
    }

    /// Appends one item (an expression) to an array.
    fn push_item(&mut self, id: usize, item: &Expr, at: postc_ir::Span, out: &mut Vec<IrStmt>) -> R<()> {
        if self.aggs.arrays[id].elems.len() >= MAX_ELEMENTS || self.aggs.arrays[id].count.hi() >= MAX_ELEMENTS {
            return Err(why(
                at,
                format!("puts more than {MAX_ELEMENTS} elements in array `{}`", self.aggs.arrays[id].name),
            ));
        }
        self.check_loops(id, at)?;
        // An object literal with values only: its properties go straight
        // into the element's slots when the position is known.
        if let ExprKind::Object(props) = &item.kind
            && let Count::Known(k) = self.aggs.arrays[id].count
            && props.iter().all(|p| p.key.name != "__proto__")
        {
            let mut keys: Vec<String> = Vec::new();
            for p in props {
                if !keys.contains(&p.key.name) {
                    keys.push(p.key.name.clone());
                }
            }
            self.shape(id, Some(keys), item.span)?;
            let slots = self.slots_at(id, k);
            for p in props {
                let v = match self.agg_expr(&p.value, out)? {
                    Agg::Plain(v) => v,
                    _ => return Err(why(p.span, "puts an object or array inside an element of an array")),
                };
                out.push(IrStmt::Assign(Place::Local(leaf(&field(&slots, &p.key.name))), v));
            }
            self.aggs.arrays[id].count = Count::Known(k + 1);
            return Ok(());
        }
        let a = self.agg_expr(item, out)?;
        self.push_agg(id, a, item.span, out)
    }

    /// Appends an element made already.
    fn push_agg(&mut self, id: usize, a: Agg, at: postc_ir::Span, out: &mut Vec<IrStmt>) -> R<()> {
        let leaves: Vec<(Option<String>, Ir)> = match a {
            Agg::Plain(v) => {
                self.shape(id, None, at)?;
                vec![(None, v)]
            }
            Agg::Object(fields) => {
                let mut keys = Vec::new();
                let mut leaves = Vec::new();
                for (k, f) in fields {
                    match f {
                        Agg::Plain(v) => leaves.push((Some(k.clone()), v)),
                        _ => return Err(why(at, "puts an object or array inside an element of an array")),
                    }
                    keys.push(k);
                }
                self.shape(id, Some(keys), at)?;
                leaves
            }
            Agg::Array(_) => return Err(why(at, "puts an array in an array")),
        };
        let store = |slots: &Agg, key: &Option<String>| -> LocalId {
            match key {
                Some(k) => leaf(&field(slots, k)),
                None => leaf(slots),
            }
        };
        match self.aggs.arrays[id].count {
            Count::Known(k) => {
                let slots = self.slots_at(id, k);
                for (key, v) in leaves {
                    out.push(IrStmt::Assign(Place::Local(store(&slots, &key)), v));
                }
                self.aggs.arrays[id].count = Count::Known(k + 1);
            }
            Count::Between(lo, hi) => {
                // Each value once, then into the slots of the position the
                // count names.
                let kept: Vec<(Option<String>, Ir)> = leaves.into_iter().map(|(k, v)| (k, self.keep(v, out))).collect();
                let r = self.runtime(id);
                let mut branches = Vec::new();
                for k in lo..=hi {
                    let slots = self.slots_at(id, k);
                    let body = kept
                        .iter()
                        .map(|(key, v)| IrStmt::Assign(Place::Local(store(&slots, key)), v.clone()))
                        .collect();
                    let at_k = Ir::Binary(IrBin::StrictEq, Box::new(Ir::Local(r)), Box::new(Ir::Number(k as f64)));
                    branches.push((at_k, body));
                }
                out.push(IrStmt::If { branches, otherwise: vec![] });
                let more = Ir::Binary(IrBin::Add, Box::new(Ir::Local(r)), Box::new(Ir::Number(1.0)));
                out.push(IrStmt::Assign(Place::Local(r), more));
                self.aggs.arrays[id].count = Count::Between(lo + 1, hi + 1);
            }
        }
        Ok(())
    }

    /// `a.push(x, y)`, `a[k] = x` (a position known when the post is
    /// compiled: the next one, or one filled already) and calls of
    /// functions that return an object, as statements. `false` when `e`
    /// is none of these.
    pub(super) fn agg_stmt(&mut self, e: &Expr, out: &mut Vec<IrStmt>) -> R<bool> {
        match &e.kind {
            ExprKind::Call { callee, args } => {
                if let ExprKind::Member { object, property } = &callee.kind
                    && self.agg_root(object)
                {
                    let Some(Agg::Array(id)) = self.agg_read(object)? else {
                        return Err(why(
                            callee.span,
                            format!("calls `.{}()` of an object postc keeps in slots", property.name),
                        ));
                    };
                    return match property.name.as_str() {
                        "push" => {
                            for a in args {
                                self.push_item(id, a, a.span, out)?;
                            }
                            Ok(true)
                        }
                        m => Err(why(
                            callee.span,
                            format!(
                                "calls `.{m}()` of array `{}`, which has no native form here",
                                self.aggs.arrays[id].name
                            ),
                        )),
                    };
                }
                if let ExprKind::Ident(name) = &callee.kind
                    && let Symbol::TopFn(i) = self.model.scopes.resolve(name, self.at)
                    && !self.model.returns_plain[self.model.scopes.top_fns[i]]
                {
                    self.agg_call(i, name, args, e.span, out)?;
                    return Ok(true);
                }
                Ok(false)
            }
            ExprKind::Assign { op: AssignOp::Assign, target, value } => {
                let ExprKind::Index { object, index } = &target.kind else { return Ok(false) };
                if !self.agg_root(object) {
                    return Ok(false);
                }
                let Some(Agg::Array(id)) = self.agg_read(object)? else {
                    return Err(why(target.span, "assigns a property of an object postc keeps in slots"));
                };
                let i = super::super::fold::expr(self.expr(index)?);
                let Some(k) = const_key(&i).as_deref().and_then(array_index) else {
                    return Err(why(
                        target.span,
                        "assigns an array element at a position known only when the post runs",
                    ));
                };
                match self.aggs.arrays[id].count {
                    Count::Known(n) if k == n => self.push_item(id, value, value.span, out)?,
                    Count::Known(n) if k < n && self.aggs.arrays[id].shape == Some(None) => {
                        self.check_loops(id, target.span)?;
                        let v = self.expr(value)?;
                        let slot = leaf(&self.aggs.arrays[id].elems[k]);
                        out.push(IrStmt::Assign(Place::Local(slot), v));
                    }
                    _ => {
                        return Err(why(
                            target.span,
                            "assigns an array element other than the next one or one already there",
                        ));
                    }
                }
                Ok(true)
            }
            _ => Ok(false),
        }
    }

    /// `f.apply(null, a)`: `f`'s form for the number of elements.
    pub(super) fn apply_aggregate(&mut self, i: usize, name: &str, a: &str, at: postc_ir::Span) -> R<Ir> {
        let Some(id) = self.agg_array(a) else { return Err(why(at, format!("calls `{name}.apply`"))) };
        if self.aggs.arrays[id].shape.as_ref().is_some_and(Option::is_some) {
            return Err(why(at, format!("calls `{name}.apply` with array `{a}` of objects")));
        }
        let count = self.aggs.arrays[id].count;
        self.fill_to(id, count.hi(), at)?;
        let call = |s: &mut Self, n: usize| -> R<Ir> {
            let f = s.call_target(i, name, n, at)?;
            let args = (0..n).map(|k| match &s.aggs.arrays[id].elems[k] {
                Agg::Plain(v) => v.clone(),
                _ => Ir::Null,
            });
            Ok(Ir::Call(f, args.collect()))
        };
        match count {
            Count::Known(n) => call(self, n),
            Count::Between(lo, hi) => {
                let r = self.runtime(id);
                let mut acc = call(self, hi)?;
                for n in (lo..hi).rev() {
                    let is_n = Ir::Binary(IrBin::StrictEq, Box::new(Ir::Local(r)), Box::new(Ir::Number(n as f64)));
                    acc = Ir::Choose(Box::new(is_n), Box::new(call(self, n)?), Box::new(acc));
                }
                Ok(acc)
            }
        }
    }

    /// `a.join(sep)` of an array of values.
    pub(super) fn join_aggregate(&mut self, id: usize, args: &[Expr], at: postc_ir::Span) -> R<Ir> {
        let sep = match args {
            [] => Ir::Text(",".into()),
            [s] => self.expr(s)?,
            _ => return Err(why(at, "calls `.join()` with more than one argument")),
        };
        if self.aggs.arrays[id].shape.as_ref().is_some_and(Option::is_some) {
            return Err(why(at, format!("joins array `{}` of objects", self.aggs.arrays[id].name)));
        }
        let hi = self.aggs.arrays[id].count.hi();
        self.fill_to(id, hi, at)?;
        let joined = |s: &Self, n: usize| {
            let mut text = Ir::Text(String::new());
            for k in 0..n {
                if k > 0 {
                    text = Ir::Binary(IrBin::Add, Box::new(text), Box::new(sep.clone()));
                }
                let e = match &s.aggs.arrays[id].elems[k] {
                    Agg::Plain(v) => super::arrays::join_part(v.clone()),
                    _ => Ir::Text(String::new()),
                };
                text = Ir::Binary(IrBin::Add, Box::new(text), Box::new(e));
            }
            text
        };
        if !repeatable(&sep) {
            return Err(why(at, "calls `.join()` with a separator that has effects"));
        }
        Ok(match self.aggs.arrays[id].count {
            Count::Known(n) => joined(self, n),
            Count::Between(lo, hi) => {
                let r = self.runtime(id);
                let mut acc = joined(self, hi);
                for n in (lo..hi).rev() {
                    let is_n = Ir::Binary(IrBin::StrictEq, Box::new(Ir::Local(r)), Box::new(Ir::Number(n as f64)));
                    acc = Ir::Choose(Box::new(is_n), Box::new(joined(self, n)), Box::new(acc));
                }
                acc
            }
        })
    }

    /// The known count of an array a name is bound to (`for (var i = 0; i
    /// < axes.length; i++)` unrolls).
    pub(super) fn known_length(&mut self, e: &Expr) -> Option<usize> {
        let ExprKind::Member { object, property } = &e.kind else { return None };
        if property.name != "length" {
            return None;
        }
        if let ExprKind::Ident(t) = &object.kind
            && let Some(n) = self.table_info(t).and_then(|t| t.array)
        {
            return Some(n);
        }
        match self.agg_read(object).ok()?? {
            Agg::Array(id) => match self.aggs.arrays[id].count {
                Count::Known(n) => Some(n),
                Count::Between(..) => None,
            },
            _ => None,
        }
    }

    /// Whether a statement names an object or array kept in slots.
    pub(super) fn mentions_aggregate(&self, s: &Stmt) -> bool {
        struct M<'n, 'c, 'a> {
            n: &'n Native<'c, 'a>,
            found: bool,
        }
        impl<'e> Visit<'e> for M<'_, '_, '_> {
            fn expr(&mut self, e: &'e Expr) -> bool {
                if let ExprKind::Ident(x) = &e.kind
                    && self.n.is_bound(x)
                {
                    self.found = true;
                }
                !matches!(e.kind, ExprKind::Function(_))
            }
            fn function_decl(&mut self, _f: &'e Function) {}
        }
        let mut m = M { n: self, found: false };
        super::super::scope::walk_stmt(s, &mut m);
        m.found
    }

    /// The counts of the arrays, to restore or compare.
    pub(super) fn counts(&self) -> Vec<Count> {
        self.aggs.arrays.iter().map(|a| a.count).collect()
    }

    pub(super) fn set_counts(&mut self, counts: &[Count]) {
        for (a, c) in self.aggs.arrays.iter_mut().zip(counts) {
            a.count = *c;
        }
    }

    /// Where branches meet: each array's count is the one they agree on,
    /// or a range its slot holds (each branch that knew it stores it).
    /// `arms`: each branch's statements, counts at its end, and whether it
    /// leaves (`return`, `break`, `continue`) instead of reaching here.
    pub(super) fn join(&mut self, arms: &mut [(&mut Vec<IrStmt>, Vec<Count>, bool)], before: &[Count]) {
        let live: Vec<usize> = (0..arms.len()).filter(|&i| !arms[i].2).collect();
        if live.is_empty() {
            self.set_counts(before);
            return;
        }
        for id in 0..before.len() {
            let first = arms[live[0]].1[id];
            let result = if live.iter().all(|&i| arms[i].1[id] == first) {
                first
            } else {
                let lo = live.iter().map(|&i| arms[i].1[id].lo()).min().unwrap_or(0);
                let hi = live.iter().map(|&i| arms[i].1[id].hi()).max().unwrap_or(0);
                let r = self.runtime(id);
                for &i in &live {
                    if let Count::Known(k) = arms[i].1[id] {
                        arms[i].0.push(IrStmt::Assign(Place::Local(r), Ir::Number(k as f64)));
                    }
                }
                Count::Between(lo, hi)
            };
            self.aggs.arrays[id].count = result;
        }
    }

    /// Whether the branches of an `if` leave arrays with known counts that
    /// differ, so that lowering the rest once per branch keeps them known.
    pub(super) fn worth_splitting(&self, ends: &[(Vec<Count>, bool)], before: &[Count], rest: &[Stmt]) -> bool {
        if rest.is_empty() || self.aggs.splits >= MAX_SPLITS || statements(rest) > MAX_SPLIT_STATEMENTS {
            return false;
        }
        let live: Vec<&Vec<Count>> = ends.iter().filter(|(_, leaves)| !leaves).map(|(c, _)| c).collect();
        if live.len() < 2 {
            return false;
        }
        let mut differ = false;
        for id in 0..before.len() {
            let first = live[0][id];
            if live.iter().any(|c| c[id] != first) {
                if live.iter().any(|c| matches!(c[id], Count::Between(..))) {
                    return false;
                }
                differ = true;
            }
        }
        differ
    }

    pub(super) fn note_split(&mut self) {
        self.aggs.splits += 1;
    }

    /// Before a loop's body: the arrays it pushes to get a counting slot
    /// and a range wide enough for every pass (`passes`: at most that many;
    /// `None` when the lowering cannot bound them). Returns the counts the
    /// arrays have after the loop.
    pub(super) fn enter_loop(
        &mut self,
        body: &[&Stmt],
        passes: Option<usize>,
        at: postc_ir::Span,
        out: &mut Vec<IrStmt>,
    ) -> R<Vec<(usize, Count)>> {
        let mut pushes: HashMap<usize, Option<usize>> = HashMap::new();
        for s in body {
            self.count_pushes(s, &mut pushes);
        }
        let mut after = Vec::new();
        let mut planned = HashSet::new();
        for (id, p) in pushes {
            let name = self.aggs.arrays[id].name.clone();
            let Some(p) = p else {
                return Err(why(
                    at,
                    format!("adds to array `{name}` in a loop inside a loop whose passes postc cannot count"),
                ));
            };
            if p == 0 {
                continue;
            }
            let Some(n) = passes else {
                return Err(why(
                    at,
                    format!(
                        "adds to array `{name}` in a loop whose passes postc cannot count (`for (var i = 0; i < 4; i++)` can be)"
                    ),
                ));
            };
            let (lo, hi) = (self.aggs.arrays[id].count.lo(), self.aggs.arrays[id].count.hi());
            if hi + n * p > MAX_ELEMENTS {
                return Err(why(at, format!("may put more than {MAX_ELEMENTS} elements in array `{name}`")));
            }
            if let Count::Known(k) = self.aggs.arrays[id].count {
                let r = self.runtime(id);
                out.push(IrStmt::Assign(Place::Local(r), Ir::Number(k as f64)));
            }
            self.aggs.arrays[id].count = Count::Between(lo, hi + n.saturating_sub(1) * p);
            after.push((id, Count::Between(lo, hi + n * p)));
            planned.insert(id);
        }
        self.aggs.loops.push(planned);
        Ok(after)
    }

    /// After a loop's body.
    pub(super) fn leave_loop(&mut self, after: Vec<(usize, Count)>) {
        self.aggs.loops.pop();
        for (id, c) in after {
            self.aggs.arrays[id].count = c;
        }
    }

    /// The most elements each array may get in one pass of `s`.
    fn count_pushes(&mut self, s: &Stmt, acc: &mut HashMap<usize, Option<usize>>) {
        let add = |acc: &mut HashMap<usize, Option<usize>>, id: usize, n: Option<usize>| {
            let e = acc.entry(id).or_insert(Some(0));
            *e = match (*e, n) {
                (Some(a), Some(b)) => Some(a + b),
                _ => None,
            };
        };
        match &s.kind {
            StmtKind::Expr(e) => {
                let mut found = Vec::new();
                collect_pushes(e, &mut found);
                for (object, n) in found {
                    if let Ok(Some(Agg::Array(id))) = self.agg_read(object) {
                        add(acc, id, Some(n));
                    }
                }
            }
            StmtKind::Var(_) | StmtKind::Return(_) | StmtKind::Throw(_) => {}
            StmtKind::Block(b) => b.iter().for_each(|s| self.count_pushes(s, acc)),
            StmtKind::If { branches, otherwise } => {
                for b in branches {
                    self.count_pushes(&b.body, acc);
                }
                if let Some(o) = otherwise {
                    self.count_pushes(o, acc);
                }
            }
            StmtKind::Switch { cases, .. } => {
                cases.iter().flat_map(|c| &c.body).for_each(|s| self.count_pushes(s, acc))
            }
            StmtKind::For { body, .. }
            | StmtKind::While { body, .. }
            | StmtKind::DoWhile { body, .. }
            | StmtKind::ForIn { body, .. } => {
                let passes = match &s.kind {
                    StmtKind::For { init, test, update, body } => self.passes(init, test, update, body),
                    _ => None,
                };
                let mut inner = HashMap::new();
                self.count_pushes(body, &mut inner);
                for (id, n) in inner {
                    let n = match (n, passes) {
                        (Some(0), _) => Some(0),
                        (Some(n), Some(p)) => Some(n * p),
                        _ => None,
                    };
                    add(acc, id, n);
                }
            }
            _ => {}
        }
    }

    /// At most how many passes a `for` loop makes: `for (var i = A; i < B;
    /// i++)` (or `<=`, `i += 1`) with `A` and `B` known and `i` assigned
    /// nowhere in the body; `break` may leave earlier.
    pub(super) fn passes(
        &mut self,
        init: &Option<ForInit>,
        test: &Option<Expr>,
        update: &Option<Expr>,
        body: &Stmt,
    ) -> Option<usize> {
        let counted = super::variadic::counted_loop(init, test, update)?;
        let from = counted.from;
        let to = match counted.to.kind {
            ExprKind::Number(n) => n,
            _ => self.known_length(counted.to)? as f64,
        };
        if super::variadic::assigns(body, counted.name) || !from.is_finite() || !to.is_finite() {
            return None;
        }
        let n = if counted.op == BinaryOp::Le { (to - from).floor() + 1.0 } else { (to - from).ceil() };
        Some(n.clamp(0.0, MAX_ELEMENTS as f64 + 1.0) as usize)
    }

    /// The shape of the object or array function `i` returns, lowering it
    /// first when it has not been; its native form stores what it returns
    /// in hidden globals.
    fn returned(&mut self, i: usize, name: &str, at: postc_ir::Span) -> R<RetShape> {
        let id = self.model.scopes.top_fns[i];
        if let Some(r) = self.layout.returns.get(&id) {
            return r.clone().map_err(|w| {
                why(
                    at,
                    format!(
                        "calls `{name}`, which may return an object or an array and has no native form: it {}",
                        w.what
                    ),
                )
            });
        }
        if self.layout.lowering.contains(&id) {
            return Err(why(at, format!("calls `{name}`, which returns an object or array, from inside itself")));
        }
        lower_top(self.model, self.setup, self.layout, id);
        match self.layout.returns.get(&id) {
            Some(r) => r.clone().map_err(|w| {
                why(
                    at,
                    format!(
                        "calls `{name}`, which may return an object or an array and has no native form: it {}",
                        w.what
                    ),
                )
            }),
            None => Err(why(at, format!("calls `{name}`, which may return an object, an array or a function"))),
        }
    }

    /// A call of a function that returns an object or array: the call,
    /// then the hidden globals copied into slots of this function.
    fn agg_call(&mut self, i: usize, name: &str, args: &[Expr], at: postc_ir::Span, out: &mut Vec<IrStmt>) -> R<Agg> {
        let id = self.model.scopes.top_fns[i];
        if self.model.fn_reassigned.contains(&i) {
            return Err(why(at, format!("calls `{name}`, which the post assigns another function to")));
        }
        if args.len() > self.model.scopes.funcs[id].params.len() || self.model.scopes.funcs[id].uses_arguments {
            return Err(why(
                at,
                format!("calls `{name}`, which returns an object or array, with a variable number of arguments"),
            ));
        }
        let shape = self.returned(i, name, at)?;
        let f = self.layout.top_fn.get(i).copied().ok_or_else(|| why(at, format!("calls `{name}`")))?;
        let args = self.args(args)?;
        out.push(IrStmt::Eval(Ir::Call(f, args)));
        Ok(self.copy_in(&shape, out))
    }

    fn copy_in(&mut self, shape: &RetShape, out: &mut Vec<IrStmt>) -> Agg {
        match shape {
            RetShape::Plain(g) => {
                let t = self.temp();
                out.push(IrStmt::Assign(Place::Local(t), Ir::Global(*g)));
                Agg::Plain(Ir::Local(t))
            }
            RetShape::Object(fields) => {
                Agg::Object(fields.iter().map(|(k, f)| (k.clone(), self.copy_in(f, out))).collect())
            }
            RetShape::Array { elems, keys, count } => {
                let id = self.new_array("returned array");
                self.aggs.arrays[id].shape = Some(keys.clone());
                for e in elems {
                    let a = self.copy_in(e, out);
                    self.aggs.arrays[id].elems.push(a);
                }
                self.aggs.arrays[id].count = match *count {
                    RetCount::Known(n) => Count::Known(n),
                    RetCount::Between(lo, hi, g) => {
                        let r = self.runtime(id);
                        out.push(IrStmt::Assign(Place::Local(r), Ir::Global(g)));
                        Count::Between(lo, hi)
                    }
                };
                Agg::Array(id)
            }
        }
    }

    /// `return e` of a function that returns an object or array: `e`
    /// stored in the function's hidden globals.
    pub(super) fn agg_return(&mut self, e: &Expr, out: &mut Vec<IrStmt>) -> R<()> {
        let a = self.agg_expr(e, out)?;
        let fname = self.model.scopes.funcs[self.at].name.clone().unwrap_or_default();
        let shape = self.store(&a, &format!("__postc_return:{fname}"), out);
        self.aggs.ret = Some(shape);
        out.push(IrStmt::Return(None));
        Ok(())
    }

    fn store(&mut self, a: &Agg, path: &str, out: &mut Vec<IrStmt>) -> RetShape {
        match a {
            Agg::Plain(v) => {
                let g = self.layout.add_global(path, Ir::Null);
                out.push(IrStmt::Assign(Place::Global(g), v.clone()));
                RetShape::Plain(g)
            }
            Agg::Object(fields) => RetShape::Object(
                fields.iter().map(|(k, f)| (k.clone(), self.store(f, &format!("{path}.{k}"), out))).collect(),
            ),
            Agg::Array(id) => {
                let id = *id;
                let count = self.aggs.arrays[id].count;
                let elems: Vec<Agg> = self.aggs.arrays[id].elems.iter().take(count.hi()).cloned().collect();
                let stored =
                    elems.iter().enumerate().map(|(k, e)| self.store(e, &format!("{path}[{k}]"), out)).collect();
                let count = match count {
                    Count::Known(n) => RetCount::Known(n),
                    Count::Between(lo, hi) => {
                        let g = self.layout.add_global(&format!("{path}.length"), Ir::Null);
                        let r = self.runtime(id);
                        out.push(IrStmt::Assign(Place::Global(g), Ir::Local(r)));
                        RetCount::Between(lo, hi, g)
                    }
                };
                RetShape::Array { elems: stored, keys: self.aggs.arrays[id].shape.clone().flatten(), count }
            }
        }
    }
}

/// Lowers top-level function `id` once (its body is kept for
/// [`super::super::functions`]); for a function that returns an object or
/// array, records the shape it returns.
pub fn lower_top(
    model: &super::super::model::Model,
    setup: &super::super::setup::Setup,
    layout: &mut Layout,
    id: FnId,
) {
    if layout.lowered.contains_key(&id) || layout.returns.contains_key(&id) || layout.lowering.contains(&id) {
        return;
    }
    let info = &model.scopes.funcs[id];
    let Some(func) = info.func else { return };
    layout.lowering.insert(id);
    let mut n = Native::new(model, setup, layout, id);
    n.entry = info.name.as_deref().is_some_and(super::super::is_entry_point);
    let body = n.lower_function(&func.body, func.span);
    let slots = n.slots;
    let reshaped = n.reshaped;
    let ret = n.aggs.ret.take();
    let returns = n.aggs.returns;
    layout.lowering.remove(&id);
    if returns {
        let r = match (&body, ret) {
            (Ok(_), Some(shape)) => Ok(shape),
            (Err(w), _) => Err(w.clone()),
            (Ok(_), None) => Err(why(func.span, "returns nothing postc can keep")),
        };
        layout.returns.insert(id, r);
    }
    layout.lowered.insert(id, Lowered { body, slots, reshaped });
}

/// A leaf's slot.
fn leaf(a: &Agg) -> LocalId {
    match a {
        Agg::Plain(Ir::Local(k)) => *k,
        _ => LocalId::new(u16::MAX),
    }
}

/// A property of an element's slots.
fn field(a: &Agg, key: &str) -> Agg {
    match a {
        Agg::Object(fields) => {
            fields.iter().find(|(k, _)| k == key).map_or(Agg::Plain(Ir::Undefined), |(_, f)| f.clone())
        }
        _ => Agg::Plain(Ir::Undefined),
    }
}

fn field_ir(a: &Agg, key: &str) -> Ir {
    match field(a, key) {
        Agg::Plain(v) => v,
        _ => Ir::Null,
    }
}

/// Every plain leaf of an aggregate changed by `f`.
fn map_plain(a: Agg, f: &dyn Fn(Ir) -> Ir) -> Agg {
    match a {
        Agg::Plain(v) => Agg::Plain(f(v)),
        Agg::Object(fields) => Agg::Object(fields.into_iter().map(|(k, x)| (k, map_plain(x, f))).collect()),
        other => other,
    }
}

/// The array position a key names ("0", "12"; not "01" or "-1").
fn array_index(k: &str) -> Option<usize> {
    let n: usize = k.parse().ok()?;
    (n.to_string() == k).then_some(n)
}

/// How many statements a list holds, nested ones included.
fn statements(body: &[Stmt]) -> usize {
    struct Count(usize);
    impl<'a> Visit<'a> for Count {
        fn expr(&mut self, _e: &'a Expr) -> bool {
            false
        }
        fn stmt(&mut self, _s: &'a Stmt) -> bool {
            self.0 += 1;
            true
        }
        fn function_decl(&mut self, _f: &'a Function) {}
    }
    let mut c = Count(0);
    walk_stmts(body, &mut c);
    c.0
}

/// The `x.push(...)` calls and `x[k] = v` assignments in an expression
/// statement: each target and how many elements it may get.
fn collect_pushes<'e>(e: &'e Expr, found: &mut Vec<(&'e Expr, usize)>) {
    match &e.kind {
        ExprKind::Call { callee, args } => {
            if let ExprKind::Member { object, property } = &callee.kind
                && property.name == "push"
            {
                found.push((object, args.len()));
            }
        }
        ExprKind::Assign { target, .. } => {
            if let ExprKind::Index { object, .. } = &target.kind {
                found.push((object, 1));
            }
        }
        _ => {}
    }
}

/// How often each local of a function is assigned, and which are declared
/// with a value.
struct Assignments<'m, 'a> {
    model: &'m super::super::model::Model<'a>,
    at: FnId,
    counts: HashMap<usize, usize>,
    declared: HashSet<usize>,
}

impl Assignments<'_, '_> {
    fn slot(&self, name: &str) -> Option<usize> {
        match self.model.scopes.resolve(name, self.at) {
            Symbol::Local { func, slot } if func == self.at => Some(slot),
            _ => None,
        }
    }

    fn count(&mut self, name: &str) {
        if let Some(s) = self.slot(name) {
            *self.counts.entry(s).or_insert(0) += 1;
        }
    }
}

impl<'a> Visit<'a> for Assignments<'_, 'a> {
    fn stmt(&mut self, s: &'a Stmt) -> bool {
        match &s.kind {
            StmtKind::Var(ds) => {
                for d in ds.iter().filter(|d| d.init.is_some()) {
                    self.count(&d.name.name);
                    if let Some(s) = self.slot(&d.name.name) {
                        self.declared.insert(s);
                    }
                }
            }
            StmtKind::For { init: Some(ForInit::Var(ds)), .. } => {
                // A loop's `var` is a counter: never an object.
                for d in ds {
                    self.count(&d.name.name);
                    self.count(&d.name.name);
                }
            }
            StmtKind::ForIn { name, .. } => self.count(&name.name),
            _ => {}
        }
        true
    }

    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } => {
                if let ExprKind::Ident(n) = &target.kind {
                    self.count(n);
                }
            }
            ExprKind::Function(_) => return false,
            _ => {}
        }
        true
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}
