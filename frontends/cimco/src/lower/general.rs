//! The general lowering: every function of a post to native IR, with
//! JavaScript's values as the IR holds them (objects, arrays, `undefined`,
//! functions as values), and no inference of what a name holds.
//!
//! The shaped lowering ([`super::native`]) turns the functions it can prove
//! plain into fast IR and leaves the rest to Rhai. When it leaves any
//! function of a post to Rhai, the post is lowered again here, whole: each
//! function, `__postc_init` and postc's bridges, so that every value keeps
//! one representation. A post with something this lowering has no form for
//! either (`new` of anything but `Error`) keeps the shaped lowering's
//! result, and
//! [`Why`] says what.
//!
//! How each construct lowers:
//!
//! - locals are slots; a closure's captured locals are its first
//!   parameters, passed by value when the closure is made (at each mention
//!   of a nested function); a captured local that changes after it is
//!   first given (in its function or in a closure) lives in a cell, a
//!   one-item array made when its function starts, so that the function
//!   and every closure share it (reads and writes go through item 0);
//! - an assignment or `++` inside an expression runs as statements before
//!   it, with the operands to its left kept in temporaries so that they are
//!   read in JavaScript's order; `&&`, `||` and `?:` keep their short
//!   circuit by running such statements under an `if`;
//! - `switch`: the matching case's index, then each case's body under
//!   `if (index <= k)` inside a loop that runs once, so that a case falls
//!   through and `break` leaves; a `continue` in it sets a flag the loop
//!   around reads;
//! - `do ... while`: a loop that tests its condition from the second pass
//!   on; `for`: a `While` with its update as the loop's step; `for ... in`:
//!   the keys (`Builtin::Keys`) walked by index;
//! - the drilling and compensation data CNC-Calc hands its entry points
//!   are host calls (`Expr::Host`) the CIMCO host answers;
//! - `F.prototype` is a property of the function value (a function that
//!   captures nothing is one value, so it has one `prototype`; the
//!   `prototype` of a nested function that captures locals is refused);
//!   `String.prototype` and the other built-in constructors' are
//!   `Builtin::Prototype`, `Object.create(p)` is `Builtin::CreateObject`,
//!   and `v instanceof F` is `Builtin::InstanceOf` of `v` and
//!   `F.prototype`;
//! - a regular expression literal is `Expr::Regex`, with its span: the
//!   runtime compiles its pattern once (and `postc_driver` refuses one
//!   it cannot run when the post is compiled, JS108).

use std::collections::{HashMap, HashSet};

use postc_ir::{
    BinaryOp as IrBin, Body, Builtin, Expr as Ir, Function as IrFunction, FunctionId, LocalId, OutputRef, Place, Site,
    Span, Stmt as IrStmt, UnaryOp as IrUn,
};

use crate::ast::*;
use crate::host_names as names;

use super::builtins;
use super::layout::{self, Layout};
use super::model::Model;
use super::native::{Why, binary_op, to_number};
use super::scope::{FnId, Symbol};
use super::setup::{Binding, Setup};

type R<T> = Result<T, Why>;

fn why(span: Span, what: impl Into<String>) -> Why {
    Why { what: what.into(), span }
}

/// What the whole-post lowering shares between functions.
pub struct Shared<'c, 'a> {
    pub model: &'c Model<'a>,
    pub setup: &'c Setup,
    pub layout: &'c mut Layout,
    /// The IR function of each nested JavaScript function, and its
    /// captures (the enclosing function's local and its slot there).
    nested: HashMap<FnId, (FunctionId, Vec<(FnId, usize)>)>,
    /// Nested functions still to lower.
    pending: Vec<FnId>,
    /// The locals that live in cells: captured, and given a value more
    /// than once (by their function or by a closure).
    cells: HashSet<(FnId, usize)>,
    /// The post is a Fusion post: its host is JavaScript the program
    /// holds, so a name it never defines is a `ReferenceError` when it
    /// runs, unless Autodesk's host declares it (then the post is refused:
    /// postc's host lacks it).
    pub fusion: bool,
    /// Host functions that stop the post when called (postc does not
    /// run them yet), and the calls of the post's own file to them: `postc
    /// check` names each (JS110).
    pub stubs: std::collections::HashSet<String>,
    pub stub_calls: Vec<(String, Span)>,
    /// The post's own file (not the host's).
    pub post_file: Option<postc_ir::FileId>,
}

impl<'c, 'a> Shared<'c, 'a> {
    pub fn new(model: &'c Model<'a>, setup: &'c Setup, layout: &'c mut Layout) -> Self {
        let cells = cells(model);
        Shared {
            model,
            setup,
            layout,
            nested: HashMap::new(),
            pending: Vec::new(),
            cells,
            fusion: false,
            stubs: Default::default(),
            stub_calls: Vec::new(),
            post_file: None,
        }
    }

    /// A name no one defines, in a Fusion post: refused when Fusion's
    /// host has it, else JavaScript's `ReferenceError` when it runs.
    fn undeclared(&self, name: &str, at: Span) -> R<Ir> {
        if crate::fusion::api::is_declared(name) {
            return Err(why(at, format!("uses `{name}` of Fusion's host, which postc does not provide yet")));
        }
        Ok(Ir::Undeclared { name: name.to_string(), span: Site(Some(at)) })
    }

    /// The IR function of nested function `id` (added on first mention)
    /// and what it captures.
    fn nested(&mut self, id: FnId) -> (FunctionId, Vec<(FnId, usize)>) {
        if let Some(n) = self.nested.get(&id) {
            return n.clone();
        }
        let name = self.model.scopes.funcs[id].name.clone().unwrap_or_else(|| format!("__postc_closure_{id}"));
        let f = self.layout.add_fn(&name);
        let mut captures = captures(self.model, id);
        let info = &self.model.scopes.funcs[id];
        if let (Some(func), Some(parent)) = (info.func, info.parent)
            && func.arrow
            && uses_this(func)
        {
            captures.push((parent, LEXICAL_THIS));
        }
        self.nested.insert(id, (f, captures.clone()));
        self.pending.push(id);
        (f, captures)
    }

    /// Lowers a top-level function (`id`) or the top-level statements
    /// (`id` 0, with `body`).
    pub fn function(&mut self, id: FnId, body: &[Stmt], entry: bool, span: Span) -> R<IrFunction> {
        let info = &self.model.scopes.funcs[id];
        let mut g = General::new(self, id, Vec::new());
        g.entry = entry;
        let mut stmts = g.cells_made();
        stmts.extend(g.body(body)?);
        let slots = g.slots;
        let info_name = info.name.clone().unwrap_or_default();
        Ok(IrFunction {
            name: info_name,
            params: info.params.clone(),
            slots,
            locals: info.locals.iter().skip(info.params.len()).cloned().collect(),
            body: Body::Native(stmts),
            span: Some(span),
            why_script: None,
            source: Vec::new(),
            uses_arguments: info.uses_arguments,
            starts_undefined: true,
        })
    }

    /// Lowers every nested function mentioned so far (and those they
    /// mention), in the order their ids were given.
    pub fn nested_functions(&mut self) -> R<Vec<(FunctionId, IrFunction)>> {
        let mut out = Vec::new();
        while let Some(id) = self.pending.pop() {
            let (fid, captures) = self.nested[&id].clone();
            let info = &self.model.scopes.funcs[id];
            let func = info.func.ok_or_else(|| why(Span::default(), "has a function without a body"))?;
            // `arguments` is what the caller passed: an arrow function's
            // is the function's around it; a closure's captures come
            // first in its frame, so its `arguments` is the rest.
            if info.uses_arguments && func.arrow {
                return Err(why(func.span, "reads `arguments` in an arrow function"));
            }
            let captured = captures.len();
            let mut params: Vec<String> = captures
                .iter()
                .map(|&(f, s)| match s {
                    LEXICAL_THIS => "__postc_this".to_string(),
                    s => self.model.scopes.funcs[f].locals[s].clone(),
                })
                .collect();
            params.extend(info.params.iter().cloned());
            let locals = info.locals.iter().skip(info.params.len()).cloned().collect();
            let mut g = General::new(self, id, captures);
            let mut stmts = Vec::new();
            if info.uses_arguments && captured > 0 {
                let copy = g.temp();
                g.arguments = Some(copy);
                stmts.push(IrStmt::Assign(
                    Place::Local(copy),
                    Ir::Invoke {
                        object: Box::new(Ir::Arguments),
                        method: "slice".into(),
                        args: vec![Ir::Number(captured as f64)],
                        span: None,
                    },
                ));
            }
            stmts.extend(g.cells_made());
            stmts.extend(g.body(&func.body)?);
            let slots = g.slots;
            out.push((
                fid,
                IrFunction {
                    name: self.layout.fn_names[fid.index()].clone(),
                    params,
                    slots,
                    locals,
                    body: Body::Native(stmts),
                    span: Some(func.span),
                    why_script: None,
                    source: Vec::new(),
                    uses_arguments: info.uses_arguments,
                    starts_undefined: true,
                },
            ));
        }
        out.sort_by_key(|(f, _)| f.index());
        Ok(out)
    }
}

