//! Names: the pre-pass that finds every register, which globals hold text
//! and which names the post ever sets; and what a name means where it is
//! used (a value, an assignment target, a temporary).
//!
//! A name means, in this order: a local of the current Sub (parameter,
//! `Dim`, `Const`, or a Function's own name for its result), a register,
//! `N` (the sequence number), a global, a Sub or Function, a built-in.
//! Anything else is a new global: as in VcPost, a variable set in one Sub is
//! seen by every later call.

use postc_ir::post::{LocalId, VarId};
use postc_ir::{Diagnostic, Expr as IrExpr, Place, Quantity, Span};

use super::template::{TemplatePart, out_parts, split};
use super::walk::{each_expr, each_stmt, stmt_exprs};
use super::{Lowerer, MAX_EXPR_DEPTH};
use crate::ast::{CommentKind, Expr, ExprKind, Item, Name, ProcKind, Procedure, Stmt, StmtKind};
use crate::diagnostics as codes;
use crate::registers::RegisterSpec;
use crate::token::{Kw, is_reserved, is_valid_name};

/// What the pre-pass finds, in file order.
enum Found<'a> {
    Register(&'a str, Span),
    Assigned(&'a str, bool),
}

/// Runs the pre-pass.
pub(super) fn collect(l: &mut Lowerer) {
    let program = l.program;
    let mut found = Vec::new();
    for item in &program.items {
        match item {
            Item::Stmt(s) => scan(std::slice::from_ref(s), &[], &mut found),
            Item::Proc(p) => {
                for kc in &p.keyword_comments {
                    if let CommentKind::Keyword(_) = kc.kind {
                        for param in kc.params.iter().filter(|p| is_valid_name(&p.name) && !is_reserved(&p.name)) {
                            found.push(Found::Register(&param.name, param.span));
                        }
                    }
                }
                scan(&p.body, &proc_locals(p), &mut found);
            }
        }
    }
    for f in found {
        match f {
            Found::Register(name, span) => l.add_register(name, span),
            Found::Assigned(name, text) => {
                let key = name.to_lowercase();
                let entry = l.text_globals.entry(key.clone()).or_insert(text);
                *entry &= text;
                l.assigned.insert(key);
            }
        }
    }
}

/// Keys of a Sub's parameters and of every name it declares with `Dim` or
/// `Const`.
pub(super) fn proc_locals(p: &Procedure) -> Vec<String> {
    let mut keys: Vec<String> = p.params.iter().map(|f| f.name.key()).collect();
    each_stmt(&p.body, &mut |s| match &s.kind {
        StmtKind::Dim(items) => keys.extend(items.iter().map(|i| i.name.key())),
        StmtKind::Const(items) => keys.extend(items.iter().map(|(n, _)| n.key())),
        _ => {}
    });
    keys
}

fn scan<'a>(stmts: &'a [Stmt], locals: &[String], found: &mut Vec<Found<'a>>) {
    let is_local = |n: &Name| locals.contains(&n.key());
    each_stmt(stmts, &mut |s| {
        match &s.kind {
            StmtKind::SetProperty { register, .. } if !is_local(register) && !register.is(super::options::OPTIONS) => {
                found.push(Found::Register(&register.text, register.span))
            }
            StmtKind::Out(Some(e)) => {
                for part in out_parts(e) {
                    if let ExprKind::Text(t) = &part.kind {
                        for piece in split(t) {
                            if let TemplatePart::Register(name) = piece {
                                found.push(Found::Register(name, part.span));
                            }
                        }
                    }
                }
            }
            StmtKind::Assign { target, value } if !is_local(target) => {
                found.push(Found::Assigned(&target.text, is_text(value)))
            }
            StmtKind::For(f) if !is_local(&f.var) => found.push(Found::Assigned(&f.var.text, false)),
            _ => {}
        }
        stmt_exprs(s, &mut |e| {
            each_expr(e, &mut |x| {
                if let ExprKind::Previous(name) = &x.kind
                    && !is_local(name)
                {
                    found.push(Found::Register(&name.text, name.span));
                }
            })
        });
    });
}

/// Whether an expression is certainly text.
fn is_text(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Text(_) | ExprKind::Binary(crate::ast::BinaryOp::Concat, ..) => true,
        ExprKind::Paren(inner) => is_text(inner),
        ExprKind::Call { name, .. } => {
            ["Left", "Right", "Mid", "UCase", "LCase", "Str", "CStr", "Format", "Chr"].iter().any(|f| name.is(f))
        }
        _ => false,
    }
}

