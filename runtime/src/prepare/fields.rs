//! Objects held in globals as globals of their own (scalar replacement):
//! a global that holds one object literal for the whole run, and whose
//! object is never seen as a whole, keeps each property in a global of its
//! own, and each of its methods becomes a plain function. `state.x = t`
//! is then an assignment, `state.x` a global read and `out.block(t)` a
//! call, which the fast-path passes take like any other code.
//!
//! The preconditions, all checked over the whole post (its functions,
//! handlers and one-time code):
//!
//! - the post has no script (a script host reads globals by name);
//! - the global is assigned once, with an object literal whose keys are
//!   plain and distinct, by a top-level statement of the one-time code
//!   (or of a function only it calls) before any post code has run, so no
//!   code reads the global before it holds the object;
//! - every other use of the global is `g.k` or `g.k = v` with `k` a key
//!   of the literal that holds no method, or `g.m(...)` with `m` one that
//!   does: the object is never passed, compared, copied, iterated or read
//!   with a computed key, so nothing can tell its properties apart from
//!   globals;
//! - a method is a function literal that captures nothing, made nowhere
//!   else and never read as a value, so it only ever runs as `g.m(...)`
//!   with `this` the object; its own `this` is only `this.k`,
//!   `this.k = v` and `this.m(...)` of the same object;
//! - `this` anywhere else in the post is only read or called through a
//!   constant key that names no such global (`this.state` would reach
//!   the object through the global object).
//!
//! What the post writes is unchanged: property reads and writes happen
//! in the same order, as reads and writes of globals, and a method runs
//! the same statements with the same arguments.

use std::collections::HashMap;

use postc_ir::{Builtin, FunctionId, GlobalId, Place};

use crate::exec::{self, Expr, Stmt};

/// What is known of a global that may hold a replaceable object.
struct Candidate {
    /// The literal's keys, in order, with the function of each method.
    keys: Vec<(exec::Text, Option<FunctionId>)>,
    /// Still replaceable.
    ok: bool,
    /// The global of each data key, once replaced.
    fields: Vec<Option<GlobalId>>,
}

impl Candidate {
    fn key(&self, k: &str) -> Option<usize> {
        self.keys.iter().position(|(key, _)| &**key == k)
    }

    /// Whether `k` is a key that holds no method.
    fn data(&self, k: &str) -> bool {
        self.key(k).is_some_and(|i| self.keys[i].1.is_none())
    }

    /// The function of method `k`.
    fn method(&self, k: &str) -> Option<FunctionId> {
        self.key(k).and_then(|i| self.keys[i].1)
    }
}

/// Replaces the objects of the post's globals that meet the
/// preconditions (module documentation) by globals, in place.
pub fn replace(
    names: &[&str],
    functions: &mut [exec::Function],
    handlers: &mut [Vec<Stmt>],
    init: &mut Vec<Stmt>,
    globals: &mut Vec<Expr>,
) {
    if functions.iter().any(|f| matches!(f.body, exec::Body::Script(_))) {
        return;
    }
    let mut candidates = find(functions, handlers, init);
    // Copies of the globals in temporaries are read through on copies of
    // the code, which is kept only if every candidate it was read through
    // for stays one (a global assigned once, before any code runs, holds
    // the same object wherever it is read): until none fails.
    while !candidates.is_empty() {
        let (mut fs, mut hs, mut is) = (functions.to_vec(), handlers.to_vec(), init.clone());
        let mut gs = globals.clone();
        let copied = |g: GlobalId| candidates.contains_key(&g);
        for f in &mut fs {
            if let exec::Body::Native(body) = &mut f.body {
                read_through(body, &copied);
            }
        }
        hs.iter_mut().for_each(|h| read_through(h, &copied));
        read_through(&mut is, &copied);
        let Some(method_of) = check(names, &mut candidates, &mut fs, &mut hs, &mut is, &mut gs) else { return };
        if candidates.values().any(|c| !c.ok) {
            candidates.retain(|_, c| c.ok);
            candidates.values_mut().for_each(|c| c.fields.clear());
            continue;
        }
        if rewrite(&mut candidates, &method_of, &mut fs, &mut hs, &mut is, &mut gs) {
            for (f, new) in functions.iter_mut().zip(fs) {
                *f = new;
            }
            for (h, new) in handlers.iter_mut().zip(hs) {
                *h = new;
            }
            *init = is;
            *globals = gs;
        }
        return;
    }
}