/// The capture of an arrow function that reads `this`: the `this` of the
/// function around it, in the place of a local's slot.
const LEXICAL_THIS: usize = usize::MAX - 1;

/// Whether an arrow function reads `this`, its own or that of an arrow
/// function inside it (whose `this` is the same).
fn uses_this(f: &Function) -> bool {
    struct This(bool);
    impl<'a> super::scope::Visit<'a> for This {
        fn expr(&mut self, e: &'a Expr) -> bool {
            match &e.kind {
                ExprKind::This => self.0 = true,
                // The walk does not go into functions: an arrow function's
                // body is looked at here, another function's `this` is its own.
                ExprKind::Function(inner) => self.0 |= inner.arrow && uses_this(inner),
                _ => {}
            }
            !self.0
        }
        fn function_decl(&mut self, _f: &'a Function) {}
    }
    let mut v = This(false);
    super::scope::walk_stmts(&f.body, &mut v);
    v.0
}

/// The function `func` declares under `name` (`function name() {...}` in
/// its body), if it declares one.
fn declared_in(model: &Model, func: FnId, name: &str) -> Option<FnId> {
    let decl = model.scopes.funcs[func].nested.iter().find(|f| f.name.as_ref().is_some_and(|n| n.name == name))?;
    model.scopes.id_of(decl)
}

/// The locals of enclosing functions that nested function `id` (or a
/// function nested in it) reads or writes, each once, in order of first use.
/// A function declared in an enclosing function and named here is made
/// here as a value ([`General::closure`]), so what it captures from
/// functions around `id` is captured too, transitively.
fn captures(model: &Model, id: FnId) -> Vec<(FnId, usize)> {
    struct Free<'m, 'a> {
        model: &'m Model<'a>,
        at: FnId,
        root: FnId,
        found: Vec<(FnId, usize)>,
        /// The enclosing functions' declarations walked for their captures.
        walked: Vec<FnId>,
    }
    impl<'a> super::scope::Visit<'a> for Free<'_, '_> {
        fn expr(&mut self, e: &'a Expr) -> bool {
            match &e.kind {
                ExprKind::Ident(name) => self.name(name),
                ExprKind::Function(f) => self.function(f),
                _ => return true,
            }
            false
        }
        fn stmt(&mut self, s: &'a Stmt) -> bool {
            match &s.kind {
                StmtKind::ForIn { name, .. } => self.name(&name.name),
                StmtKind::Var(ds) => ds.iter().for_each(|d| self.name(&d.name.name)),
                _ => {}
            }
            true
        }
        fn function_decl(&mut self, f: &'a Function) {
            self.function(f);
        }
    }
    impl Free<'_, '_> {
        fn name(&mut self, name: &str) {
            if let Symbol::Local { func, slot } = self.model.scopes.resolve(name, self.at)
                && slot != usize::MAX
                && func != self.at
                && self.encloses(func)
            {
                if !self.found.contains(&(func, slot)) {
                    self.found.push((func, slot));
                }
                self.declared(func, name);
            }
        }
        /// A function `func` declares under `name`: what it captures from
        /// functions around the root, captured as well.
        fn declared(&mut self, func: FnId, name: &str) {
            let Some(id) = declared_in(self.model, func, name) else { return };
            let Some(decl) = self.model.scopes.funcs[id].func else { return };
            if id == self.root || self.walked.contains(&id) {
                return;
            }
            self.walked.push(id);
            let outer = self.at;
            self.at = id;
            super::scope::walk_stmts(&decl.body, self);
            self.at = outer;
        }
        /// Whether `func` is a function around the root (not the root or
        /// one nested in it).
        fn encloses(&self, func: FnId) -> bool {
            let mut cur = Some(self.root);
            while let Some(c) = cur {
                if c == func {
                    return c != self.root;
                }
                cur = self.model.scopes.funcs[c].parent;
            }
            false
        }
        fn function(&mut self, f: &Function) {
            let Some(inner) = self.model.scopes.id_of(f) else { return };
            let outer = self.at;
            self.at = inner;
            super::scope::walk_stmts(&f.body, self);
            self.at = outer;
        }
    }
    let Some(func) = model.scopes.funcs[id].func else { return Vec::new() };
    let mut v = Free { model, at: id, root: id, found: Vec::new(), walked: Vec::new() };
    super::scope::walk_stmts(&func.body, &mut v);
    v.found
}

/// The captured locals that need a cell: given a value more than once
/// (a parameter counts as given once), counting what closures assign, or
/// given one by a function nested in the one that has it (a `var x;`
/// that a closure sets).
fn cells(model: &Model) -> HashSet<(FnId, usize)> {
    let mut given: HashMap<(FnId, usize), usize> = HashMap::new();
    let mut captured = HashSet::new();
    for (id, info) in model.scopes.funcs.iter().enumerate() {
        for slot in 0..info.params.len() {
            *given.entry((id, slot)).or_default() += 1;
        }
        for local in assignments(model, id) {
            // Set from a nested function: a cell whatever the count.
            let n = if local.0 == id { 1 } else { 2 };
            *given.entry(local).or_default() += n;
        }
        if info.parent.is_some() {
            captured.extend(captures(model, id));
        }
    }
    captured.into_iter().filter(|l| given.get(l).is_some_and(|&n| n > 1)).collect()
}

/// Each assignment function `func` makes (`var` with a value, `=`, `+=`,
/// `++`, `for ... in`) to a local, its own or one of a function around it,
/// not counting nested functions: the local assigned, once per assignment.
fn assignments(model: &Model, func: FnId) -> Vec<(FnId, usize)> {
    struct Count<'m, 'a> {
        model: &'m Model<'a>,
        func: FnId,
        found: Vec<(FnId, usize)>,
    }
    impl Count<'_, '_> {
        fn name(&mut self, name: &str) {
            if let Symbol::Local { func, slot } = self.model.scopes.resolve(name, self.func)
                && slot != usize::MAX
            {
                self.found.push((func, slot));
            }
        }
    }
    impl<'a> super::scope::Visit<'a> for Count<'_, '_> {
        fn expr(&mut self, e: &'a Expr) -> bool {
            match &e.kind {
                ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } => {
                    if let ExprKind::Ident(n) = &target.kind {
                        self.name(n);
                    }
                    true
                }
                ExprKind::Function(_) => false,
                _ => true,
            }
        }
        fn stmt(&mut self, s: &'a Stmt) -> bool {
            match &s.kind {
                StmtKind::Var(ds) => ds.iter().filter(|d| d.init.is_some()).for_each(|d| self.name(&d.name.name)),
                StmtKind::ForIn { name, .. } => self.name(&name.name),
                StmtKind::For { init: Some(ForInit::Var(ds)), .. } => {
                    ds.iter().filter(|d| d.init.is_some()).for_each(|d| self.name(&d.name.name))
                }
                _ => {}
            }
            true
        }
        fn function_decl(&mut self, _f: &'a Function) {}
    }
    let Some(f) = model.scopes.funcs[func].func else { return Vec::new() };
    let mut c = Count { model, func, found: Vec::new() };
    super::scope::walk_stmts(&f.body, &mut c);
    c.found
}

/// A loop or `switch` being lowered, for `break` and `continue`.
enum Jump {
    Loop,
    /// A `switch`: `continue` inside it sets this flag and leaves.
    Switch {
        continue_flag: Option<LocalId>,
    },
}

struct General<'s, 'c, 'a> {
    shared: &'s mut Shared<'c, 'a>,
    at: FnId,
    captures: Vec<(FnId, usize)>,
    slots: u16,
    entry: bool,
    jumps: Vec<Jump>,
    /// Where `arguments` lives when it is not the frame's: in a nested
    /// function that captures locals, the frame starts with the captured
    /// values, so `arguments` is a copy of the frame past them, made as
    /// the function starts.
    arguments: Option<LocalId>,
}

