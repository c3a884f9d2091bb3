//! Scopes: every function of a post (declarations, nested declarations and
//! function expressions), its parameters and hoisted `var`s, and what a
//! name means at any point: a local of the function or of an enclosing
//! one, a top-level function, a global, or a name the host provides.

use std::collections::HashMap;

use crate::ast::*;

/// Index of a function in [`Scopes::funcs`]; 0 is the program's top level.
pub type FnId = usize;

/// One function (or the top level).
#[derive(Debug)]
pub struct FuncInfo<'a> {
    /// The function's name (a declaration's or a named expression's).
    pub name: Option<String>,
    pub func: Option<&'a Function>,
    pub parent: Option<FnId>,
    pub params: Vec<String>,
    /// Parameters first, then hoisted `var`s and nested declarations.
    pub locals: Vec<String>,
    /// Nested function declarations, hoisted to the top of the body.
    pub nested: Vec<&'a Function>,
    pub uses_this: bool,
    pub uses_arguments: bool,
    /// Some local of an enclosing function is used here (a closure).
    pub captures: bool,
}

impl FuncInfo<'_> {
    pub fn slot(&self, name: &str) -> Option<usize> {
        self.locals.iter().position(|l| l == name)
    }
}

/// What a name means where it is used.
#[derive(Clone, Debug, PartialEq)]
pub enum Symbol {
    /// A local (parameter or `var`) of a function: the current one or,
    /// for closures, an enclosing one.
    Local { func: FnId, slot: usize },
    /// A top-level function declaration.
    TopFn(usize),
    /// A global variable, declared or implicit.
    Global(String),
}

/// Every function of a program.
pub struct Scopes<'a> {
    pub funcs: Vec<FuncInfo<'a>>,
    /// Function of each `Function` node, by its file and the start of its span.
    by_span: HashMap<(postc_ir::FileId, usize), FnId>,
    /// Top-level function declarations, in order.
    pub top_fns: Vec<FnId>,
    pub top_fn_names: HashMap<String, usize>,
    /// Top-level `var` declarations, in order (the first of each name).
    pub top_vars: Vec<&'a Ident>,
}

impl<'a> Scopes<'a> {
    pub fn build(program: &'a Program) -> Scopes<'a> {
        let mut s = Scopes {
            funcs: Vec::new(),
            by_span: HashMap::new(),
            top_fns: Vec::new(),
            top_fn_names: HashMap::new(),
            top_vars: Vec::new(),
        };
        s.funcs.push(FuncInfo {
            name: None,
            func: None,
            parent: None,
            params: Vec::new(),
            locals: Vec::new(),
            nested: Vec::new(),
            uses_this: false,
            uses_arguments: false,
            captures: false,
        });
        let mut vars = Vec::new();
        let mut decls = Vec::new();
        hoist(&program.body, &mut vars, &mut decls);
        s.top_vars = vars;
        for f in decls {
            let id = s.add(f, 0);
            let name = f.name.as_ref().map(|n| n.name.clone()).unwrap_or_default();
            let index = s.top_fns.len();
            s.top_fns.push(id);
            // A later declaration of the same name wins, as in JavaScript.
            s.top_fn_names.insert(name, index);
        }
        s.scan_stmts(&program.body, 0);
        s
    }

    fn add(&mut self, f: &'a Function, parent: FnId) -> FnId {
        if let Some(&id) = self.by_span.get(&(f.span.file, f.span.start)) {
            return id;
        }
        let mut vars = Vec::new();
        let mut nested = Vec::new();
        hoist(&f.body, &mut vars, &mut nested);
        let params: Vec<String> = f.params.iter().map(|p| p.name.clone()).collect();
        let mut locals = params.clone();
        for v in vars.into_iter().chain(nested.iter().filter_map(|n| n.name.as_ref())) {
            if !locals.contains(&v.name) {
                locals.push(v.name.clone());
            }
        }
        let id = self.funcs.len();
        self.funcs.push(FuncInfo {
            name: f.name.as_ref().map(|n| n.name.clone()),
            func: Some(f),
            parent: Some(parent),
            params,
            locals,
            nested: nested.clone(),
            uses_this: false,
            uses_arguments: false,
            captures: false,
        });
        self.by_span.insert((f.span.file, f.span.start), id);
        for n in nested {
            self.add(n, id);
        }
        self.scan_stmts(&f.body, id);
        id
    }

    /// The function a `Function` node is.
    pub fn id_of(&self, f: &Function) -> Option<FnId> {
        self.by_span.get(&(f.span.file, f.span.start)).copied()
    }

    /// What `name` means inside function `at`.
    pub fn resolve(&self, name: &str, at: FnId) -> Symbol {
        let mut cur = Some(at);
        while let Some(id) = cur {
            if id == 0 {
                break;
            }
            let info = &self.funcs[id];
            if let Some(slot) = info.slot(name) {
                return Symbol::Local { func: id, slot };
            }
            if name == "arguments" {
                return Symbol::Local { func: id, slot: usize::MAX };
            }
            cur = info.parent;
        }
        if let Some(&i) = self.top_fn_names.get(name) {
            return Symbol::TopFn(i);
        }
        Symbol::Global(name.to_string())
    }

    /// Marks `this`, `arguments` and captured locals of every function.
    fn scan_stmts(&mut self, body: &'a [Stmt], at: FnId) {
        let mut w = Walker { scopes: self, at };
        for s in body {
            walk_stmt(s, &mut w);
        }
    }
}

/// Collects the `var` names and nested function declarations of a body,
/// not looking into nested functions.
fn hoist<'a>(body: &'a [Stmt], vars: &mut Vec<&'a Ident>, decls: &mut Vec<&'a Function>) {
    for s in body {
        hoist_stmt(s, vars, decls);
    }
}

