//! The program model: the post's globals (declared with `var`, assigned
//! without one, and the properties of the `globals` and `PostInfo`
//! objects, which are flattened into globals named `globals.decimalMark`),
//! how often each is assigned, which are constants, and which can only
//! hold numbers, text, booleans or nothing ("plain") rather than objects.
//!
//! Plain-ness is what lets native IR share a global with the Rhai side:
//! the runtime keeps plain values in the IR's globals. It is inferred
//! conservatively by iterating to a fixed point over every assignment,
//! every return and every call argument of the program.

use std::collections::{HashMap, HashSet};

use crate::ast::*;

use super::builtins;
use super::consts::{Const, const_eval};
mod infer;
pub mod tables;

use super::scope::{FnId, Scopes, Symbol, Visit, walk_expr, walk_stmts};

/// The objects whose properties become globals.
pub const FLATTENED: &[&str] = &["globals", "PostInfo"];

/// One global.
#[derive(Debug, Clone)]
pub struct GlobalInfo<'a> {
    pub name: String,
    /// The expression that gives its first value (declaration or the only
    /// top-level assignment), if any.
    pub init: Option<&'a Expr>,
    pub assignments: usize,
    /// Known at compile time: never assigned after its first value.
    pub constant: Option<Const>,
    /// Only ever holds numbers, text, booleans or nothing.
    pub plain: bool,
    /// Declared with `var` or flattened (not an implicit global).
    pub declared: bool,
    /// Where it is declared (`var x`), if it is.
    pub declared_at: Option<postc_ir::Span>,
}

/// The model of a program.
pub struct Model<'a> {
    pub scopes: Scopes<'a>,
    pub globals: Vec<GlobalInfo<'a>>,
    pub global_index: HashMap<String, usize>,
    /// Flattened objects present in this post.
    pub flattened: HashSet<String>,
    /// Plain-ness of each function's locals.
    pub local_plain: Vec<Vec<bool>>,
    /// Plain-ness of each function's return value.
    pub returns_plain: Vec<bool>,
    /// Top-level functions that are used as values (not only called).
    pub fn_as_value: HashSet<usize>,
    /// Top-level functions that are assigned to (a name reused).
    pub fn_reassigned: HashSet<usize>,
    /// Look-up tables ([`tables`]): each one's entries.
    pub tables: HashMap<String, tables::Table>,
}

impl<'a> Model<'a> {
    pub fn build(program: &'a Program) -> Model<'a> {
        let scopes = Scopes::build(program);
        let mut m = Model {
            local_plain: scopes.funcs.iter().map(|f| vec![true; f.locals.len()]).collect(),
            returns_plain: vec![true; scopes.funcs.len()],
            scopes,
            globals: Vec::new(),
            global_index: HashMap::new(),
            flattened: HashSet::new(),
            fn_as_value: HashSet::new(),
            fn_reassigned: HashSet::new(),
            tables: HashMap::new(),
        };
        m.find_flattened(program);
        for v in m.scopes.top_vars.clone() {
            if !m.flattened.contains(&v.name) {
                let g = m.add_global(&v.name, true);
                m.globals[g].declared_at = Some(v.span);
            }
        }
        m.declare_flattened(program);
        m.count_assignments(program);
        m.find_constants(program);
        m.tables = tables::find(&m, program);
        m.infer_plain(program);
        m
    }

    fn add_global(&mut self, name: &str, declared: bool) -> usize {
        if let Some(&i) = self.global_index.get(name) {
            self.globals[i].declared |= declared;
            return i;
        }
        let i = self.globals.len();
        self.globals.push(GlobalInfo {
            name: name.to_string(),
            init: None,
            assignments: 0,
            constant: None,
            plain: true,
            declared,
            declared_at: None,
        });
        self.global_index.insert(name.to_string(), i);
        i
    }

    pub fn global(&self, name: &str) -> Option<&GlobalInfo<'a>> {
        self.global_index.get(name).map(|&i| &self.globals[i])
    }