impl<'s, 'c, 'a> General<'s, 'c, 'a> {
    fn new(shared: &'s mut Shared<'c, 'a>, at: FnId, captures: Vec<(FnId, usize)>) -> Self {
        let locals = shared.model.scopes.funcs[at].locals.len();
        let slots = (captures.len() + locals) as u16;
        General { shared, at, captures, slots, entry: false, jumps: Vec::new(), arguments: None }
    }

    fn model(&self) -> &'c Model<'a> {
        self.shared.model
    }

    fn temp(&mut self) -> LocalId {
        self.slots += 1;
        LocalId::new(self.slots - 1)
    }

    /// The cells of this function's own locals, made as it starts (a
    /// parameter's cell holds the value it was given).
    fn cells_made(&mut self) -> Vec<IrStmt> {
        let info = &self.model().scopes.funcs[self.at];
        let params = info.params.len();
        let mut out = Vec::new();
        for slot in 0..info.locals.len() {
            if self.shared.cells.contains(&(self.at, slot)) {
                let l = self.own(slot);
                let first = if slot < params { Ir::Local(l) } else { Ir::Undefined };
                out.push(IrStmt::Assign(Place::Local(l), Ir::Array(vec![first])));
            }
        }
        out
    }

    /// Whether a name is a local that lives in a cell.
    fn in_cell(&self, name: &str) -> bool {
        match self.model().scopes.resolve(name, self.at) {
            Symbol::Local { func, slot } => self.shared.cells.contains(&(func, slot)),
            _ => false,
        }
    }

    fn body(&mut self, body: &[Stmt]) -> R<Vec<IrStmt>> {
        let mut out = Vec::new();
        for s in body {
            self.stmt(s, &mut out)?;
        }
        Ok(out)
    }

    // ---- names ----

    /// The slot of local `slot` of the function being lowered.
    fn own(&self, slot: usize) -> LocalId {
        LocalId::new((self.captures.len() + slot) as u16)
    }

    /// Where a name lives, when it is a local (own or captured).
    fn local_of(&self, name: &str, at: Span) -> R<Option<LocalId>> {
        match self.model().scopes.resolve(name, self.at) {
            Symbol::Local { slot: usize::MAX, .. } => Ok(None),
            Symbol::Local { func, slot } if func == self.at => Ok(Some(self.own(slot))),
            Symbol::Local { func, slot } => match self.captures.iter().position(|&c| c == (func, slot)) {
                Some(p) => Ok(Some(LocalId::new(p as u16))),
                None => Err(why(
                    at,
                    format!("reads `{name}`, a local of a function around this one, which this function is not given"),
                )),
            },
            _ => Ok(None),
        }
    }

    /// The nested function declared under `name` in this function or one
    /// around it, if the name is one.
    fn nested_decl(&self, name: &str) -> Option<FnId> {
        let Symbol::Local { func, slot } = self.model().scopes.resolve(name, self.at) else { return None };
        if slot == usize::MAX {
            return None;
        }
        declared_in(self.model(), func, name)
    }

    /// A nested function as a value: its captures read now.
    fn closure(&mut self, id: FnId, at: Span) -> R<Ir> {
        let (function, captures) = self.shared.nested(id);
        let values = self.capture_values(&captures, at)?;
        Ok(Ir::Closure { function, captures: values })
    }

    /// The values a nested function captures, read here.
    fn capture_values(&self, captures: &[(FnId, usize)], at: Span) -> R<Vec<Ir>> {
        let mut values = Vec::with_capacity(captures.len());
        for &(func, slot) in captures {
            if slot == LEXICAL_THIS {
                values.push(self.this_value());
                continue;
            }
            let name = &self.model().scopes.funcs[func].locals[slot];
            let local = self.local_of(name, at)?.ok_or_else(|| why(at, format!("captures `{name}`")))?;
            values.push(Ir::Local(local));
        }
        Ok(values)
    }

    /// `this`: the object the function was called on, or, in an arrow
    /// function, the `this` it captured.
    fn this_value(&self) -> Ir {
        match self.captures.iter().position(|&(_, slot)| slot == LEXICAL_THIS) {
            Some(p) => Ir::Local(LocalId::new(p as u16)),
            None => Ir::This,
        }
    }

    fn global_value(&mut self, name: &str, at: Span) -> R<Ir> {
        match self.model().global(name) {
            Some(g) => {
                if let Some(c) = &g.constant {
                    return Ok(const_expr(c));
                }
                if let Some(b) = self.shared.setup.bindings.get(name) {
                    return Ok(Ir::Output(match *b {
                        Binding::Var(v) => OutputRef::Variable(v),
                        Binding::Format(f) => OutputRef::Format(f),
                    }));
                }
                self.shared
                    .layout
                    .global_index
                    .get(name)
                    .map(|g| Ir::Global(*g))
                    .ok_or_else(|| why(at, format!("reads `{name}`")))
            }
            None if self.shared.fusion && !matches!(name, "NaN" | "Infinity" | "undefined") => {
                self.shared.undeclared(name, at)
            }
            None => match builtins::constant(name) {
                Some(c) => Ok(const_expr(&c)),
                None => Err(why(at, format!("reads `{name}`, which the host gives no value"))),
            },
        }
    }

    fn ident(&mut self, name: &str, at: Span) -> R<Ir> {
        if let Some(id) = self.nested_decl(name) {
            return self.closure(id, at);
        }
        match self.model().scopes.resolve(name, self.at) {
            Symbol::Local { slot: usize::MAX, .. } => Ok(self.arguments.map_or(Ir::Arguments, Ir::Local)),
            Symbol::Local { .. } => {
                let l = Ir::Local(self.local_of(name, at)?.expect("a local"));
                Ok(if self.in_cell(name) { cell_item(l) } else { l })
            }
            Symbol::TopFn(i) => Ok(Ir::Closure { function: self.shared.layout.top_fn[i], captures: vec![] }),
            Symbol::Global(g) => self.global_value(&g, at),
        }
    }

    /// `object.prototype` where the object is a name that says more than
    /// a property read: the prototype of a built-in constructor
    /// (`String.prototype`), or a refusal. A nested function that captures
    /// locals is a new value at each mention (`Ir::Closure`), so it has no
    /// one `prototype` to read or set: the post is refused. `None` for the
    /// rest, a property read like any other.
    fn prototype(&self, object: &Expr, at: Span) -> R<Option<Ir>> {
        let ExprKind::Ident(name) = &object.kind else { return Ok(None) };
        if let Some(id) = self.nested_decl(name) {
            if !captures(self.model(), id).is_empty() {
                return Err(why(
                    at,
                    format!(
                        "uses the `prototype` of `{name}`, a nested function that captures locals of the function around it"
                    ),
                ));
            }
            return Ok(None);
        }
        let builtin =
            matches!(name.as_str(), "Object" | "Array" | "String" | "Number" | "Boolean" | "Function" | "RegExp");
        Ok((builtin && self.is_host(name)).then(|| Ir::Builtin(Builtin::Prototype, vec![Ir::Text(name.clone())])))
    }

    fn binding(&self, name: &str) -> Option<Binding> {
        match self.model().scopes.resolve(name, self.at) {
            Symbol::Global(g) => self.shared.setup.bindings.get(&g).copied(),
            _ => None,
        }
    }

    fn is_host(&self, name: &str) -> bool {
        matches!(self.model().scopes.resolve(name, self.at), Symbol::Global(_)) && self.model().global(name).is_none()
    }

    // ---- statements ----

