//! Checks on a parsed program that the grammar does not make:
//! `return` only inside functions, `break` only inside loops and
//! `switch`, `continue` only inside loops.

use postc_ir::Diagnostic;

use crate::ast::*;
use crate::diagnostics as d;

/// The problems in `program`.
pub fn check(program: &Program) -> Vec<Diagnostic> {
    let mut v = Validator { diagnostics: Vec::new() };
    let top = Context { in_function: false, in_loop: false, in_switch: false };
    for s in &program.body {
        v.stmt(s, top);
    }
    v.diagnostics
}

#[derive(Clone, Copy)]
struct Context {
    in_function: bool,
    in_loop: bool,
    in_switch: bool,
}

struct Validator {
    diagnostics: Vec<Diagnostic>,
}

impl Validator {
    fn function(&mut self, f: &Function) {
        let cx = Context { in_function: true, in_loop: false, in_switch: false };
        for s in &f.body {
            self.stmt(s, cx);
        }
    }

    fn stmts(&mut self, body: &[Stmt], cx: Context) {
        for s in body {
            self.stmt(s, cx);
        }
    }

    fn stmt(&mut self, s: &Stmt, cx: Context) {
        let looped = Context { in_loop: true, ..cx };
        match &s.kind {
            StmtKind::Var(decls) => self.declarators(decls),
            StmtKind::Function(f) => self.function(f),
            StmtKind::Expr(e) | StmtKind::Throw(e) => self.expr(e),
            StmtKind::Block(body) => self.stmts(body, cx),
            StmtKind::Empty | StmtKind::Error => {}
            StmtKind::If { branches, otherwise } => {
                for b in branches {
                    self.expr(&b.cond);
                    self.stmt(&b.body, cx);
                }
                if let Some(o) = otherwise {
                    self.stmt(o, cx);
                }
            }
            StmtKind::Switch { discriminant, cases } => {
                self.expr(discriminant);
                let inner = Context { in_switch: true, ..cx };
                for c in cases {
                    if let Some(t) = &c.test {
                        self.expr(t);
                    }
                    self.stmts(&c.body, inner);
                }
            }
            StmtKind::For { init, test, update, body } => {
                match init {
                    Some(ForInit::Var(decls)) => self.declarators(decls),
                    Some(ForInit::Expr(e)) => self.expr(e),
                    None => {}
                }
                for e in test.iter().chain(update.iter()) {
                    self.expr(e);
                }
                self.stmt(body, looped);
            }
            StmtKind::ForIn { object, body, .. } => {
                self.expr(object);
                self.stmt(body, looped);
            }
            StmtKind::While { cond, body } | StmtKind::DoWhile { body, cond } => {
                self.expr(cond);
                self.stmt(body, looped);
            }
            StmtKind::Break => {
                if !cx.in_loop && !cx.in_switch {
                    self.diagnostics.push(
                        Diagnostic::error(d::JUMP_OUTSIDE_LOOP, "`break` is only allowed inside a loop or a `switch`")
                            .at(s.span, "nothing to break out of"),
                    );
                }
            }
            StmtKind::Continue => {
                if !cx.in_loop {
                    self.diagnostics.push(
                        Diagnostic::error(d::JUMP_OUTSIDE_LOOP, "`continue` is only allowed inside a loop")
                            .at(s.span, "not inside a loop"),
                    );
                }
            }
            StmtKind::Return(value) => {
                if let Some(v) = value {
                    self.expr(v);
                }
                if !cx.in_function {
                    self.diagnostics.push(
                        Diagnostic::error(d::RETURN_OUTSIDE_FUNCTION, "`return` is only allowed inside a function")
                            .at(s.span, "outside any function")
                            .help("the statements at the top of a post run once, when the post is loaded; put this in a function such as `onOpen`"),
                    );
                }
            }
            StmtKind::Try { block, handler, finalizer } => {
                self.stmts(block, cx);
                if let Some(h) = handler {
                    self.stmts(&h.body, cx);
                }
                if let Some(f) = finalizer {
                    self.stmts(f, cx);
                }
            }
        }
    }

    fn declarators(&mut self, decls: &[VarDeclarator]) {
        for d in decls {
            if let Some(init) = &d.init {
                self.expr(init);
            }
        }
    }

    /// Looks into expressions only for function expressions.
    fn expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Function(f) => self.function(f),
            ExprKind::Array(items) | ExprKind::Sequence(items) => items.iter().for_each(|i| self.expr(i)),
            ExprKind::Object(props) => props.iter().for_each(|p| self.expr(&p.value)),
            ExprKind::Member { object: a, .. }
            | ExprKind::Unary { operand: a, .. }
            | ExprKind::Update { target: a, .. } => self.expr(a),
            ExprKind::Index { object: a, index: b }
            | ExprKind::Binary { left: a, right: b, .. }
            | ExprKind::Logical { left: a, right: b, .. }
            | ExprKind::Assign { target: a, value: b, .. } => {
                self.expr(a);
                self.expr(b);
            }
            ExprKind::Call { callee, args } | ExprKind::New { callee, args } => {
                self.expr(callee);
                args.iter().for_each(|a| self.expr(a));
            }
            ExprKind::Conditional { test, consequent, alternate } => {
                self.expr(test);
                self.expr(consequent);
                self.expr(alternate);
            }
            _ => {}
        }
    }
}