/// Collects the `var` declarations (the first of each name) and function
/// declarations a body hoists.
pub(super) fn hoist_stmt<'a>(s: &'a Stmt, vars: &mut Vec<&'a Ident>, decls: &mut Vec<&'a Function>) {
    let push = |name: &'a Ident, vars: &mut Vec<&'a Ident>| {
        if !vars.iter().any(|v| v.name == name.name) {
            vars.push(name);
        }
    };
    match &s.kind {
        StmtKind::Var(ds) => ds.iter().for_each(|d| push(&d.name, vars)),
        StmtKind::Function(f) => decls.push(f),
        StmtKind::Block(b) => hoist(b, vars, decls),
        StmtKind::If { branches, otherwise } => {
            for b in branches {
                hoist_stmt(&b.body, vars, decls);
            }
            if let Some(o) = otherwise {
                hoist_stmt(o, vars, decls);
            }
        }
        StmtKind::Switch { cases, .. } => cases.iter().for_each(|c| hoist(&c.body, vars, decls)),
        StmtKind::For { init, body, .. } => {
            if let Some(ForInit::Var(ds)) = init {
                ds.iter().for_each(|d| push(&d.name, vars));
            }
            hoist_stmt(body, vars, decls);
        }
        StmtKind::ForIn { declared, name, body, .. } => {
            if *declared {
                push(name, vars);
            }
            hoist_stmt(body, vars, decls);
        }
        StmtKind::While { body, .. } | StmtKind::DoWhile { body, .. } => hoist_stmt(body, vars, decls),
        StmtKind::Try { block, handler, finalizer } => {
            hoist(block, vars, decls);
            if let Some(h) = handler {
                // The caught value lives in a variable of the function.
                push(&h.param, vars);
                hoist(&h.body, vars, decls);
            }
            if let Some(f) = finalizer {
                hoist(f, vars, decls);
            }
        }
        _ => {}
    }
}

struct Walker<'s, 'a> {
    scopes: &'s mut Scopes<'a>,
    at: FnId,
}

impl<'a> Visit<'a> for Walker<'_, 'a> {
    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::This => self.scopes.funcs[self.at].uses_this = true,
            ExprKind::Ident(name) => {
                if name == "arguments" && self.at != 0 && self.scopes.funcs[self.at].slot("arguments").is_none() {
                    self.scopes.funcs[self.at].uses_arguments = true;
                } else if let Symbol::Local { func, .. } = self.scopes.resolve(name, self.at)
                    && func != self.at
                {
                    self.scopes.funcs[self.at].captures = true;
                }
            }
            ExprKind::Function(f) => {
                let at = self.at;
                let id = self.scopes.add(f, at);
                if self.scopes.funcs[id].captures {
                    // The closure sees locals of its parent.
                }
                return false;
            }
            _ => {}
        }
        true
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}