/// Checks every use of the candidates and marks those that fail; the
/// method functions of each; `None` when `this` may reach any.
fn check(
    names: &[&str],
    candidates: &mut HashMap<GlobalId, Candidate>,
    functions: &mut [exec::Function],
    handlers: &mut [Vec<Stmt>],
    init: &mut [Stmt],
    globals: &mut [Expr],
) -> Option<HashMap<usize, GlobalId>> {
    // Who makes or calls each function.
    let mut refs = vec![0usize; functions.len()];
    {
        let mut count = |e: &mut Expr| {
            if let Expr::Call(f, _) | Expr::Closure { function: f, .. } = e
                && let Some(n) = refs.get_mut(f.index())
            {
                *n += 1;
            }
        };
        each_expr(functions, handlers, init, &mut count);
    }
    let mut method_of: HashMap<usize, GlobalId> = HashMap::new();
    for (g, c) in candidates.iter_mut() {
        for f in c.keys.iter().filter_map(|(_, f)| *f) {
            if refs.get(f.index()).copied() != Some(1) || method_of.insert(f.index(), *g).is_some() {
                c.ok = false;
            }
        }
    }
    let names_of: Vec<&str> = candidates.keys().map(|g| names.get(g.index()).copied().unwrap_or("")).collect();
    let mut checker = Checker { candidates, this_of: None, names: &names_of, poisoned: false };
    for (i, f) in functions.iter_mut().enumerate() {
        checker.this_of = method_of.get(&i).copied();
        if let exec::Body::Native(body) = &mut f.body {
            checker.stmts(body);
        }
    }
    checker.this_of = None;
    for h in handlers.iter_mut() {
        checker.stmts(h);
    }
    checker.stmts(init);
    for initial in globals.iter_mut() {
        checker.expr(initial);
    }
    if checker.poisoned {
        return None;
    }
    Some(method_of)
}

/// Gives each data key of every candidate a global and rewrites the code;
/// false when the post has no global ids left.
fn rewrite(
    candidates: &mut HashMap<GlobalId, Candidate>,
    method_of: &HashMap<usize, GlobalId>,
    functions: &mut [exec::Function],
    handlers: &mut [Vec<Stmt>],
    init: &mut Vec<Stmt>,
    globals: &mut Vec<Expr>,
) -> bool {
    // A global for each data key, starting `undefined` as the object's
    // global did before the one-time code set it.
    for c in candidates.values_mut() {
        c.fields.clear();
        for (_, method) in &c.keys {
            if method.is_some() {
                c.fields.push(None);
                continue;
            }
            let Some(id) = GlobalId::from_usize(globals.len()) else { return false };
            globals.push(Expr::Undefined);
            c.fields.push(Some(id));
        }
    }
    let mut rewriter = Rewriter { candidates, this_of: None };
    for (i, f) in functions.iter_mut().enumerate() {
        rewriter.this_of = method_of.get(&i).copied();
        if let exec::Body::Native(body) = &mut f.body {
            rewriter.stmts(body);
        }
        if rewriter.this_of.is_some() {
            // Its `this` is read through the object's globals only.
            f.uses_this = false;
        }
    }
    rewriter.this_of = None;
    for h in handlers.iter_mut() {
        rewriter.stmts(h);
    }
    rewriter.stmts(init);
    true
}

/// Reads a temporary that copies a global (`t = g; t.k = t.k + 1`, as the
/// front ends lower a compound assignment to a property) as the global in
/// the statement after the copy, and drops the copy when nothing else
/// reads the temporary. `copied(g)` says the global is never assigned
/// after it is first read, so `t` and `g` hold the same value there.
fn read_through(body: &mut Vec<Stmt>, copied: &dyn Fn(GlobalId) -> bool) {
    let mut temps = Vec::new();
    through(body, copied, &mut temps);
    if temps.is_empty() {
        return;
    }
    let mut read = Vec::new();
    reads(body, &mut read);
    let dead = |k: &postc_ir::LocalId| !read.contains(k);
    let dead: Vec<_> = temps.into_iter().filter(|k| dead(k)).collect();
    if !dead.is_empty() {
        drop_copies(body, &dead, copied);
    }
}

