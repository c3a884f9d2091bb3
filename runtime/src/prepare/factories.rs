//! Factory functions specialised per global, and methods of objects a
//! global holds for the whole run called directly.
//!
//! A field post makes its modal words with a *factory*: `var xWord =
//! modal("X", xyzFormat)`, where `modal(prefix, format)` keeps its state
//! in locals and returns an object of closures over them (`{word:
//! function (v) {...}, reset: function () {...}}`). The general lowering
//! gives each closure its captures as leading parameters, and a captured
//! local the closures change lives in a cell (a one-item array). Every
//! `xWord.word(v)` then looks the method up by name, copies the captures
//! into a frame and reads and writes its state through cells.
//!
//! **Specialising a factory call** ([`specialise`]). A top-level statement
//! of the one-time code (or of the function only it calls) `g = F(args)`
//! becomes the statements `F` stands for with its arguments known: each
//! cell becomes a global of its own, set as `F` sets the cell, and each
//! closure of the returned object a function of its own, made from the
//! closure's function with every captured value replaced by the argument
//! it is (a constant) and every read and write of a cell by a read and
//! write of its global; `g` is assigned the object literal of those
//! functions, which capture nothing. The preconditions:
//!
//! - the post has no script (a script host reads globals by name);
//! - every argument of the call is a constant (a number, a text, a
//!   boolean, null, undefined, a format or an output variable), and `F`
//!   takes no `arguments` and no `this`;
//! - `F`'s body is only: cells made of a constant or a parameter
//!   (`c = [p]`), cells set to a constant or a parameter (`c[0] = p`), and
//!   last `return {...}` of an object literal whose values are constants,
//!   closures that capture nothing, or closures that capture parameters
//!   and cells of `F`: so calling `F` runs no other code and its cells are
//!   reached by nothing but the returned closures;
//! - in each closure's function, a captured parameter is never assigned
//!   and a captured cell is only read as `c[0]` and set as `c[0] = v`
//!   (never passed on, captured again or compared), and the function does
//!   not read `arguments`.
//!
//! What the post writes is unchanged: the closures run the same
//! statements with the same values, the state of each call of `F` is kept
//! where only its closures reach it, and the object holds a new function
//! per call of `F` as it held new closures.
//!
//! **Calling methods directly** ([`direct_calls`]). Then `g.m(args)` of
//! a global that holds one object literal for the whole run becomes a
//! call of `m`'s function, and `g.m` read as a value that function's one
//! value (the same value the literal holds). The preconditions:
//!
//! - the post has no script;
//! - `g` is assigned once in the whole post, with an object literal, by a
//!   top-level statement of the one-time code (or of the function only it
//!   calls) before any post code has run;
//! - the literal's value for `m` is a closure that captures nothing of a
//!   function that does not read `this`;
//! - no statement of the post sets a property with a key that is not a
//!   constant, or with the constant key `m`: nothing can give the object
//!   another `m` (the object may be passed, kept in arrays and read whole;
//!   a property it holds from its literal is found before its
//!   prototype's).

use std::collections::{HashMap, HashSet};

use postc_ir::{FunctionId, GlobalId, LocalId, Place};

use super::fields::{each_expr, each_stmt, runs_code_stmt};
use crate::exec::{self, Expr, Stmt};

/// What a closure of the factory's object captures, by position.
#[derive(Clone)]
enum Capture {
    /// A value known when the factory is called (an argument or a constant).
    Value(Expr),
    /// A cell of the factory, kept in this global.
    Cell(GlobalId),
}