    fn stmt(&mut self, s: &Stmt, out: &mut Vec<IrStmt>) -> R<()> {
        if self.shared.setup.done.contains(&s.span.start) {
            return Ok(());
        }
        // A statement of a Fusion post's own text that calls a function
        // (the host's API, most of them) is marked with its place: an
        // error raised in the host under it points back at it, and
        // `--trace` gives it as where the lines it writes come from.
        if self.shared.fusion && Some(s.span.file) == self.shared.post_file && calls(s) {
            out.push(IrStmt::Origin(s.span));
        }
        match &s.kind {
            StmtKind::Var(ds) => self.declare(ds, out)?,
            StmtKind::Function(_) => {}
            StmtKind::Expr(e) => self.effect(e, out)?,
            StmtKind::Block(b) => {
                for s in b {
                    self.stmt(s, out)?;
                }
            }
            StmtKind::Empty => {}
            StmtKind::If { branches, otherwise } => self.lower_if(branches, otherwise.as_deref(), out)?,
            StmtKind::While { cond, body } => {
                self.jumps.push(Jump::Loop);
                let b = self.nested_stmt(body);
                self.jumps.pop();
                let b = b?;
                out.push(self.while_loop(cond, b, vec![], s.span)?);
            }
            StmtKind::DoWhile { body, cond } => {
                // f = false; while (true) { if (f) { if (!cond) break; } f = true; body }
                let flag = self.temp();
                out.push(IrStmt::Assign(Place::Local(flag), Ir::Bool(false)));
                let mut test = Vec::new();
                let c = self.expr(cond, &mut test)?;
                test.push(IrStmt::If {
                    branches: vec![(Ir::Unary(IrUn::Not, Box::new(c)), vec![IrStmt::Break])],
                    otherwise: vec![],
                });
                self.jumps.push(Jump::Loop);
                let b = self.nested_stmt(body);
                self.jumps.pop();
                let mut inner = vec![
                    IrStmt::If { branches: vec![(Ir::Local(flag), test)], otherwise: vec![] },
                    IrStmt::Assign(Place::Local(flag), Ir::Bool(true)),
                ];
                inner.extend(b?);
                out.push(IrStmt::While { cond: Ir::Bool(true), body: inner, span: Some(s.span), step: vec![] });
            }
            StmtKind::For { init, test, update, body } => {
                match init {
                    Some(ForInit::Var(ds)) => self.declare(ds, out)?,
                    Some(ForInit::Expr(e)) => self.effect(e, out)?,
                    None => {}
                }
                let mut step = Vec::new();
                if let Some(u) = update {
                    self.effect(u, &mut step)?;
                }
                self.jumps.push(Jump::Loop);
                let b = self.nested_stmt(body);
                self.jumps.pop();
                let b = b?;
                match test {
                    Some(t) => out.push(self.while_loop(t, b, step, s.span)?),
                    None => out.push(IrStmt::While { cond: Ir::Bool(true), body: b, span: Some(s.span), step }),
                }
            }
            StmtKind::ForIn { name, object, body, .. } => {
                let mut pre = Vec::new();
                let o = self.expr(object, &mut pre)?;
                out.extend(pre);
                let keys = self.temp();
                let i = self.temp();
                out.push(IrStmt::Assign(Place::Local(keys), Ir::Builtin(Builtin::Keys, vec![o])));
                out.push(IrStmt::Assign(Place::Local(i), Ir::Number(0.0)));
                let target = Expr::new(ExprKind::Ident(name.name.clone()), name.span);
                let t = self.name_target(&target)?;
                let mut b = vec![set(t, member(Ir::Local(keys), Ir::Local(i), None))];
                self.jumps.push(Jump::Loop);
                let inner = self.nested_stmt(body);
                self.jumps.pop();
                b.extend(inner?);
                let len = member(Ir::Local(keys), Ir::Text("length".into()), None);
                out.push(IrStmt::While {
                    cond: Ir::Binary(IrBin::JsLt, Box::new(Ir::Local(i)), Box::new(len)),
                    body: b,
                    span: Some(s.span),
                    step: vec![IrStmt::Assign(
                        Place::Local(i),
                        Ir::Binary(IrBin::Add, Box::new(Ir::Local(i)), Box::new(Ir::Number(1.0))),
                    )],
                });
            }
            StmtKind::Switch { discriminant, cases } => self.switch(discriminant, cases, s.span, out)?,
            StmtKind::Break => out.push(IrStmt::Break),
            StmtKind::Continue => match self.jumps.last() {
                Some(Jump::Switch { .. }) => {
                    let f = self.switch_flag();
                    out.push(IrStmt::Assign(Place::Local(f), Ir::Bool(true)));
                    out.push(IrStmt::Break);
                }
                _ => out.push(IrStmt::Continue),
            },
            StmtKind::Return(e) => {
                let v = match e {
                    Some(e) => {
                        let mut pre = Vec::new();
                        let v = self.expr(e, &mut pre)?;
                        out.extend(pre);
                        Some(v)
                    }
                    None => Some(Ir::Undefined),
                };
                if self.entry {
                    out.push(IrStmt::Origin(s.span));
                }
                out.push(IrStmt::Return(v));
            }
            StmtKind::Throw(e) => {
                let mut pre = Vec::new();
                let v = self.expr(e, &mut pre)?;
                out.extend(pre);
                out.push(IrStmt::Throw { value: v, span: Some(s.span) });
            }
            StmtKind::Try { block, handler, finalizer } => {
                let body = self.body(block)?;
                let catch = match handler {
                    Some(h) => {
                        let slot = self
                            .local_of(&h.param.name, h.param.span)?
                            .ok_or_else(|| why(h.param.span, "has a `catch` name that is not a local"))?;
                        Some((slot, self.body(&h.body)?))
                    }
                    None => None,
                };
                let finally = match finalizer {
                    Some(f) => self.body(f)?,
                    None => Vec::new(),
                };
                out.push(IrStmt::Try { body, catch, finally });
            }
            StmtKind::Error => return Err(why(s.span, "has a statement that does not parse")),
        }
        Ok(())
    }

    /// The `continue` flag of the innermost `switch`, made on first use.
    fn switch_flag(&mut self) -> LocalId {
        if let Some(Jump::Switch { continue_flag: Some(f) }) = self.jumps.last() {
            return *f;
        }
        let t = self.temp();
        if let Some(Jump::Switch { continue_flag }) = self.jumps.last_mut() {
            *continue_flag = Some(t);
        }
        t
    }

    fn nested_stmt(&mut self, s: &Stmt) -> R<Vec<IrStmt>> {
        let mut v = Vec::new();
        self.stmt(s, &mut v)?;
        Ok(v)
    }

    /// `while (cond) body`, with the statements `cond` needs run before
    /// each test.
    fn while_loop(&mut self, cond: &Expr, body: Vec<IrStmt>, step: Vec<IrStmt>, span: Span) -> R<IrStmt> {
        let mut pre = Vec::new();
        let c = self.expr(cond, &mut pre)?;
        if pre.is_empty() {
            return Ok(IrStmt::While { cond: c, body, span: Some(span), step });
        }
        pre.push(IrStmt::If {
            branches: vec![(Ir::Unary(IrUn::Not, Box::new(c)), vec![IrStmt::Break])],
            otherwise: vec![],
        });
        pre.extend(body);
        Ok(IrStmt::While { cond: Ir::Bool(true), body: pre, span: Some(span), step })
    }

    fn declare(&mut self, ds: &[VarDeclarator], out: &mut Vec<IrStmt>) -> R<()> {
        for d in ds {
            if let Some(init) = &d.init {
                let target = Expr::new(ExprKind::Ident(d.name.name.clone()), d.name.span);
                let mut pre = Vec::new();
                let v = self.expr(init, &mut pre)?;
                out.extend(pre);
                let t = self.name_target(&target)?;
                out.push(set(t, v));
            }
        }
        Ok(())
    }

    fn lower_if(&mut self, branches: &[IfBranch], otherwise: Option<&Stmt>, out: &mut Vec<IrStmt>) -> R<()> {
        let Some((first, rest)) = branches.split_first() else {
            if let Some(o) = otherwise {
                self.stmt(o, out)?;
            }
            return Ok(());
        };
        let mut pre = Vec::new();
        let c = self.expr(&first.cond, &mut pre)?;
        out.extend(pre);
        let then = self.nested_stmt(&first.body)?;
        let mut other = Vec::new();
        self.lower_if(rest, otherwise, &mut other)?;
        out.push(IrStmt::If { branches: vec![(c, then)], otherwise: other });
        Ok(())
    }

