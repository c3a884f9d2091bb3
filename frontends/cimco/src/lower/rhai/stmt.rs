//! Statements in Rhai.

use crate::ast::*;

use super::{Gen, Jump, local_name};

impl Gen<'_, '_> {
    pub(super) fn stmt(&mut self, s: &Stmt) {
        if self.done(s) {
            return;
        }
        self.mark(s.span);
        match &s.kind {
            StmtKind::Var(ds) => {
                for d in ds {
                    if let Some(init) = &d.init {
                        let target = Expr::new(ExprKind::Ident(d.name.name.clone()), d.name.span);
                        self.assign_stmt(&target, AssignOp::Assign, init);
                    }
                }
            }
            StmtKind::Function(_) | StmtKind::Empty | StmtKind::Error => {}
            StmtKind::Expr(e) => match &e.kind {
                ExprKind::Assign { op, target, value } => self.assign_stmt(target, *op, value),
                _ => {
                    self.expr(e);
                    self.w(";\n");
                }
            },
            StmtKind::Block(b) => {
                self.w("{\n");
                for s in b {
                    self.stmt(s);
                }
                self.w("}\n");
            }
            StmtKind::If { branches, otherwise } => {
                for (i, b) in branches.iter().enumerate() {
                    self.w(if i == 0 { "if " } else { " else if " });
                    self.cond(&b.cond);
                    self.w(" {\n");
                    self.stmt(&b.body);
                    self.w("}");
                }
                if let Some(o) = otherwise {
                    self.w(" else {\n");
                    self.stmt(o);
                    self.w("}");
                }
                self.w("\n");
            }
            StmtKind::While { cond, body } => {
                self.loop_at = s.span.start;
                self.w("while ");
                self.cond(cond);
                self.w(" {\n");
                self.loop_body(body);
                self.w("}\n");
            }
            StmtKind::DoWhile { body, cond } => {
                self.loop_at = s.span.start;
                self.w("do {\n");
                self.loop_body(body);
                self.w("} while ");
                self.cond(cond);
                self.w(";\n");
            }
            StmtKind::For { init, test, update, body } => {
                self.loop_at = s.span.start;
                self.w("{\n");
                match init {
                    Some(ForInit::Var(ds)) => {
                        let v = Stmt::new(StmtKind::Var(ds.clone()), s.span);
                        self.stmt(&v);
                    }
                    Some(ForInit::Expr(e)) => {
                        let st = Stmt::new(StmtKind::Expr(e.clone()), e.span);
                        self.stmt(&st);
                    }
                    None => {}
                }
                let first = self.temp("f");
                self.w(&format!("let {first} = true;\nloop {{\nif !{first} {{\n"));
                if let Some(u) = update {
                    let st = Stmt::new(StmtKind::Expr(u.clone()), u.span);
                    self.stmt(&st);
                }
                self.w(&format!("}}\n{first} = false;\n"));
                if let Some(t) = test {
                    self.mark(t.span);
                    self.w("if !");
                    self.cond(t);
                    self.w(" { break; }\n");
                }
                self.loop_body(body);
                self.w("}\n}\n");
            }
            StmtKind::ForIn { name, object, body, .. } => {
                self.loop_at = s.span.start;
                let k = self.temp("k");
                self.w(&format!("for {k} in __keys("));
                self.expr(object);
                self.w(") {\n");
                let target = Expr::new(ExprKind::Ident(name.name.clone()), name.span);
                self.store(&target, &k);
                self.w(";\n");
                self.loop_body(body);
                self.w("}\n");
            }
            StmtKind::Switch { discriminant, cases } => self.switch(discriminant, cases),
            StmtKind::Break => self.w("break;\n"),
            StmtKind::Continue => match self.jumps.iter().rev().find(|_| true).cloned() {
                Some(Jump::Switch(flag)) => self.w(&format!("{flag} = true;\nbreak;\n")),
                _ => self.w("continue;\n"),
            },
            StmtKind::Return(e) => {
                self.w("return ");
                match e {
                    Some(e) => self.expr(e),
                    None => self.w("()"),
                }
                self.w(";\n");
            }
            StmtKind::Throw(e) => {
                self.w("throw ");
                self.expr(e);
                self.w(";\n");
            }
            StmtKind::Try { block, handler, finalizer } => self.try_stmt(block, handler.as_ref(), finalizer.as_deref()),
        }
    }