fn through(body: &mut [Stmt], copied: &dyn Fn(GlobalId) -> bool, temps: &mut Vec<postc_ir::LocalId>) {
    for i in 0..body.len() {
        if let Stmt::Assign(Place::Local(k), source) = &body[i]
            && is_copied(source, copied)
            && i + 1 < body.len()
        {
            let (k, source) = (*k, source.clone());
            let next = &mut body[i + 1];
            if matches!(next, Stmt::SetMember { .. } | Stmt::Eval(_) | Stmt::Assign(..) | Stmt::Return(_)) {
                next.for_each_expr_mut(|e| substitute(e, k, &source));
                if !temps.contains(&k) {
                    temps.push(k);
                }
            }
        }
        body[i].for_each_body_mut(|b| through(b, copied, temps));
    }
}

/// Whether a temporary's value may be read through: `this` (the same
/// for a whole call), or a global `copied` says is never assigned once
/// read.
fn is_copied(source: &Expr, copied: &dyn Fn(GlobalId) -> bool) -> bool {
    match source {
        Expr::This => true,
        Expr::Global(g) => copied(*g),
        _ => false,
    }
}

fn substitute(e: &mut Expr, k: postc_ir::LocalId, source: &Expr) {
    if matches!(e, Expr::Local(j) if *j == k) {
        *e = source.clone();
        return;
    }
    e.for_each_operand_mut(|a| substitute(a, k, source));
}

/// The locals statements read, at any depth.
fn reads(body: &mut [Stmt], out: &mut Vec<postc_ir::LocalId>) {
    for s in body {
        s.for_each_expr_mut(|e| e.for_each_local_mut(&mut |k| out.push(*k)));
        s.for_each_named_local_mut(|u, k| {
            if u != exec::LocalUse::Write {
                out.push(*k);
            }
        });
        s.for_each_body_mut(|b| reads(b, out));
    }
}

fn drop_copies(body: &mut Vec<Stmt>, dead: &[postc_ir::LocalId], copied: &dyn Fn(GlobalId) -> bool) {
    body.retain(
        |s| !matches!(s, Stmt::Assign(Place::Local(k), source) if dead.contains(k) && is_copied(source, copied)),
    );
    for s in body {
        s.for_each_body_mut(|b| drop_copies(b, dead, copied));
    }
}

/// The globals assigned an object literal before any post code runs, by
/// a top-level statement of the one-time code or of a function it calls
/// (with no arguments) and nothing else makes or calls.
fn find(
    functions: &mut [exec::Function],
    handlers: &mut [Vec<Stmt>],
    init: &mut [Stmt],
) -> HashMap<GlobalId, Candidate> {
    let mut found = HashMap::new();
    let mut ran = false;
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
    let consider = |s: &mut Stmt, ran: &mut bool, found: &mut HashMap<GlobalId, Candidate>| {
        if let Stmt::Assign(Place::Global(g), Expr::Object(props)) = s
            && !*ran
            && !found.contains_key(g)
            && let Some(c) = candidate(props)
        {
            found.insert(*g, c);
        }
        *ran |= runs_code_stmt(s);
    };
    for s in init.iter_mut() {
        if let Stmt::Eval(Expr::Call(f, args)) = s
            && args.is_empty()
            && calls.get(f.index()).copied() == Some(1)
            && let Some(exec::Function { body: exec::Body::Native(body), .. }) = functions.get_mut(f.index())
        {
            for s in body.iter_mut() {
                consider(s, &mut ran, &mut found);
            }
            continue;
        }
        consider(s, &mut ran, &mut found);
    }
    found
}

/// The candidate an object literal makes: plain, distinct keys, each a
/// value made without running post code, methods capturing nothing.
fn candidate(props: &mut [(exec::Text, Expr)]) -> Option<Candidate> {
    let mut keys: Vec<(exec::Text, Option<FunctionId>)> = Vec::new();
    for (k, v) in props.iter_mut() {
        if &**k == "__proto__" || keys.iter().any(|(seen, _)| **seen == **k) || runs_code(v) {
            return None;
        }
        let method = match v {
            Expr::Closure { function, captures } if captures.is_empty() => Some(*function),
            _ => None,
        };
        keys.push((k.clone(), method));
    }
    Some(Candidate { keys, ok: true, fields: Vec::new() })
}