/// Specialises the factory calls of the one-time code that meet the
/// preconditions (module documentation), adding a function for each
/// closure they make and a global for each cell.
pub fn specialise(
    functions: &mut Vec<exec::Function>,
    handlers: &mut [Vec<Stmt>],
    init: &mut Vec<Stmt>,
    globals: &mut Vec<Expr>,
) {
    if functions.iter().any(|f| matches!(f.body, exec::Body::Script(_))) {
        return;
    }
    let once = init_function(functions, handlers, init);
    let mut body = match once {
        Some(f) => match &mut functions[f.index()].body {
            exec::Body::Native(b) => std::mem::take(b),
            exec::Body::Script(_) => return,
        },
        None => std::mem::take(init),
    };
    let mut out = Vec::with_capacity(body.len());
    for s in body.drain(..) {
        match &s {
            Stmt::Assign(Place::Global(g), Expr::Call(f, args)) => match made(functions, globals, *f, args) {
                Some((sets, object)) => {
                    out.extend(sets.into_iter().map(|(cell, v)| Stmt::Assign(Place::Global(cell), v)));
                    out.push(Stmt::Assign(Place::Global(*g), object));
                }
                None => out.push(s),
            },
            _ => out.push(s),
        }
    }
    match once {
        Some(f) => {
            if let exec::Body::Native(b) = &mut functions[f.index()].body {
                *b = out;
            }
        }
        None => *init = out,
    }
}

/// The function the one-time code calls once with no arguments, and that
/// nothing else calls, when its top-level statements are the post's
/// (the CIMCO front end's `__postc_init`).
fn init_function(
    functions: &mut [exec::Function],
    handlers: &mut [Vec<Stmt>],
    init: &mut [Stmt],
) -> Option<FunctionId> {
    let mut calls = vec![0usize; functions.len()];
    {
        let mut count = |e: &mut Expr| {
            if let Expr::Call(f, _) | Expr::Closure { function: f, .. } = e
                && let Some(n) = calls.get_mut(f.index())
            {
                *n += 1;
            }
        };
        each_expr(functions, handlers, init, &mut count);
    }
    init.iter().find_map(|s| match s {
        Stmt::Eval(Expr::Call(f, args))
            if args.is_empty()
                && calls.get(f.index()).copied() == Some(1)
                && matches!(functions.get(f.index()).map(|f| &f.body), Some(exec::Body::Native(_))) =>
        {
            Some(*f)
        }
        _ => None,
    })
}

/// A constant a call may pass and a closure capture: evaluating it runs
/// nothing and gives the same value each time (as far as `===` tells).
fn constant(e: &Expr) -> bool {
    matches!(e, Expr::Number(_) | Expr::Text(_) | Expr::Bool(_) | Expr::Null | Expr::Undefined | Expr::Output(_))
}