    /// A loop's body; each pass counts against the step budget, which
    /// names this loop when it runs out.
    fn loop_body(&mut self, body: &Stmt) {
        self.jumps.push(Jump::Loop);
        self.w(&format!("__tick({});\n", self.loop_at));
        self.stmt(body);
        self.jumps.pop();
    }

    /// `switch`: the index of the first matching case (or `default`), then
    /// every case from there on until a `break`.
    fn switch(&mut self, disc: &Expr, cases: &[SwitchCase]) {
        let (d, i, c) = (self.temp("d"), self.temp("i"), self.temp("c"));
        self.w(&format!("let {d} = "));
        self.expr(disc);
        let default = cases.iter().position(|c| c.test.is_none()).unwrap_or(cases.len());
        self.w(&format!(";\nlet {i} = {default};\nlet {c} = false;\n"));
        let mut first = true;
        for (k, case) in cases.iter().enumerate() {
            if let Some(t) = &case.test {
                self.mark(t.span);
                self.w(if first { "if " } else { " else if " });
                first = false;
                self.w(&format!("__seq({d}, "));
                self.expr(t);
                self.w(&format!(") {{ {i} = {k}; }}"));
            }
        }
        if !first {
            self.w("\n");
        }
        self.w("loop {\n");
        self.jumps.push(Jump::Switch(c.clone()));
        for (k, case) in cases.iter().enumerate() {
            self.mark(case.span);
            self.w(&format!("if {i} <= {k} {{\n"));
            for s in &case.body {
                self.stmt(s);
            }
            self.w("}\n");
        }
        self.jumps.pop();
        self.w("break;\n}\n");
        match self.jumps.last().cloned() {
            Some(Jump::Switch(outer)) => self.w(&format!("if {c} {{ {outer} = true; break; }}\n")),
            Some(Jump::Loop) => self.w(&format!("if {c} {{ continue; }}\n")),
            None => {}
        }
    }

    fn try_stmt(&mut self, block: &[Stmt], handler: Option<&CatchClause>, finalizer: Option<&[Stmt]>) {
        self.w("try {\n");
        for s in block {
            self.stmt(s);
        }
        self.w("} catch (");
        match handler {
            Some(h) => {
                let e = self.temp("e");
                self.w(&format!("{e}) {{\n"));
                let target = Expr::new(ExprKind::Ident(h.param.name.clone()), h.param.span);
                self.store(&target, &format!("__caught({e})"));
                self.w(";\n");
                for s in &h.body {
                    self.stmt(s);
                }
                self.w("}\n");
            }
            None => {
                let e = self.temp("e");
                self.w(&format!("{e}) {{\n"));
                for s in finalizer.unwrap_or(&[]) {
                    self.stmt(s);
                }
                self.w(&format!("throw {e};\n}}\n"));
            }
        }
        for s in finalizer.unwrap_or(&[]) {
            self.stmt(s);
        }
    }

    /// `target = value` as a statement.
    fn assign_stmt(&mut self, target: &Expr, op: AssignOp, value: &Expr) {
        self.assign_expr(target, op, value);
        self.w(";\n");
    }

    /// Stores Rhai text `value` into a JavaScript target (no compound).
    pub(super) fn store(&mut self, target: &Expr, value: &str) {
        match &target.kind {
            ExprKind::Ident(name) => match self.target_of(name) {
                super::expr::Target::Local(v) => self.w(&format!("{v} = {value}")),
                super::expr::Target::Global(i) => self.w(&format!("__gs({i}, {value})")),
                super::expr::Target::None => self.w(&format!("__assign_error({})", super::quote(name))),
            },
            _ => {
                let _ = local_name;
                self.w(&format!("__assign_error({})", super::quote("?")));
            }
        }
    }
}