    /// The constant value of a global, if it has one.
    pub fn constant(&self, name: &str) -> Option<&Const> {
        self.global(name).and_then(|g| g.constant.as_ref())
    }

    /// A configuration global in either form: `decimalMark` or `globals.decimalMark`.
    pub fn setting(&self, name: &str) -> Option<&Const> {
        self.constant(name).or_else(|| self.constant(&format!("globals.{name}")))
    }

    /// `globals` and `PostInfo` are flattened when every use of them is
    /// `NAME.property` and they are set from one object literal at the top.
    fn find_flattened(&mut self, program: &'a Program) {
        for &name in FLATTENED {
            let mut literal = 0;
            for s in &program.body {
                if object_literal_assignment(s, name).is_some() {
                    literal += 1;
                }
            }
            if literal != 1 {
                continue;
            }
            let mut v = BareUse { name, found: false, depth_ok: true };
            walk_stmts(&program.body, &mut v);
            for f in &self.scopes.funcs {
                if let Some(func) = f.func {
                    walk_stmts(&func.body, &mut v);
                }
            }
            if !v.found {
                self.flattened.insert(name.to_string());
            }
        }
    }

    fn declare_flattened(&mut self, program: &'a Program) {
        for s in &program.body {
            for &name in FLATTENED {
                if !self.flattened.contains(name) {
                    continue;
                }
                if let Some(props) = object_literal_assignment(s, name) {
                    for p in props {
                        let g = self.add_global(&format!("{name}.{}", p.key.name), true);
                        self.globals[g].init = Some(&p.value);
                        self.globals[g].assignments += 1;
                    }
                }
            }
        }
    }

    /// The flattened global a member expression names (`globals.x`).
    pub fn flattened_name(&self, e: &Expr) -> Option<String> {
        if let ExprKind::Member { object, property } = &e.kind
            && let ExprKind::Ident(obj) = &object.kind
            && self.flattened.contains(obj)
        {
            return Some(format!("{obj}.{}", property.name));
        }
        None
    }

    fn count_assignments(&mut self, program: &'a Program) {
        let mut targets: Vec<(String, Option<&'a Expr>, bool)> = Vec::new();
        // Top-level declarations and assignments.
        for s in &program.body {
            match &s.kind {
                StmtKind::Var(ds) => {
                    for d in ds {
                        if let Some(init) = &d.init
                            && !self.flattened.contains(&d.name.name)
                        {
                            targets.push((d.name.name.clone(), Some(init), true));
                        }
                    }
                }
                StmtKind::Expr(e) => {
                    if let ExprKind::Assign { op: AssignOp::Assign, target, value } = &e.kind
                        && let ExprKind::Ident(name) = &target.kind
                        && !self.flattened.contains(name)
                    {
                        targets.push((name.clone(), Some(&**value), true));
                        // Its value may hold more assignments.
                        let mut c = Assigns { model: self, at: 0, found: Vec::new() };
                        walk_expr(value, &mut c);
                        let found = c.found;
                        targets.extend(found.into_iter().map(|n| (n, None, false)));
                        continue;
                    }
                    let mut c = Assigns { model: self, at: 0, found: Vec::new() };
                    walk_expr(e, &mut c);
                    let found = c.found;
                    targets.extend(found.into_iter().map(|n| (n, None, false)));
                }
                _ => {
                    let mut c = Assigns { model: self, at: 0, found: Vec::new() };
                    walk_stmts(std::slice::from_ref(s), &mut c);
                    let found = c.found;
                    targets.extend(found.into_iter().map(|n| (n, None, false)));
                }
            }
        }
        for id in 1..self.scopes.funcs.len() {
            let Some(func) = self.scopes.funcs[id].func else { continue };
            let mut c = Assigns { model: self, at: id, found: Vec::new() };
            walk_stmts(&func.body, &mut c);
            let found = c.found;
            targets.extend(found.into_iter().map(|n| (n, None, false)));
        }
        for (name, init, top) in targets {
            if let Some(&f) = self.scopes.top_fn_names.get(&name) {
                self.fn_reassigned.insert(f);
                continue;
            }
            let g = self.add_global(&name, false);
            let info = &mut self.globals[g];
            info.assignments += 1;
            if top && info.init.is_none() && info.assignments == 1 {
                info.init = init;
            }
        }
    }

    fn find_constants(&mut self, _program: &'a Program) {
        // Constants may refer to earlier constants: iterate in order, twice.
        for _ in 0..2 {
            for i in 0..self.globals.len() {
                let g = &self.globals[i];
                if g.assignments != 1 || g.constant.is_some() {
                    continue;
                }
                let Some(init) = g.init else { continue };
                if let Some(c) = const_eval(init, &|name| self.const_ident(name), &|e| self.flattened_name(e)) {
                    self.globals[i].constant = Some(c);
                }
            }
        }
    }

    fn const_ident(&self, name: &str) -> Option<Const> {
        if let Some(c) = self.constant(name) {
            return Some(c.clone());
        }
        if self.global_index.contains_key(name) || self.scopes.top_fn_names.contains_key(name) {
            return None;
        }
        builtins::constant(name)
    }
}

/// `NAME = {...}` or `var NAME = {...}` at the top of a program.
pub fn object_literal_assignment<'a>(s: &'a Stmt, name: &str) -> Option<&'a [Property]> {
    match &s.kind {
        StmtKind::Expr(e) => match &e.kind {
            ExprKind::Assign { op: AssignOp::Assign, target, value } => match (&target.kind, &value.kind) {
                (ExprKind::Ident(n), ExprKind::Object(props)) if n == name => Some(props),
                _ => None,
            },
            _ => None,
        },
        StmtKind::Var(ds) if ds.len() == 1 && ds[0].name.name == name => match ds[0].init.as_ref().map(|i| &i.kind) {
            Some(ExprKind::Object(props)) => Some(props),
            _ => None,
        },
        _ => None,
    }
}