/// What `f(args)` stands for when `f` is a factory: the values the cells'
/// globals are set to, in order, and the object literal; `None` when a
/// precondition fails. Globals and functions are added only when it
/// succeeds.
fn made(
    functions: &mut Vec<exec::Function>,
    globals: &mut Vec<Expr>,
    f: FunctionId,
    args: &[Expr],
) -> Option<(Vec<(GlobalId, Expr)>, Expr)> {
    let factory = functions.get(f.index())?;
    let exec::Body::Native(body) = &factory.body else { return None };
    if factory.uses_arguments || factory.uses_this || args.len() > factory.params || !args.iter().all(constant) {
        return None;
    }
    let fill = factory.fill();
    let arg = |i: usize| args.get(i).cloned().unwrap_or_else(|| fill.clone());
    let value = |e: &Expr| match e {
        e if constant(e) => Some(e.clone()),
        Expr::Local(i) if i.index() < factory.params => Some(arg(i.index())),
        _ => None,
    };
    let (last, rest) = body.split_last()?;
    let mut cells: Vec<LocalId> = Vec::new();
    let mut sets: Vec<(LocalId, Expr)> = Vec::new();
    for s in rest {
        match s {
            Stmt::Assign(Place::Local(c), Expr::Array(items))
                if c.index() >= factory.params && items.len() == 1 && !cells.contains(c) =>
            {
                sets.push((*c, value(&items[0])?));
                cells.push(*c);
            }
            Stmt::SetMember { object: Expr::Local(c), key: Expr::Number(k), value: v, .. }
                if *k == 0.0 && cells.contains(c) =>
            {
                sets.push((*c, value(v)?));
            }
            _ => return None,
        }
    }
    let Stmt::Return(Some(Expr::Object(props))) = last else { return None };
    // What each closure of the literal captures, before anything is added.
    #[allow(clippy::type_complexity)]
    let mut plans: Vec<Option<(FunctionId, Vec<Result<Expr, LocalId>>)>> = Vec::with_capacity(props.len());
    for (_, v) in props {
        plans.push(match v {
            Expr::Closure { function, captures } if !captures.is_empty() => {
                let mut caps = Vec::with_capacity(captures.len());
                for c in captures {
                    caps.push(match c {
                        Expr::Local(l) if cells.contains(l) => Err(*l),
                        other => Ok(value(other)?),
                    });
                }
                Some((*function, caps))
            }
            Expr::Closure { .. } => None,
            v if constant(v) => None,
            _ => return None,
        });
    }
    // Each closure's function specialised, checked before any global is
    // given: a cell's global is the next free one, in the order of cells.
    let first = globals.len();
    let cell_global = |l: LocalId| -> Option<GlobalId> {
        let i = cells.iter().position(|c| *c == l)?;
        GlobalId::from_usize(first + i)
    };
    GlobalId::from_usize(first + cells.len())?;
    let mut made_functions = Vec::new();
    for plan in plans.iter().flatten() {
        let (function, caps) = plan;
        let caps: Vec<Capture> = caps
            .iter()
            .map(|c| match c {
                Ok(v) => Some(Capture::Value(v.clone())),
                Err(l) => cell_global(*l).map(Capture::Cell),
            })
            .collect::<Option<_>>()?;
        made_functions.push(specialised(functions.get(function.index())?, &caps)?);
    }
    // Every precondition holds: the globals and functions are added.
    let props = props.clone();
    let sets: Vec<(GlobalId, Expr)> =
        sets.into_iter().map(|(c, v)| cell_global(c).map(|g| (g, v))).collect::<Option<_>>()?;
    globals.extend(cells.iter().map(|_| Expr::Undefined));
    let mut new = made_functions.into_iter();
    let mut object = Vec::with_capacity(props.len());
    for ((k, v), plan) in props.into_iter().zip(plans) {
        let v = match plan {
            Some(_) => {
                let id = FunctionId::from_usize(functions.len())?;
                functions.push(new.next()?);
                Expr::Closure { function: id, captures: Vec::new() }
            }
            None => v,
        };
        object.push((k, v));
    }
    Some((sets, Expr::Object(object)))
}

/// A closure's function with its leading captured parameters replaced as
/// `caps` says; `None` when the function uses a capture otherwise than
/// the preconditions allow.
fn specialised(function: &exec::Function, caps: &[Capture]) -> Option<exec::Function> {
    let exec::Body::Native(body) = &function.body else { return None };
    let k = caps.len();
    if function.uses_arguments || function.params < k || usize::from(function.slots) < k {
        return None;
    }
    let mut body = body.clone();
    let mut ok = true;
    let mut rewriter = Specialiser { caps, ok: &mut ok };
    rewriter.stmts(&mut body);
    if !ok {
        return None;
    }
    Some(exec::Function {
        params: function.params - k,
        uses_arguments: false,
        uses_this: function.uses_this,
        starts_undefined: function.starts_undefined,
        slots: function.slots - k as u16,
        body: exec::Body::Native(body),
        origin: function.origin,
        returns: None,
    })
}

/// Rewrites a closure's body for [`specialised`].
struct Specialiser<'a> {
    caps: &'a [Capture],
    ok: &'a mut bool,
}