    fn switch(&mut self, disc: &Expr, cases: &[SwitchCase], span: Span, out: &mut Vec<IrStmt>) -> R<()> {
        let mut pre = Vec::new();
        let d = self.expr(disc, &mut pre)?;
        out.extend(pre);
        let t = self.temp();
        out.push(IrStmt::Assign(Place::Local(t), d));
        let index = self.temp();
        let default = cases.iter().position(|c| c.test.is_none()).unwrap_or(cases.len());
        // The tests in order, until one matches.
        let mut chain: Vec<IrStmt> = vec![IrStmt::Assign(Place::Local(index), Ir::Number(default as f64))];
        for (k, c) in cases.iter().enumerate().rev() {
            let Some(test) = &c.test else { continue };
            let mut pre = Vec::new();
            let v = self.expr(test, &mut pre)?;
            let cond = Ir::Binary(IrBin::StrictEq, Box::new(Ir::Local(t)), Box::new(v));
            pre.push(IrStmt::If {
                branches: vec![(cond, vec![IrStmt::Assign(Place::Local(index), Ir::Number(k as f64))])],
                otherwise: chain,
            });
            chain = pre;
        }
        out.extend(chain);
        self.jumps.push(Jump::Switch { continue_flag: None });
        let mut body = Vec::new();
        let mut result = Ok(());
        for (k, c) in cases.iter().enumerate() {
            match self.body(&c.body) {
                Ok(b) if b.is_empty() => {}
                Ok(b) => body.push(IrStmt::If {
                    branches: vec![(
                        Ir::Binary(IrBin::JsLe, Box::new(Ir::Local(index)), Box::new(Ir::Number(k as f64))),
                        b,
                    )],
                    otherwise: vec![],
                }),
                Err(e) => {
                    result = Err(e);
                    break;
                }
            }
        }
        let flag = match self.jumps.pop() {
            Some(Jump::Switch { continue_flag }) => continue_flag,
            _ => None,
        };
        result?;
        body.push(IrStmt::Break);
        if let Some(f) = flag {
            out.push(IrStmt::Assign(Place::Local(f), Ir::Bool(false)));
        }
        out.push(IrStmt::While { cond: Ir::Bool(true), body, span: Some(span), step: vec![] });
        if let Some(f) = flag {
            // A `continue` inside: on to the loop around, through the
            // flags of the switches in between.
            let leave = match self.jumps.last() {
                Some(Jump::Switch { .. }) => {
                    let outer = self.switch_flag();
                    vec![IrStmt::Assign(Place::Local(outer), Ir::Bool(true)), IrStmt::Break]
                }
                _ => vec![IrStmt::Continue],
            };
            out.push(IrStmt::If { branches: vec![(Ir::Local(f), leave)], otherwise: vec![] });
        }
        Ok(())
    }

    // ---- assignments ----

    /// A name as a target: item 0 of its cell, or its place.
    fn name_target(&mut self, target: &Expr) -> R<Target> {
        if let ExprKind::Ident(name) = &target.kind
            && self.in_cell(name)
            && let Some(l) = self.local_of(name, target.span)?
        {
            return Ok(Target::Member(Ir::Local(l), Box::new(Ir::Number(0.0)), None));
        }
        Ok(Target::Place(self.simple_place(target)?))
    }

    /// A name as a place (a local or a global), for `var`, `for ... in`
    /// and plain assignments.
    fn simple_place(&mut self, target: &Expr) -> R<Place> {
        let at = target.span;
        match &target.kind {
            ExprKind::Ident(name) => {
                if self.nested_decl(name).is_some() {
                    return Err(why(at, format!("assigns `{name}`, a function declared here")));
                }
                if let Some(l) = self.local_of(name, at)? {
                    if l.index() < self.captures.len() {
                        return Err(why(at, format!("assigns `{name}`, which this closure captured")));
                    }
                    return Ok(Place::Local(l));
                }
                match self.model().scopes.resolve(name, self.at) {
                    Symbol::Global(g) => self.global_place(&g, at),
                    Symbol::TopFn(_) => Err(why(at, format!("assigns `{name}`, a function of the post"))),
                    Symbol::Local { .. } => Err(why(at, "assigns `arguments`")),
                }
            }
            ExprKind::Member { .. } => match self.model().flattened_name(target) {
                Some(flat) => self.global_place(&flat, at),
                None => Err(why(at, "assigns a property as a simple place")),
            },
            _ => Err(why(at, "assigns something that is not a name")),
        }
    }

    fn global_place(&mut self, name: &str, at: Span) -> R<Place> {
        if self.shared.setup.bindings.contains_key(name) {
            return Err(why(at, format!("assigns `{name}`, an output variable or format")));
        }
        if self.model().constant(name).is_some() {
            return Err(why(at, format!("assigns `{name}`, a constant")));
        }
        self.shared
            .layout
            .global_index
            .get(name)
            .map(|g| Place::Global(*g))
            .ok_or_else(|| why(at, format!("assigns `{name}`, which is never declared")))
    }

    /// An assignment's target: a place, or an object and key.
    fn target(&mut self, target: &Expr, pre: &mut Vec<IrStmt>) -> R<Target> {
        match &target.kind {
            ExprKind::Member { object, property } if self.model().flattened_name(target).is_none() => {
                if property.name == "prototype" {
                    self.prototype(object, target.span)?;
                }
                let o = self.expr(object, pre)?;
                let o = self.keep(o, pre);
                Ok(Target::Member(o, Box::new(Ir::Text(property.name.clone())), Some(target.span)))
            }
            ExprKind::Index { object, index } => {
                let o = self.expr(object, pre)?;
                let o = self.keep(o, pre);
                let k = self.expr(index, pre)?;
                let k = self.keep(k, pre);
                Ok(Target::Member(o, Box::new(k), Some(target.span)))
            }
            _ => self.name_target(target),
        }
    }

    /// Stores into a target, and the expression that reads it back.
    fn store(&mut self, t: &Target, v: Ir, pre: &mut Vec<IrStmt>) -> Ir {
        match t {
            Target::Place(p) => {
                pre.push(IrStmt::Assign(*p, v));
                place_value(p)
            }
            Target::Member(o, k, span) => {
                pre.push(IrStmt::SetMember { object: o.clone(), key: (**k).clone(), value: v, span: Site(*span) });
                member(o.clone(), (**k).clone(), *span)
            }
        }
    }

    fn read(&self, t: &Target) -> Ir {
        match t {
            Target::Place(p) => place_value(p),
            Target::Member(o, k, span) => member(o.clone(), (**k).clone(), *span),
        }
    }

    /// A value kept in a temporary unless it is a constant or a temporary.
    fn keep(&mut self, v: Ir, pre: &mut Vec<IrStmt>) -> Ir {
        if stable(&v) {
            return v;
        }
        let t = self.temp();
        pre.push(IrStmt::Assign(Place::Local(t), v));
        Ir::Local(t)
    }

    /// An expression evaluated for its effect.
    fn effect(&mut self, e: &Expr, out: &mut Vec<IrStmt>) -> R<()> {
        match &e.kind {
            ExprKind::Assign { op, target, value } => {
                let mut pre = Vec::new();
                let t = self.target(target, &mut pre)?;
                let v = match op.binary() {
                    None => self.expr(value, &mut pre)?,
                    Some(b) => {
                        let cur = self.read(&t);
                        let cur = if self.has_effects(value) { self.keep(cur, &mut pre) } else { cur };
                        let v = self.expr(value, &mut pre)?;
                        binary_op(b, cur, v)
                    }
                };
                out.extend(pre);
                out.push(set(t, v));
                Ok(())
            }
            ExprKind::Update { op, target, .. } => {
                let mut pre = Vec::new();
                let t = self.target(target, &mut pre)?;
                let cur = Ir::Unary(IrUn::Plus, Box::new(self.read(&t)));
                let op = if *op == UpdateOp::Increment { IrBin::Add } else { IrBin::Sub };
                let v = Ir::Binary(op, Box::new(cur), Box::new(Ir::Number(1.0)));
                out.extend(pre);
                out.push(set(t, v));
                Ok(())
            }
            ExprKind::Call { callee, args } if args.is_empty() => {
                if let ExprKind::Member { object, property } = &callee.kind
                    && let ExprKind::Ident(o) = &object.kind
                    && let Some(Binding::Var(var)) = self.binding(o)
                    && property.name == "reset"
                {
                    out.push(IrStmt::Forget(var));
                    return Ok(());
                }
                let mut pre = Vec::new();
                let v = self.expr(e, &mut pre)?;
                out.extend(pre);
                out.push(IrStmt::Eval(v));
                Ok(())
            }
            ExprKind::Sequence(items) => {
                for i in items {
                    self.effect(i, out)?;
                }
                Ok(())
            }
            _ => {
                let mut pre = Vec::new();
                let v = self.expr(e, &mut pre)?;
                out.extend(pre);
                if !stable(&v) {
                    out.push(IrStmt::Eval(v));
                }
                Ok(())
            }
        }
    }

    /// Whether an expression may assign something (so operands read
    /// before it must be kept).
    fn has_effects(&self, e: &Expr) -> bool {
        any_expr(e, |k| matches!(k, ExprKind::Assign { .. } | ExprKind::Update { .. } | ExprKind::Call { .. }))
    }

    // ---- expressions ----

    /// Operands in order: each kept in a temporary when a later one has
    /// statements to run first.
    fn operands(&mut self, es: &[&Expr], pre: &mut Vec<IrStmt>) -> R<Vec<Ir>> {
        let mut vals = Vec::new();
        for (k, e) in es.iter().enumerate() {
            let mut own = Vec::new();
            let v = self.expr(e, &mut own)?;
            if !own.is_empty() || es[k + 1..].iter().any(|e| self.needs_statements(e)) {
                // Earlier operands are read before this one's statements.
                for earlier in vals.iter_mut() {
                    let taken = std::mem::replace(earlier, Ir::Undefined);
                    *earlier = self.keep(taken, pre);
                }
            }
            pre.extend(own);
            vals.push(v);
        }
        Ok(vals)
    }