/// Whether evaluating an expression may run post code (a call, a
/// method, a constructor, the host).
fn runs_code(e: &mut Expr) -> bool {
    if matches!(
        e,
        Expr::Call(..)
            | Expr::CallValue(..)
            | Expr::Invoke { .. }
            | Expr::Host { .. }
            | Expr::Builtin(Builtin::Construct, _)
    ) {
        return true;
    }
    let mut found = false;
    e.for_each_operand_mut(|a| found |= runs_code(a));
    found
}

pub(super) fn runs_code_stmt(s: &mut Stmt) -> bool {
    let mut found = false;
    s.for_each_expr_mut(|e| found |= runs_code(e));
    s.for_each_body_mut(|b| found |= b.iter_mut().any(runs_code_stmt));
    found
}

/// Calls `f` on every statement of the post's code, at every depth (on a
/// statement before the statements of its bodies).
pub(super) fn each_stmt(
    functions: &mut [exec::Function],
    handlers: &mut [Vec<Stmt>],
    init: &mut [Stmt],
    f: &mut dyn FnMut(&mut Stmt),
) {
    fn stmts(body: &mut [Stmt], f: &mut dyn FnMut(&mut Stmt)) {
        for s in body {
            f(s);
            s.for_each_body_mut(|b| stmts(b, f));
        }
    }
    for function in functions {
        if let exec::Body::Native(body) = &mut function.body {
            stmts(body, f);
        }
    }
    for h in handlers {
        stmts(h, f);
    }
    stmts(init, f);
}

/// Calls `f` on every expression of the post's code, at every depth
/// (on an expression before the expressions it is made of).
pub(super) fn each_expr(
    functions: &mut [exec::Function],
    handlers: &mut [Vec<Stmt>],
    init: &mut [Stmt],
    f: &mut dyn FnMut(&mut Expr),
) {
    fn expr(e: &mut Expr, f: &mut dyn FnMut(&mut Expr)) {
        f(e);
        e.for_each_operand_mut(|a| expr(a, f));
    }
    each_stmt(functions, handlers, init, &mut |s| s.for_each_expr_mut(|e| expr(e, f)));
}

/// The text of a constant key.
fn key(e: &Expr) -> Option<&str> {
    match e {
        Expr::Text(t) => Some(t),
        _ => None,
    }
}

/// Checks every use of the candidates' globals and of `this`.
struct Checker<'a> {
    candidates: &'a mut HashMap<GlobalId, Candidate>,
    /// The candidate whose method this code is.
    this_of: Option<GlobalId>,
    /// The candidates' global names.
    names: &'a [&'a str],
    /// `this` used in a way that may reach a candidate.
    poisoned: bool,
}