impl Lowerer<'_> {
    /// Makes a name a register (once; `N` and keywords excepted).
    pub(super) fn add_register(&mut self, name: &str, span: Span) {
        let key = name.to_lowercase();
        if key == "n" || self.registers.contains_key(&key) || Kw::from_word(name).is_some() {
            return;
        }
        let Some(id) = VarId::from_usize(self.specs.len()) else {
            self.too_many("registers");
            return;
        };
        self.specs.push(RegisterSpec { span: Some(span), ..RegisterSpec::new(name) });
        self.registers.insert(key, id);
    }

    /// The sequence-number register, created on first use.
    pub(super) fn sequence_var(&mut self) -> VarId {
        if let Some(id) = self.sequence {
            return id;
        }
        let id = VarId::from_usize(self.specs.len()).unwrap_or(VarId::new(0));
        self.specs.push(RegisterSpec::new("N"));
        self.sequence = Some(id);
        id
    }

    /// The register a name stands for (`N` is the sequence number).
    pub(super) fn register_var(&mut self, name: &str) -> Option<VarId> {
        let key = name.to_lowercase();
        if key == "n" {
            return Some(self.sequence_var());
        }
        self.registers.get(&key).copied()
    }

    fn local(&self, key: &str) -> Option<(LocalId, bool)> {
        let scope = self.scope.as_ref()?;
        if let Some(l) = scope.locals.get(key) {
            return Some(*l);
        }
        (scope.function.as_deref() == Some(key)).then_some(scope.ret.map(|r| (r, false))).flatten()
    }

    /// A name read as a value.
    pub(super) fn value(&mut self, name: &Name) -> IrExpr {
        let key = name.key();
        if let Some((slot, _)) = self.local(&key) {
            return IrExpr::Local(slot);
        }
        if key == "n" {
            return IrExpr::Quantity(Quantity::BlockNumber);
        }
        if let Some(var) = self.registers.get(&key) {
            return IrExpr::Var(*var);
        }
        if let Some(g) = self.globals.get_mut(&key) {
            g.first_read.get_or_insert(name.span);
            return IrExpr::Global(g.index);
        }
        if let Some(p) = self.procs.get(&key).cloned() {
            if p.kind == ProcKind::Function && p.params == 0 {
                return IrExpr::Call(p.id, Vec::new());
            }
            let d = if p.kind == ProcKind::Sub {
                Diagnostic::error(codes::NOT_A_VALUE, format!("Sub `{}` gives no value", name.text))
                    .at(name.span, "a Sub cannot be used in an expression")
                    .help("call it on a line of its own, or make it a Function")
            } else {
                Diagnostic::error(
                    codes::ARGUMENT_COUNT,
                    format!("Function `{}` needs {} argument(s)", name.text, p.params),
                )
                .at(name.span, "no arguments given")
            };
            self.diagnostics.push(d);
            return IrExpr::Number(0.0);
        }
        if crate::builtins::lookup(&key).is_some() || crate::routines::host_function(&key).is_some() {
            self.diagnostics.push(
                Diagnostic::error(
                    codes::ARGUMENT_COUNT,
                    format!("`{}` is a function and needs its arguments", name.text),
                )
                .at(name.span, format!("write `{}(...)`", name.text)),
            );
            return IrExpr::Number(0.0);
        }
        let index = self.new_global(&name.text, None, false, false);
        if let Some(g) = self.globals.get_mut(&key) {
            g.first_read.get_or_insert(name.span);
        }
        IrExpr::Global(index)
    }

    /// A name as the target of an assignment; `None` (reported) when it
    /// cannot be assigned.
    pub(super) fn place(&mut self, name: &Name) -> Option<Place> {
        let key = name.key();
        let refuse = |what: String, help: &str| {
            Diagnostic::error(codes::NOT_ASSIGNABLE, format!("`{}` cannot be assigned: {what}", name.text))
                .at(name.span, "not a variable")
                .help(help.to_string())
        };
        if let Some((slot, constant)) = self.local(&key) {
            if constant {
                self.diagnostics
                    .push(refuse("it is a `Const`".into(), "use a variable (`Dim`) for values that change"));
                return None;
            }
            return Some(Place::Local(slot));
        }
        if key == "n" {
            self.diagnostics.push(refuse(
                "it is the sequence number, which counts by itself".into(),
                "set the numbering outside the Subs with `N.Start = 10` and `N.Increment = 10`",
            ));
            return None;
        }
        if let Some(var) = self.registers.get(&key) {
            return Some(Place::Var(*var));
        }
        if let Some(g) = self.globals.get(&key) {
            if g.constant {
                self.diagnostics
                    .push(refuse("it is a `Const`".into(), "use a variable (`Dim`) for values that change"));
                return None;
            }
            return Some(Place::Global(g.index));
        }
        if let Some(p) = self.procs.get(&key) {
            let what = format!("it is a {}", p.kind.as_str());
            self.diagnostics
                .push(refuse(what, "a Function sets its result by assigning to its own name inside its body"));
            return None;
        }
        if crate::builtins::lookup(&key).is_some() || crate::routines::host_function(&key).is_some() {
            self.diagnostics.push(refuse("it is a built-in function".into(), "choose another name for the variable"));
            return None;
        }
        Some(Place::Global(self.new_global(&name.text, None, false, false)))
    }

    /// A hidden variable for a value computed once (loop bounds, the subject
    /// of a `Select Case`).
    pub(super) fn temp(&mut self, what: &str) -> (Place, IrExpr) {
        self.hidden += 1;
        let name = format!("${what}{}", self.hidden);
        if let Some(scope) = self.scope.as_mut() {
            let slot = LocalId::new(u16::try_from(scope.names.len()).unwrap_or(u16::MAX));
            scope.names.push(name);
            return (Place::Local(slot), IrExpr::Local(slot));
        }
        let index = self.new_global(&name, None, false, true);
        (Place::Global(index), IrExpr::Global(index))
    }

    /// An expression checked for depth, lowered.
    pub(super) fn expr_checked(&mut self, e: &Expr) -> IrExpr {
        let depth = e.depth();
        if depth > MAX_EXPR_DEPTH {
            self.diagnostics.push(
                Diagnostic::error(
                    codes::TOO_COMPLEX,
                    format!("this expression is nested too deeply ({depth} levels; at most {MAX_EXPR_DEPTH})"),
                )
                .at(e.span, "too deep")
                .help("split the calculation over several lines with intermediate variables"),
            );
            return IrExpr::Number(0.0);
        }
        self.expr(e)
    }
}

/// Reading a place back as a value.
pub(super) fn place_value(place: Place) -> IrExpr {
    match place {
        Place::Local(slot) => IrExpr::Local(slot),
        Place::Global(index) => IrExpr::Global(index),
        Place::Var(var) => IrExpr::Var(var),
    }
}