    /// Whether lowering an expression puts statements before it.
    fn needs_statements(&self, e: &Expr) -> bool {
        any_expr(e, |k| matches!(k, ExprKind::Assign { .. } | ExprKind::Update { .. } | ExprKind::Sequence(_)))
    }

    fn expr(&mut self, e: &Expr, pre: &mut Vec<IrStmt>) -> R<Ir> {
        let at = e.span;
        Ok(match &e.kind {
            ExprKind::Number(n) => Ir::Number(*n),
            ExprKind::String(s) => Ir::Text(s.clone()),
            ExprKind::Bool(b) => Ir::Bool(*b),
            ExprKind::Null => Ir::Null,
            ExprKind::Undefined => Ir::Undefined,
            ExprKind::This => self.this_value(),
            ExprKind::Regex { pattern, flags } => {
                Ir::Regex { pattern: pattern.clone(), flags: flags.clone(), span: Some(at) }
            }
            ExprKind::Ident(name) => self.ident(name, at)?,
            ExprKind::Template { quasis, exprs } => {
                // The text pieces and each substitution's ToString, joined
                // with `+` (text with text only joins).
                let refs: Vec<&Expr> = exprs.iter().collect();
                let values = self.operands(&refs, pre)?;
                let mut text = Ir::Text(quasis.first().cloned().unwrap_or_default());
                for (value, piece) in values.into_iter().zip(quasis.iter().skip(1)) {
                    let value = Ir::Builtin(Builtin::JsString, vec![value]);
                    text = Ir::Binary(IrBin::Add, Box::new(text), Box::new(value));
                    if !piece.is_empty() {
                        text = Ir::Binary(IrBin::Add, Box::new(text), Box::new(Ir::Text(piece.clone())));
                    }
                }
                text
            }
            ExprKind::Array(items) => {
                let refs: Vec<&Expr> = items.iter().collect();
                Ir::Array(self.operands(&refs, pre)?)
            }
            ExprKind::Object(props) => {
                let refs: Vec<&Expr> = props.iter().map(|p| &p.value).collect();
                let vals = self.operands(&refs, pre)?;
                Ir::Object(props.iter().map(|p| p.key.name.clone()).zip(vals).collect())
            }
            ExprKind::Function(f) => {
                let id = self
                    .model()
                    .scopes
                    .id_of(f)
                    .ok_or_else(|| why(at, "has a function expression postc cannot place"))?;
                self.closure(id, at)?
            }
            ExprKind::Member { object, property } => {
                if property.name == "prototype"
                    && let Some(p) = self.prototype(object, at)?
                {
                    return Ok(p);
                }
                if let Some(flat) = self.model().flattened_name(e) {
                    return self.global_value(&flat, at);
                }
                if let ExprKind::Ident(o) = &object.kind
                    && o == "Math"
                    && self.is_host("Math")
                {
                    return names::math_constant(&property.name)
                        .map(Ir::Number)
                        .ok_or_else(|| why(at, format!("reads `Math.{}`, which postc does not have", property.name)));
                }
                if let ExprKind::Ident(o) = &object.kind
                    && o == "Number"
                    && self.is_host("Number")
                {
                    let n = match property.name.as_str() {
                        "POSITIVE_INFINITY" => f64::INFINITY,
                        "NEGATIVE_INFINITY" => f64::NEG_INFINITY,
                        "NaN" => f64::NAN,
                        "MAX_VALUE" => f64::MAX,
                        "MIN_VALUE" => 5e-324,
                        _ => return Err(why(at, format!("reads `Number.{}`", property.name))),
                    };
                    return Ok(Ir::Number(n));
                }
                if let ExprKind::Ident(o) = &object.kind
                    && self.binding(o).is_some()
                {
                    return Err(why(at, format!("reads `{o}.{}` of an output variable or format", property.name)));
                }
                // A static method of a class the host defines, or adds to
                // JavaScript's, read as a value (`Array.isArray || ...`): its
                // top-level function `__Array_isArray`, as a call does.
                if let ExprKind::Ident(o) = &object.kind
                    && (matches!(self.model().scopes.resolve(o, self.at), Symbol::TopFn(_)) || self.is_host(o))
                    && let Some(&i) = self.model().scopes.top_fn_names.get(&format!("__{o}_{}", property.name))
                {
                    return Ok(Ir::Closure { function: self.shared.layout.top_fn[i], captures: vec![] });
                }
                let o = self.expr(object, pre)?;
                member(o, Ir::Text(property.name.clone()), Some(at))
            }
            ExprKind::Index { object, index } => {
                let v = self.operands(&[object, index], pre)?;
                let mut v = v.into_iter();
                let (o, k) = (v.next().unwrap_or(Ir::Undefined), v.next().unwrap_or(Ir::Undefined));
                member(o, k, Some(at))
            }
            ExprKind::Call { callee, args } => self.call(callee, args, at, pre)?,
            ExprKind::New { callee, args } => match &callee.kind {
                ExprKind::Ident(n) if n == "Error" && self.is_host("Error") => {
                    let refs: Vec<&Expr> = args.iter().collect();
                    let mut v = self.operands(&refs, pre)?.into_iter();
                    let message = match v.next() {
                        Some(m) => Ir::Builtin(Builtin::Str, vec![m]),
                        None => Ir::Text(String::new()),
                    };
                    Ir::Object(vec![("name".into(), Ir::Text("Error".into())), ("message".into(), message)])
                }
                ExprKind::Ident(n) if n == "Array" && self.is_host(n) => {
                    let a = self.args(args, pre)?;
                    array_of(a, at)?
                }
                ExprKind::Ident(n) if n == "Object" && self.is_host(n) && args.is_empty() => Ir::Object(vec![]),
                ExprKind::Ident(n) if n == "RegExp" && self.is_host(n) => match args.as_slice() {
                    [Expr { kind: ExprKind::String(p), .. }] => {
                        Ir::Regex { pattern: p.clone(), flags: String::new(), span: Some(at) }
                    }
                    [Expr { kind: ExprKind::String(p), .. }, Expr { kind: ExprKind::String(f), .. }] => {
                        Ir::Regex { pattern: p.clone(), flags: f.clone(), span: Some(at) }
                    }
                    // A pattern made when the post runs: compiled then.
                    _ => {
                        let a = self.args(args, pre)?;
                        Ir::Builtin(Builtin::NewRegExp, a.into_iter().take(2).collect())
                    }
                },
                ExprKind::Ident(n) if self.is_host(n) => {
                    return Err(why(at, format!("makes a `new {n}`, which the host does not provide")));
                }
                _ => {
                    if let ExprKind::Ident(n) = &callee.kind {
                        self.note_stub(n, at);
                    }
                    let mut operands: Vec<&Expr> = vec![callee];
                    operands.extend(args.iter());
                    Ir::Builtin(Builtin::Construct, self.operands(&operands, pre)?)
                }
            },
            ExprKind::Unary { op, operand } => {
                if *op == UnaryOp::Typeof
                    && let ExprKind::Ident(n) = &operand.kind
                    && self.is_host(n)
                    && builtins::constant(n).is_none()
                {
                    return Ok(Ir::Text(if builtins::knows(n) { "function" } else { "undefined" }.into()));
                }
                let a = Box::new(self.expr(operand, pre)?);
                match op {
                    UnaryOp::Neg => Ir::Unary(IrUn::Neg, Box::new(to_number(*a))),
                    UnaryOp::Plus => Ir::Unary(IrUn::Plus, a),
                    UnaryOp::Not => Ir::Unary(IrUn::Not, a),
                    UnaryOp::BitNot => Ir::Unary(IrUn::BitNot, a),
                    UnaryOp::Typeof => Ir::Unary(IrUn::Typeof, a),
                }
            }
            ExprKind::Update { op, prefix, target } => {
                let t = self.target(target, pre)?;
                let cur = Ir::Unary(IrUn::Plus, Box::new(self.read(&t)));
                let old = self.keep(cur, pre);
                let op = if *op == UpdateOp::Increment { IrBin::Add } else { IrBin::Sub };
                let new = Ir::Binary(op, Box::new(old.clone()), Box::new(Ir::Number(1.0)));
                let stored = self.store(&t, new, pre);
                if *prefix { self.keep(stored, pre) } else { old }
            }
            // `v instanceof F`: whether `F.prototype` is on `v`'s chain.
            ExprKind::Binary { op: BinaryOp::Instanceof, left, right } => match self.prototype(right, at)? {
                Some(builtin) => Ir::Builtin(Builtin::InstanceOf, vec![self.expr(left, pre)?, builtin]),
                None => {
                    let v = self.operands(&[left, right], pre)?;
                    let mut v = v.into_iter();
                    let (a, f) = (v.next().unwrap_or(Ir::Undefined), v.next().unwrap_or(Ir::Undefined));
                    let proto = member(f, Ir::Text("prototype".into()), None);
                    Ir::Builtin(Builtin::InstanceOf, vec![a, proto])
                }
            },
            ExprKind::Binary { op, left, right } => {
                let v = self.operands(&[left, right], pre)?;
                let mut v = v.into_iter();
                let (a, b) = (v.next().unwrap_or(Ir::Undefined), v.next().unwrap_or(Ir::Undefined));
                binary_op(*op, a, b)
            }
            ExprKind::Logical { op, left, right } => {
                let a = self.expr(left, pre)?;
                let mut rest = Vec::new();
                let b = self.expr(right, &mut rest)?;
                if rest.is_empty() {
                    let op = if *op == LogicalOp::And { IrBin::And } else { IrBin::Or };
                    Ir::Binary(op, Box::new(a), Box::new(b))
                } else {
                    // t = a; if (t [is truthy for &&]) { rest; t = b }
                    let t = self.temp();
                    pre.push(IrStmt::Assign(Place::Local(t), a));
                    rest.push(IrStmt::Assign(Place::Local(t), b));
                    let test = match op {
                        LogicalOp::And => Ir::Local(t),
                        LogicalOp::Or => Ir::Unary(IrUn::Not, Box::new(Ir::Local(t))),
                    };
                    pre.push(IrStmt::If { branches: vec![(test, rest)], otherwise: vec![] });
                    Ir::Local(t)
                }
            }
            ExprKind::Conditional { test, consequent, alternate } => {
                let c = self.expr(test, pre)?;
                let mut p1 = Vec::new();
                let a = self.expr(consequent, &mut p1)?;
                let mut p2 = Vec::new();
                let b = self.expr(alternate, &mut p2)?;
                if p1.is_empty() && p2.is_empty() {
                    Ir::Choose(Box::new(c), Box::new(a), Box::new(b))
                } else {
                    let t = self.temp();
                    p1.push(IrStmt::Assign(Place::Local(t), a));
                    p2.push(IrStmt::Assign(Place::Local(t), b));
                    pre.push(IrStmt::If { branches: vec![(c, p1)], otherwise: p2 });
                    Ir::Local(t)
                }
            }
            ExprKind::Assign { op, target, value } => {
                let t = self.target(target, pre)?;
                let v = match op.binary() {
                    None => self.expr(value, pre)?,
                    Some(b) => {
                        let cur = self.read(&t);
                        let cur = self.keep(cur, pre);
                        let v = self.expr(value, pre)?;
                        binary_op(b, cur, v)
                    }
                };
                let v = self.keep(v, pre);
                self.store(&t, v.clone(), pre);
                v
            }
            ExprKind::Sequence(items) => {
                let Some((last, first)) = items.split_last() else { return Ok(Ir::Undefined) };
                for i in first {
                    self.effect(i, pre)?;
                }
                self.expr(last, pre)?
            }
            ExprKind::Error => return Err(why(at, "has an expression that does not parse")),
        })
    }