impl Specialiser<'_> {
    /// The capture a local is, or the local it becomes.
    fn local(&mut self, l: &mut LocalId) -> Option<&Capture> {
        let i = l.index();
        if i < self.caps.len() {
            return self.caps.get(i);
        }
        match LocalId::from_usize(i - self.caps.len()) {
            Some(new) => *l = new,
            None => *self.ok = false,
        }
        None
    }

    fn cell(&self, e: &Expr) -> Option<GlobalId> {
        match e {
            Expr::Local(l) => match self.caps.get(l.index()) {
                Some(Capture::Cell(g)) => Some(*g),
                _ => None,
            },
            _ => None,
        }
    }

    fn expr(&mut self, e: &mut Expr) {
        if let Expr::Member(o, key, _) = e
            && matches!(**key, Expr::Number(n) if n == 0.0)
            && let Some(g) = self.cell(o)
        {
            *e = Expr::Global(g);
            return;
        }
        match e {
            Expr::Local(l) => match self.local(l).cloned() {
                Some(Capture::Value(v)) => *e = v,
                Some(Capture::Cell(_)) => *self.ok = false,
                None => {}
            },
            Expr::Written(l) | Expr::LocalEmpty { local: l, .. } | Expr::LocalIsText { local: l, .. } => {
                if self.local(l).is_some() {
                    *self.ok = false;
                }
            }
            Expr::Arguments => *self.ok = false,
            e => e.for_each_operand_mut(|a| self.expr(a)),
        }
    }

    fn stmts(&mut self, body: &mut [Stmt]) {
        for s in body {
            if let Stmt::SetMember { object, key: Expr::Number(n), value, .. } = s
                && *n == 0.0
                && let Some(g) = self.cell(object)
            {
                let mut value = std::mem::replace(value, Expr::Undefined);
                self.expr(&mut value);
                *s = Stmt::Assign(Place::Global(g), value);
                continue;
            }
            s.for_each_named_local_mut(|_, l| {
                if self.local(l).is_some() {
                    // A capture assigned (or a mark on it): not a constant.
                    *self.ok = false;
                }
            });
            s.for_each_expr_mut(|e| self.expr(e));
            s.for_each_body_mut(|b| self.stmts(b));
        }
    }
}

/// Rewrites `g.m(args)` and `g.m` of the globals that meet the
/// preconditions of direct calls (module documentation).
pub fn direct_calls(functions: &mut [exec::Function], handlers: &mut [Vec<Stmt>], init: &mut [Stmt]) {
    if functions.iter().any(|f| matches!(f.body, exec::Body::Script(_))) {
        return;
    }
    // How often each global is assigned, and the keys properties are set with.
    let mut assigned: HashMap<GlobalId, usize> = HashMap::new();
    let mut set_keys: HashSet<String> = HashSet::new();
    let mut any_key = false;
    each_stmt(functions, handlers, init, &mut |s| match &*s {
        Stmt::Assign(Place::Global(g), _) => *assigned.entry(*g).or_default() += 1,
        Stmt::SetMember { key, .. } => match key {
            Expr::Text(t) => {
                set_keys.insert(t.to_string());
            }
            Expr::Number(n) if n.is_finite() && *n == n.trunc() && n.abs() < 1e15 => {
                set_keys.insert(format!("{}", *n as i64));
            }
            _ => any_key = true,
        },
        _ => {}
    });
    if any_key {
        return;
    }
    // The literals assigned before any code runs.
    let mut direct: HashMap<(GlobalId, String), FunctionId> = HashMap::new();
    let once = init_function(functions, handlers, init);
    let top: Vec<Stmt> = match once {
        Some(f) => match &functions[f.index()].body {
            exec::Body::Native(b) => b.clone(),
            exec::Body::Script(_) => return,
        },
        None => init.to_vec(),
    };
    for mut s in top {
        // Nothing may have run before the object is the global's, its
        // own literal's values included.
        if runs_code_stmt(&mut s) {
            break;
        }
        if let Stmt::Assign(Place::Global(g), Expr::Object(props)) = &s
            && assigned.get(g).copied() == Some(1)
        {
            for (k, v) in props {
                if let Expr::Closure { function, captures } = v
                    && captures.is_empty()
                    && !set_keys.contains(&**k)
                    && functions.get(function.index()).is_some_and(|f| !f.uses_this)
                {
                    direct.insert((*g, k.to_string()), *function);
                }
            }
        }
    }
    if direct.is_empty() {
        return;
    }
    let mut rewrite = |e: &mut Expr| {
        let (object, method) = match e {
            Expr::Invoke { object, method, .. } => (&**object, &**method),
            Expr::Member(object, key, _) => match &**key {
                Expr::Text(t) => (&**object, &**t),
                _ => return,
            },
            _ => return,
        };
        let target = match object {
            Expr::Global(g) => direct.get(&(*g, method.to_string())).copied(),
            _ => None,
        };
        let Some(f) = target else { return };
        *e = match std::mem::replace(e, Expr::Undefined) {
            Expr::Invoke { args, .. } => Expr::Call(f, args),
            _ => Expr::Closure { function: f, captures: Vec::new() },
        };
    };
    each_expr(functions, handlers, init, &mut rewrite);
}
