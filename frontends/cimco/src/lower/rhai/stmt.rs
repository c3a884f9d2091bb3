//! Statements in Rhai.

use crate::ast::*;
use crate::host_names as names;

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
                self.w(&format!("for {k} in {KEYS}(", KEYS = names::KEYS));
                self.expr(object);
                self.w(") {\n");
                let target = Expr::new(ExprKind::Ident(name.name.clone()), name.span);
                self.store(&target, &k);
                self.w(";\n");
                self.loop_body(body);
                self.w("}\n");
            }
            StmtKind::Switch { discriminant, cases } => self.switch(discriminant, cases),
            StmtKind::Break => self.jump_break(),
            StmtKind::Continue => self.jump_continue(),
            StmtKind::Return(e) => {
                let tried = self.jumps.iter().any(|j| matches!(j, Jump::Try));
                self.w(&if tried { format!("throw {}(1, ", names::JUMP) } else { "return ".to_string() });
                match e {
                    Some(e) => self.expr(e),
                    None => self.w("()"),
                }
                self.w(if tried { ");\n" } else { ";\n" });
            }
            StmtKind::Throw(e) => {
                self.w("throw ");
                self.expr(e);
                self.w(";\n");
            }
            StmtKind::Try { block, handler, finalizer } => self.try_stmt(block, handler.as_ref(), finalizer.as_deref()),
        }
    }

    /// `break`: out of the innermost loop or switch, or, first, out of a
    /// `try` whose `finally` must run.
    fn jump_break(&mut self) {
        match self.jumps.last().cloned() {
            Some(Jump::Try) => self.w(&format!("throw {}(2, ());\n", names::JUMP)),
            _ => self.w("break;\n"),
        }
    }

    /// `continue`: to the next pass of the innermost loop, through the
    /// switches and `try`s around it.
    fn jump_continue(&mut self) {
        match self.jumps.last().cloned() {
            Some(Jump::Switch(flag)) => self.w(&format!("{flag} = true;\nbreak;\n")),
            Some(Jump::Try) => self.w(&format!("throw {}(3, ());\n", names::JUMP)),
            _ => self.w("continue;\n"),
        }
    }

    /// A loop's body; each pass counts against the step budget, which
    /// names this loop when it runs out.
    fn loop_body(&mut self, body: &Stmt) {
        self.jumps.push(Jump::Loop);
        self.w(&format!("{TICK}({});\n", self.loop_at, TICK = names::TICK));
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
                self.w(&format!("{SEQ}({d}, ", SEQ = names::SEQ));
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
        if !self.jumps.is_empty() {
            self.w(&format!("if {c} {{\n"));
            self.jump_continue();
            self.w("}\n");
        }
    }

    /// `try`: the body and the `catch` run inside Rhai `try`s; what leaves
    /// them (a jump or an error, also an error of the `catch`) is recorded
    /// in a completion variable (0 normal, 1 return, 2 break, 3 continue,
    /// 4 throw) and a value; then the `finally` runs, then the recorded
    /// jump or error goes on, as JavaScript does.
    fn try_stmt(&mut self, block: &[Stmt], handler: Option<&CatchClause>, finalizer: Option<&[Stmt]>) {
        let (c, v, e) = (self.temp("c"), self.temp("v"), self.temp("e"));
        let record = format!(
            "let {c}_k = {JUMP_KIND}({e});\nif {c}_k > 0 {{\n{c} = {c}_k;\n{v} = {JUMP_VALUE}({e});\n}} else {{\n",
            JUMP_KIND = names::JUMP_KIND,
            JUMP_VALUE = names::JUMP_VALUE
        );
        self.w(&format!("let {c} = 0;\nlet {v} = ();\ntry {{\n"));
        self.jumps.push(Jump::Try);
        for s in block {
            self.stmt(s);
        }
        self.w(&format!("}} catch ({e}) {{\n{record}"));
        match handler {
            Some(h) => {
                let e2 = self.temp("e");
                self.w("try {\n");
                let target = Expr::new(ExprKind::Ident(h.param.name.clone()), h.param.span);
                self.store(&target, &format!("{CAUGHT}({e})", CAUGHT = names::CAUGHT));
                self.w(";\n");
                for s in &h.body {
                    self.stmt(s);
                }
                let c2 = format!("{c}_k2");
                self.w(&format!(
                    "}} catch ({e2}) {{\nlet {c2} = {JUMP_KIND}({e2});\nif {c2} > 0 {{\n{c} = {c2};\n{v} = {JUMP_VALUE}({e2});\n}} else {{\n{c} = 4;\n{v} = {e2};\n}}\n}}\n", JUMP_KIND = names::JUMP_KIND, JUMP_VALUE = names::JUMP_VALUE));
            }
            None => self.w(&format!("{c} = 4;\n{v} = {e};\n")),
        }
        self.jumps.pop();
        self.w("}\n}\n");
        for s in finalizer.unwrap_or(&[]) {
            self.stmt(s);
        }
        self.w(&format!("if {c} == 1 {{\n"));
        let tried = self.jumps.iter().any(|j| matches!(j, Jump::Try));
        self.w(&if tried { format!("throw {JUMP}(1, {v});\n", JUMP = names::JUMP) } else { format!("return {v};\n") });
        // Outside any loop a `break` or `continue` cannot have left the
        // `try` (and Rhai refuses one there).
        if !self.jumps.is_empty() {
            self.w(&format!("}} else if {c} == 2 {{\n"));
            self.jump_break();
            self.w(&format!("}} else if {c} == 3 {{\n"));
            self.jump_continue();
        }
        self.w(&format!("}} else if {c} == 4 {{\nthrow {v};\n}}\n"));
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
                super::expr::Target::Global(i) => {
                    self.w(&format!("{GLOBAL_SET}({i}, {value})", GLOBAL_SET = names::GLOBAL_SET))
                }
                super::expr::Target::None => {
                    self.w(&format!("{ASSIGN_ERROR}({})", super::quote(name), ASSIGN_ERROR = names::ASSIGN_ERROR))
                }
            },
            _ => {
                let _ = local_name;
                self.w(&format!("{ASSIGN_ERROR}({})", super::quote("?"), ASSIGN_ERROR = names::ASSIGN_ERROR));
            }
        }
    }
}