    fn args(&mut self, args: &[Expr], pre: &mut Vec<IrStmt>) -> R<Vec<Ir>> {
        let refs: Vec<&Expr> = args.iter().collect();
        self.operands(&refs, pre)
    }

    /// Notes a call (or `new`) of the post's own file to a host function
    /// postc does not run yet.
    fn note_stub(&mut self, name: &str, at: Span) {
        if self.shared.stubs.contains(name) && Some(at.file) == self.shared.post_file {
            self.shared.stub_calls.push((name.to_string(), at));
        }
    }

    fn call(&mut self, callee: &Expr, args: &[Expr], at: Span, pre: &mut Vec<IrStmt>) -> R<Ir> {
        match &callee.kind {
            ExprKind::Member { object, property } => self.method(object, &property.name, args, at, pre),
            ExprKind::Ident(name) => {
                if let Some(id) = self.nested_decl(name) {
                    let (function, captures) = self.shared.nested(id);
                    let mut values = self.capture_values(&captures, at)?;
                    values.extend(self.args(args, pre)?);
                    return Ok(Ir::Call(function, values));
                }
                match self.model().scopes.resolve(name, self.at) {
                    Symbol::TopFn(i) => {
                        self.note_stub(name, at);
                        let f = self.shared.layout.top_fn[i];
                        Ok(Ir::Call(f, self.args(args, pre)?))
                    }
                    Symbol::Global(g) if self.model().global(&g).is_none() => {
                        let a = self.args(args, pre)?;
                        if g == names::WRITE_LINE {
                            // The output primitive of a host written in JavaScript:
                            // one block, the text as it is, then the host's line
                            // ending (the post's own is empty).
                            let pieces = a.into_iter().map(postc_ir::Piece::Expr).collect();
                            pre.push(IrStmt::Line { pieces, span: Some(at) });
                            return Ok(Ir::Undefined);
                        }
                        // The host's text primitives, native (runtime
                        // `interp::host_text`).
                        if g == names::FORMAT_NUMBER {
                            return Ok(Ir::Builtin(Builtin::FormatNumber, a));
                        }
                        if g == names::WORDS {
                            return Ok(Ir::Builtin(Builtin::Words, a));
                        }
                        if g == names::FORMAT_OUTPUT {
                            return Ok(Ir::Builtin(Builtin::FormatOutput, a));
                        }
                        if g == names::PROPERTY {
                            return Ok(Ir::Builtin(Builtin::Property, a));
                        }
                        if g == names::SETTING_ERROR {
                            return Ok(Ir::Builtin(Builtin::SettingError, a));
                        }
                        if g == names::JOB_UNIT_IS_MM {
                            return Ok(Ir::Binary(
                                postc_ir::BinaryOp::Eq,
                                Box::new(Ir::Quantity(postc_ir::Quantity::UnitsText)),
                                Box::new(Ir::Text(postc_ir::Units::Mm.name().into())),
                            ));
                        }
                        self.host_call(&g, a, at)
                    }
                    _ => {
                        // The function is read before its arguments run.
                        let f = self.ident(name, at)?;
                        let f = if args.iter().any(|a| self.needs_statements(a)) { self.keep(f, pre) } else { f };
                        Ok(Ir::CallValue(Box::new(f), self.args(args, pre)?))
                    }
                }
            }
            _ => {
                let f = self.expr(callee, pre)?;
                let f = self.keep(f, pre);
                Ok(Ir::CallValue(Box::new(f), self.args(args, pre)?))
            }
        }
    }

    fn host_call(&mut self, name: &str, a: Vec<Ir>, at: Span) -> R<Ir> {
        let b = match name {
            "getFeedrate" if !self.shared.fusion => {
                let f = self.shared.layout.function(layout::FEEDRATE).ok_or_else(|| why(at, "calls `getFeedrate`"))?;
                return Ok(Ir::Call(f, a));
            }
            "Array" => return array_of(a, at),
            "parseInt" => Builtin::ParseInt,
            "parseFloat" => Builtin::ParseFloat,
            "isNaN" => Builtin::IsNaN,
            "Number" if !a.is_empty() => Builtin::ToNumber,
            "Number" => return Ok(Ir::Number(0.0)),
            "String" if !a.is_empty() && self.shared.fusion => {
                return Ok(Ir::Builtin(Builtin::JsString, a.into_iter().take(1).collect()));
            }
            "String" if !a.is_empty() => {
                return Ok(Ir::Builtin(Builtin::Str, a.into_iter().take(1).collect()));
            }
            "String" => return Ok(Ir::Text(String::new())),
            names::GET_COMPENSATION if !self.shared.fusion => {
                return Ok(Ir::Host { name: names::COMPENSATION.into(), args: vec![] });
            }
            _ if self.shared.fusion => {
                let f = self.shared.undeclared(name, at)?;
                return Ok(Ir::CallValue(Box::new(f), a));
            }
            _ => return Err(why(at, format!("calls `{name}`, a host function with no native form"))),
        };
        Ok(Ir::Builtin(b, a))
    }