/// Finds uses of a flattened object other than `NAME.property` and the
/// one literal assignment.
struct BareUse<'n> {
    name: &'n str,
    found: bool,
    depth_ok: bool,
}

impl<'a> Visit<'a> for BareUse<'_> {
    fn stmt(&mut self, s: &'a Stmt) -> bool {
        object_literal_assignment(s, self.name).is_none() || {
            // Look into the literal's values only.
            if let Some(props) = object_literal_assignment(s, self.name) {
                for p in props {
                    walk_expr(&p.value, self);
                }
            }
            false
        }
    }

    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Member { object, .. } if matches!(&object.kind, ExprKind::Ident(n) if n == self.name) => false,
            ExprKind::Ident(n) if n == self.name => {
                self.found = true;
                false
            }
            ExprKind::Function(f) => {
                walk_stmts(&f.body, self);
                false
            }
            _ => self.depth_ok,
        }
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}

/// Collects the names of globals assigned in a body.
struct Assigns<'m, 'a> {
    model: &'m Model<'a>,
    at: FnId,
    found: Vec<String>,
}

impl Assigns<'_, '_> {
    fn target(&mut self, t: &Expr) {
        match &t.kind {
            ExprKind::Ident(name) => {
                if let Symbol::Global(n) = self.model.scopes.resolve(name, self.at) {
                    self.found.push(n);
                } else if let Symbol::TopFn(_) = self.model.scopes.resolve(name, self.at) {
                    self.found.push(name.clone());
                }
            }
            _ => {
                if let Some(flat) = self.model.flattened_name(t) {
                    self.found.push(flat);
                }
            }
        }
    }
}

impl<'a> Visit<'a> for Assigns<'_, 'a> {
    fn stmt(&mut self, s: &'a Stmt) -> bool {
        if let StmtKind::ForIn { name, .. } = &s.kind {
            let ident = Expr::new(ExprKind::Ident(name.name.clone()), name.span);
            self.target(&ident);
        }
        true
    }

    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } => self.target(target),
            ExprKind::Function(_) => return false,
            _ => {}
        }
        true
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}