/// A visitor over statements and expressions of one function body. Nested
/// function declarations are reported to `function_decl` and not entered;
/// function expressions are reported to `expr`, which returns whether to go
/// into an expression's children.
pub trait Visit<'a> {
    fn expr(&mut self, e: &'a Expr) -> bool;
    fn stmt(&mut self, _s: &'a Stmt) -> bool {
        true
    }
    fn function_decl(&mut self, f: &'a Function);
}

pub fn walk_stmts<'a>(body: &'a [Stmt], v: &mut impl Visit<'a>) {
    for s in body {
        walk_stmt(s, v);
    }
}

pub fn walk_stmt<'a>(s: &'a Stmt, v: &mut impl Visit<'a>) {
    if !v.stmt(s) {
        return;
    }
    match &s.kind {
        StmtKind::Var(ds) => ds.iter().filter_map(|d| d.init.as_ref()).for_each(|e| walk_expr(e, v)),
        StmtKind::Function(f) => v.function_decl(f),
        StmtKind::Expr(e) | StmtKind::Throw(e) => walk_expr(e, v),
        StmtKind::Return(e) => e.iter().for_each(|e| walk_expr(e, v)),
        StmtKind::Block(b) => walk_stmts(b, v),
        StmtKind::If { branches, otherwise } => {
            for b in branches {
                walk_expr(&b.cond, v);
                walk_stmt(&b.body, v);
            }
            if let Some(o) = otherwise {
                walk_stmt(o, v);
            }
        }
        StmtKind::Switch { discriminant, cases } => {
            walk_expr(discriminant, v);
            for c in cases {
                c.test.iter().for_each(|t| walk_expr(t, v));
                walk_stmts(&c.body, v);
            }
        }
        StmtKind::For { init, test, update, body } => {
            match init {
                Some(ForInit::Var(ds)) => ds.iter().filter_map(|d| d.init.as_ref()).for_each(|e| walk_expr(e, v)),
                Some(ForInit::Expr(e)) => walk_expr(e, v),
                None => {}
            }
            test.iter().chain(update.iter()).for_each(|e| walk_expr(e, v));
            walk_stmt(body, v);
        }
        StmtKind::ForIn { object, body, .. } => {
            walk_expr(object, v);
            walk_stmt(body, v);
        }
        StmtKind::While { cond, body } | StmtKind::DoWhile { body, cond } => {
            walk_expr(cond, v);
            walk_stmt(body, v);
        }
        StmtKind::Try { block, handler, finalizer } => {
            walk_stmts(block, v);
            if let Some(h) = handler {
                walk_stmts(&h.body, v);
            }
            if let Some(f) = finalizer {
                walk_stmts(f, v);
            }
        }
        StmtKind::Break | StmtKind::Continue | StmtKind::Empty | StmtKind::Error => {}
    }
}

pub fn walk_expr<'a>(e: &'a Expr, v: &mut impl Visit<'a>) {
    if !v.expr(e) {
        return;
    }
    match &e.kind {
        ExprKind::Array(items) | ExprKind::Sequence(items) | ExprKind::Template { exprs: items, .. } => {
            items.iter().for_each(|i| walk_expr(i, v))
        }
        ExprKind::Object(props) => props.iter().for_each(|p| walk_expr(&p.value, v)),
        ExprKind::Member { object, .. } => walk_expr(object, v),
        ExprKind::Unary { operand: a, .. } | ExprKind::Update { target: a, .. } => walk_expr(a, v),
        ExprKind::Index { object: a, index: b }
        | ExprKind::Binary { left: a, right: b, .. }
        | ExprKind::Logical { left: a, right: b, .. }
        | ExprKind::Assign { target: a, value: b, .. } => {
            walk_expr(a, v);
            walk_expr(b, v);
        }
        ExprKind::Call { callee, args } | ExprKind::New { callee, args } => {
            walk_expr(callee, v);
            args.iter().for_each(|a| walk_expr(a, v));
        }
        ExprKind::Conditional { test, consequent, alternate } => {
            walk_expr(test, v);
            walk_expr(consequent, v);
            walk_expr(alternate, v);
        }
        _ => {}
    }
}