    fn method(&mut self, object: &Expr, name: &str, args: &[Expr], at: Span, pre: &mut Vec<IrStmt>) -> R<Ir> {
        if let ExprKind::Ident(o) = &object.kind {
            if o == "Math" && self.is_host("Math") {
                // A function of `Math` the host writes in JavaScript
                // (`Math.random`, docs/fusion.md choice 27).
                if let Some(&i) = self.model().scopes.top_fn_names.get(&format!("__Math_{name}")) {
                    let f = self.shared.layout.top_fn[i];
                    return Ok(Ir::Call(f, self.args(args, pre)?));
                }
                let a = self.args(args, pre)?;
                return math(name, a, at);
            }
            if o == "String" && name == "fromCharCode" && self.is_host("String") {
                let a = self.args(args, pre)?;
                let mut chars = a.into_iter().map(|c| Ir::Builtin(Builtin::Chr, vec![c]));
                let first = chars.next().unwrap_or(Ir::Text(String::new()));
                return Ok(chars.fold(first, |text, c| Ir::Binary(IrBin::Add, Box::new(text), Box::new(c))));
            }
            if o == "Array" && name == "isArray" && args.len() == 1 && self.is_host("Array") {
                let a = self.args(args, pre)?;
                return Ok(Ir::Builtin(Builtin::IsArray, a));
            }
            if o == "Object" && name == "keys" && args.len() == 1 && self.is_host("Object") {
                let a = self.args(args, pre)?;
                return Ok(Ir::Builtin(Builtin::OwnKeys, a));
            }
            if o == "Object" && name == "create" && self.is_host("Object") {
                if args.len() > 1 {
                    return Err(why(at, "calls `Object.create` with property descriptors"));
                }
                let a = self.args(args, pre)?;
                return Ok(Ir::Builtin(Builtin::CreateObject, a));
            }
            // A static method of a class the host defines in JavaScript
            // (`Vector.diff(a, b)`), or one it adds to JavaScript's
            // (`JSON.stringify(v)`), is its top-level function `__Vector_diff`.
            if (matches!(self.model().scopes.resolve(o, self.at), Symbol::TopFn(_)) || self.is_host(o))
                && let Some(&i) = self.model().scopes.top_fn_names.get(&format!("__{o}_{name}"))
            {
                let f = self.shared.layout.top_fn[i];
                return Ok(Ir::Call(f, self.args(args, pre)?));
            }
            if let Some(b) = self.binding(o) {
                let mut a = self.args(args, pre)?;
                return match (b, name, a.len()) {
                    (Binding::Var(var), "format", 1) => {
                        Ok(Ir::FormatVar { var, value: Box::new(to_number(a.remove(0))), span: Some(at) })
                    }
                    (Binding::Var(var), "getLast", _) => {
                        Ok(Ir::Binary(IrBin::Add, Box::new(Ir::Number(0.0)), Box::new(Ir::Var(var))))
                    }
                    (Binding::Var(var), "reset", 0) => {
                        pre.push(IrStmt::Forget(var));
                        Ok(Ir::Undefined)
                    }
                    (Binding::Format(format), "format", 1) => {
                        Ok(Ir::Format { format, value: Box::new(to_number(a.remove(0))), span: Some(at) })
                    }
                    _ => Err(why(at, format!("calls `{o}.{name}()` with {} argument(s)", a.len()))),
                };
            }
            if self.is_host(o) && builtins::knows(o) {
                return Err(why(at, format!("calls `{o}.{name}()`, a host object's method with no native form")));
            }
        }
        if let ExprKind::Member { .. } = &object.kind
            && let Some(flat) = self.model().flattened_name(object)
        {
            let recv = self.global_value(&flat, at)?;
            let a = self.args(args, pre)?;
            return Ok(Ir::Invoke { object: Box::new(recv), method: name.to_string(), args: a, span: Some(at) });
        }
        let recv = self.expr(object, pre)?;
        let recv = if args.iter().any(|a| self.needs_statements(a)) { self.keep(recv, pre) } else { recv };
        let a = self.args(args, pre)?;
        Ok(Ir::Invoke { object: Box::new(recv), method: name.to_string(), args: a, span: Some(at) })
    }
}

/// `Array(...)` or `new Array(...)`: `n` empty items for one number
/// `n`, else the items given.
fn array_of(a: Vec<Ir>, at: Span) -> R<Ir> {
    match a.as_slice() {
        [Ir::Number(n)] if *n >= 0.0 && n.fract() == 0.0 && *n <= 65536.0 => {
            Ok(Ir::Array(vec![Ir::Undefined; *n as usize]))
        }
        [_] => Err(why(at, "makes an `Array(n)` of a length known only when the post runs")),
        _ => Ok(Ir::Array(a)),
    }
}

/// Where an assignment stores: a place, or an object, a key and the
/// assignment's target in the post.
enum Target {
    Place(Place),
    Member(Ir, Box<Ir>, Option<Span>),
}

/// `object[key]`, `span` the member in the post.
fn member(object: Ir, key: Ir, span: Option<Span>) -> Ir {
    Ir::Member { object: Box::new(object), key: Box::new(key), span: Site(span) }
}

/// Whether a simple statement (an expression, a declaration, a `return`,
/// a `throw`) calls a function or makes an object with `new`.
fn calls(s: &Stmt) -> bool {
    let call = |e: &Expr| any_expr(e, |k| matches!(k, ExprKind::Call { .. } | ExprKind::New { .. }));
    match &s.kind {
        StmtKind::Expr(e) | StmtKind::Return(Some(e)) | StmtKind::Throw(e) => call(e),
        StmtKind::Var(ds) => ds.iter().any(|d| d.init.as_ref().is_some_and(call)),
        _ => false,
    }
}

/// Whether `e` or an expression inside it (not inside a nested function)
/// is one `found` picks.
fn any_expr(e: &Expr, found: fn(&ExprKind) -> bool) -> bool {
    struct F(bool, fn(&ExprKind) -> bool);
    impl<'a> super::scope::Visit<'a> for F {
        fn expr(&mut self, e: &'a Expr) -> bool {
            self.0 |= (self.1)(&e.kind);
            !self.0 && !matches!(e.kind, ExprKind::Function(_))
        }
        fn function_decl(&mut self, _f: &'a Function) {}
    }
    let mut f = F(false, found);
    super::scope::walk_expr(e, &mut f);
    f.0
}

/// The statement that stores a value into a target.
fn set(t: Target, value: Ir) -> IrStmt {
    match t {
        Target::Place(p) => IrStmt::Assign(p, value),
        Target::Member(object, key, span) => IrStmt::SetMember { object, key: *key, value, span: Site(span) },
    }
}

/// Item 0 of a cell.
fn cell_item(cell: Ir) -> Ir {
    member(cell, Ir::Number(0.0), None)
}

fn place_value(p: &Place) -> Ir {
    match p {
        Place::Local(l) => Ir::Local(*l),
        Place::Global(g) => Ir::Global(*g),
        Place::Var(v) => Ir::Var(*v),
    }
}

/// Whether reading an expression again gives the same value with no effect.
fn stable(v: &Ir) -> bool {
    matches!(v, Ir::Number(_) | Ir::Text(_) | Ir::Bool(_) | Ir::Null | Ir::Undefined | Ir::Local(_) | Ir::This)
}

/// A constant as IR, `undefined` kept apart from `null`.
fn const_expr(c: &super::consts::Const) -> Ir {
    match c {
        super::consts::Const::Undefined => Ir::Undefined,
        other => layout::const_expr(other),
    }
}

/// `Math.name(args)`: missing arguments read as NaN, extra ones are dropped.
fn math(name: &str, a: Vec<Ir>, at: Span) -> R<Ir> {
    if name == "pow" {
        let mut it = a.into_iter();
        let (x, y) = (it.next().unwrap_or(Ir::Undefined), it.next().unwrap_or(Ir::Undefined));
        return Ok(Ir::Binary(IrBin::Pow, Box::new(to_number(x)), Box::new(to_number(y))));
    }
    match (name, a.is_empty()) {
        ("min", true) => return Ok(Ir::Number(f64::INFINITY)),
        ("max", true) => return Ok(Ir::Number(f64::NEG_INFINITY)),
        _ => {}
    }
    let (b, arity) =
        builtins::math(name).ok_or_else(|| why(at, format!("calls `Math.{name}`, which postc does not run")))?;
    let arity = arity.unwrap_or(a.len());
    let mut a: Vec<Ir> = a.into_iter().map(to_number).collect();
    a.resize(arity.max(a.len()), Ir::Number(f64::NAN));
    a.truncate(arity);
    Ok(Ir::Builtin(b, a))
}