impl Checker<'_> {
    fn fail(&mut self, g: GlobalId) {
        if let Some(c) = self.candidates.get_mut(&g) {
            c.ok = false;
        }
    }

    /// Whether `k` of the object `object` stands for is a data key, a
    /// method (`call`), or neither; `None` when `object` is neither a
    /// candidate's global nor `this` (then it is checked as any other
    /// expression).
    fn access(&mut self, object: &Expr, k: Option<&str>, call: bool) -> Option<()> {
        let g = match object {
            Expr::Global(g) if self.candidates.contains_key(g) => *g,
            Expr::This => match self.this_of {
                Some(g) => g,
                None => {
                    // `this` of other code: the global object, or another
                    // object; a constant key naming no candidate cannot
                    // reach one.
                    if k.is_none_or(|k| self.names.contains(&k)) {
                        self.poisoned = true;
                    }
                    return Some(());
                }
            },
            _ => return None,
        };
        let fits = match (k, self.candidates.get(&g)) {
            (Some(k), Some(c)) => {
                if call {
                    c.method(k).is_some()
                } else {
                    c.data(k)
                }
            }
            _ => false,
        };
        if !fits {
            self.fail(g);
        }
        Some(())
    }

    fn expr(&mut self, e: &mut Expr) {
        match e {
            Expr::Member(o, k, _) if self.access(o, key(k), false).is_some() => {
                if key(k).is_none() {
                    self.expr(k);
                }
            }
            Expr::Invoke { object, method, args, .. } if self.access(object, Some(method), true).is_some() => {
                args.iter_mut().for_each(|a| self.expr(a));
            }
            Expr::Global(g) => {
                let g = *g;
                self.fail(g);
            }
            Expr::This => {
                match self.this_of {
                    Some(g) => self.fail(g),
                    None => self.poisoned = true,
                };
            }
            e => e.for_each_operand_mut(|a| self.expr(a)),
        }
    }

    fn stmts(&mut self, body: &mut [Stmt]) {
        for s in body {
            match s {
                Stmt::SetMember { object, key: k, value, .. } => {
                    if self.access(object, key(k), false).is_none() {
                        self.expr(object);
                        self.expr(k);
                    } else if key(k).is_none() {
                        self.expr(k);
                    }
                    self.expr(value);
                }
                Stmt::Assign(Place::Global(g), value) if self.candidates.contains_key(g) => {
                    let g = *g;
                    // The defining assignment is the one that holds a
                    // literal of exactly the candidate's keys; there is one.
                    let defining = match value {
                        Expr::Object(props) => self.candidates.get(&g).is_some_and(|c| {
                            c.fields.is_empty()
                                && props.len() == c.keys.len()
                                && props.iter().zip(&c.keys).all(|((k, _), (ck, _))| **k == **ck)
                        }),
                        _ => false,
                    };
                    if defining && let Some(c) = self.candidates.get_mut(&g) {
                        // Marks it seen: a second is another assignment.
                        c.fields.push(None);
                    } else {
                        self.fail(g);
                    }
                    self.expr(value);
                }
                s => {
                    s.for_each_expr_mut(|e| self.expr(e));
                    s.for_each_body_mut(|b| self.stmts(b));
                }
            }
        }
    }
}

/// Rewrites the uses of replaced objects.
struct Rewriter<'a> {
    candidates: &'a HashMap<GlobalId, Candidate>,
    this_of: Option<GlobalId>,
}

impl Rewriter<'_> {
    /// The candidate an object expression stands for here.
    fn object(&self, e: &Expr) -> Option<&Candidate> {
        match e {
            Expr::Global(g) => self.candidates.get(g),
            Expr::This => self.this_of.and_then(|g| self.candidates.get(&g)),
            _ => None,
        }
    }

    /// The global of data key `k` of the object `e` stands for.
    fn field(&self, e: &Expr, k: &Expr) -> Option<GlobalId> {
        let c = self.object(e)?;
        c.fields.get(c.key(key(k)?)?).copied().flatten()
    }

    fn expr(&self, e: &mut Expr) {
        e.for_each_operand_mut(|a| self.expr(a));
        let replaced = match e {
            Expr::Member(o, k, _) => self.field(o, k).map(Expr::Global),
            Expr::Invoke { object, method, args, .. } => {
                self.object(object).and_then(|c| c.method(method)).map(|f| Expr::Call(f, std::mem::take(args)))
            }
            _ => None,
        };
        if let Some(r) = replaced {
            *e = r;
        }
    }

    fn stmts(&self, body: &mut Vec<Stmt>) {
        let mut out = Vec::with_capacity(body.len());
        for mut s in std::mem::take(body) {
            let field = match &s {
                Stmt::SetMember { object, key: k, .. } => self.field(object, k),
                _ => None,
            };
            let defining = match &s {
                Stmt::Assign(Place::Global(g), Expr::Object(_)) => self.candidates.get(g),
                _ => None,
            };
            match (&mut s, field, defining) {
                (Stmt::SetMember { value, .. }, Some(g), _) => {
                    let mut value = std::mem::replace(value, Expr::Undefined);
                    self.expr(&mut value);
                    out.push(Stmt::Assign(Place::Global(g), value));
                }
                (Stmt::Assign(_, Expr::Object(props)), _, Some(c)) => {
                    // The defining literal: each data key's value, in order.
                    for ((_, v), field) in props.iter_mut().zip(&c.fields) {
                        if let Some(field) = field {
                            let mut v = std::mem::replace(v, Expr::Undefined);
                            self.expr(&mut v);
                            out.push(Stmt::Assign(Place::Global(*field), v));
                        }
                    }
                }
                _ => {
                    s.for_each_expr_mut(|e| self.expr(e));
                    s.for_each_body_mut(|b| self.stmts(b));
                    out.push(s);
                }
            }
        }
        *body = out;
    }
}
