//! Lowering control flow: loops, `Select Case` and `Exit`.
//!
//! - `For v = a To b Step s` becomes `v = a`, the bound and step kept in
//!   hidden variables unless they are plain numbers, then
//!   `While v <= b (or v >= b for a negative step) { body; v = v + s }`.
//! - `Select Case x` keeps `x` in a hidden variable unless it is a plain
//!   name or number and becomes an `If` chain: `Case 1, 2` is
//!   `x = 1 Or x = 2`, `Case 1 To 5` is `x >= 1 And x <= 5`, `Case Is > 3`
//!   is `x > 3`.
//! - `While c`/`Do While c` is `While c`; `Do Until c` is `While Not c`;
//!   `Do ... Loop While c` is `While True { body; If Not c Then Exit }`.
//! - `Exit For`/`Exit Do` is `Break` of the innermost loop, which must be of
//!   that kind; `Exit Sub` is `Return`; `Exit Function` returns the result.

use postc_ir::{BinaryOp as IrOp, Diagnostic, Expr as IrExpr, Stmt as IrStmt, UnaryOp as IrUnary};

use super::names::place_value;
use super::{LoopFrame, Lowerer};
use crate::ast::{CaseTest, ExitKind, ExprKind, LoopKind, LoopTest, ProcKind, Stmt, UnaryOp};
use crate::diagnostics as codes;

impl Lowerer<'_> {
    pub(super) fn loop_stmt(
        &mut self,
        test: Option<&LoopTest>,
        at_end: bool,
        body: &[Stmt],
        kind: LoopKind,
        s: &Stmt,
    ) -> Vec<IrStmt> {
        let frame = if kind == LoopKind::While { LoopFrame::While } else { LoopFrame::Do };
        self.loops.push(frame);
        let mut lowered = self.block(body);
        self.loops.pop();
        let cond = match (test, at_end) {
            (Some(t), false) => self.loop_condition(t, false),
            (Some(t), true) => {
                let stop = self.loop_condition(t, true);
                lowered.push(IrStmt::If { branches: vec![(stop, vec![IrStmt::Break])], otherwise: Vec::new() });
                IrExpr::Bool(true)
            }
            (None, _) => IrExpr::Bool(true),
        };
        vec![IrStmt::While { cond, body: lowered, span: Some(s.span), step: vec![] }]
    }

    /// The condition that keeps a loop going (or, `negate`, that stops it).
    fn loop_condition(&mut self, t: &LoopTest, negate: bool) -> IrExpr {
        let c = self.expr_checked(&t.cond);
        if t.until != negate { IrExpr::Unary(IrUnary::Not, Box::new(c)) } else { c }
    }

    pub(super) fn exit(&mut self, kind: ExitKind, s: &Stmt) -> Option<IrStmt> {
        let in_kind =
            self.scope.as_ref().map(|sc| if sc.function.is_some() { ProcKind::Function } else { ProcKind::Sub });
        let refuse = |message: String, help: &str| {
            Diagnostic::error(codes::MISPLACED_EXIT, message)
                .at(s.span, "cannot leave from here")
                .help(help.to_string())
        };
        match kind {
            ExitKind::Sub | ExitKind::Function => {
                let want = if kind == ExitKind::Sub { ProcKind::Sub } else { ProcKind::Function };
                if in_kind == Some(want) {
                    let ret = self.scope.as_ref().and_then(|sc| sc.ret);
                    return Some(IrStmt::Return(ret.map(IrExpr::Local)));
                }
                let help = match in_kind {
                    Some(k) => format!("inside a {} write `Exit {}`", k.as_str(), k.as_str()),
                    None => "outside the Subs there is nothing to leave".to_string(),
                };
                self.diagnostics.push(refuse(format!("`Exit {}` outside a {}", want.as_str(), want.as_str()), &help));
                None
            }
            ExitKind::For | ExitKind::Do | ExitKind::While => {
                let (want, word) = match kind {
                    ExitKind::For => (LoopFrame::For, "For"),
                    ExitKind::Do => (LoopFrame::Do, "Do"),
                    _ => (LoopFrame::While, "While"),
                };
                if self.loops.last() == Some(&want) {
                    return Some(IrStmt::Break);
                }
                let d = if self.loops.contains(&want) {
                    refuse(
                        format!("`Exit {word}` from inside another kind of loop is not supported"),
                        "set a flag variable, leave the inner loop, and test the flag after it",
                    )
                } else {
                    refuse(
                        format!("`Exit {word}` outside a {word} loop"),
                        "remove it, or put it inside the loop it should leave",
                    )
                };
                self.diagnostics.push(d);
                None
            }
        }
    }

    pub(super) fn select(
        &mut self,
        subject: &crate::ast::Expr,
        cases: &[crate::ast::CaseArm],
        otherwise: &[Stmt],
    ) -> Vec<IrStmt> {
        let mut out = Vec::new();
        let lowered = self.expr_checked(subject);
        let value = match lowered {
            IrExpr::Number(_)
            | IrExpr::Text(_)
            | IrExpr::Bool(_)
            | IrExpr::Local(_)
            | IrExpr::Global(_)
            | IrExpr::Var(_) => lowered,
            other => {
                let (place, value) = self.temp("select");
                out.push(IrStmt::Assign(place, other));
                value
            }
        };
        let mut branches = Vec::new();
        for arm in cases {
            let mut cond: Option<IrExpr> = None;
            for test in &arm.tests {
                let one = match test {
                    CaseTest::Value(e) => bin(IrOp::Eq, value.clone(), self.expr_checked(e)),
                    CaseTest::Is(op, e) => {
                        bin(super::expr::binary_op(*op).unwrap_or(IrOp::Eq), value.clone(), self.expr_checked(e))
                    }
                    CaseTest::Range(a, b) => {
                        let low = bin(IrOp::Ge, value.clone(), self.expr_checked(a));
                        bin(IrOp::And, low, bin(IrOp::Le, value.clone(), self.expr_checked(b)))
                    }
                };
                cond = Some(match cond {
                    Some(c) => bin(IrOp::Or, c, one),
                    None => one,
                });
            }
            let body = self.block(&arm.body);
            branches.push((cond.unwrap_or(IrExpr::Bool(false)), body));
        }
        let otherwise = self.block(otherwise);
        if branches.is_empty() {
            out.extend(otherwise);
        } else {
            out.push(IrStmt::If { branches, otherwise });
        }
        out
    }

    pub(super) fn for_loop(&mut self, f: &crate::ast::ForLoop, s: &Stmt) -> Vec<IrStmt> {
        let (var, from, to, step, body) = (&f.var, &f.from, &f.to, f.step.as_ref(), &f.body);
        let mut out = Vec::new();
        let start = self.expr_checked(from);
        let Some(place) = self.place(var) else { return out };
        out.push(IrStmt::Assign(place, start));
        let counter = place_value(place);
        let end = self.once(to, "to", &mut out);
        let step_value = match step {
            Some(e) => self.once(e, "step", &mut out),
            None => IrExpr::Number(1.0),
        };
        let cond = match literal_sign(step) {
            Some(false) => bin(IrOp::Ge, counter.clone(), end),
            Some(true) => bin(IrOp::Le, counter.clone(), end),
            None => IrExpr::Choose(
                Box::new(bin(IrOp::Ge, step_value.clone(), IrExpr::Number(0.0))),
                Box::new(bin(IrOp::Le, counter.clone(), end.clone())),
                Box::new(bin(IrOp::Ge, counter.clone(), end)),
            ),
        };
        self.loops.push(LoopFrame::For);
        let mut lowered = self.block(body);
        self.loops.pop();
        lowered.push(IrStmt::Assign(place, bin(IrOp::Add, counter, step_value)));
        out.push(IrStmt::While { cond, body: lowered, span: Some(s.span), step: vec![] });
        out
    }

    /// A value computed once: literal numbers stay, others go to a hidden
    /// variable assigned before the loop.
    fn once(&mut self, e: &crate::ast::Expr, what: &str, out: &mut Vec<IrStmt>) -> IrExpr {
        let lowered = self.expr_checked(e);
        if matches!(lowered, IrExpr::Number(_))
            || matches!(&lowered, IrExpr::Unary(IrUnary::Neg, inner) if matches!(**inner, IrExpr::Number(_)))
        {
            return lowered;
        }
        let (place, value) = self.temp(what);
        out.push(IrStmt::Assign(place, lowered));
        value
    }
}

/// Whether a step is a literal that is not negative (`Some(true)`),
/// negative (`Some(false)`), or not a literal (`None`). No step is 1.
fn literal_sign(step: Option<&crate::ast::Expr>) -> Option<bool> {
    let Some(e) = step else { return Some(true) };
    match &e.kind {
        ExprKind::Number(n) => Some(*n >= 0.0),
        ExprKind::Unary(UnaryOp::Neg, inner) => match inner.kind {
            ExprKind::Number(n) => Some(n <= 0.0),
            _ => None,
        },
        ExprKind::Paren(inner) => literal_sign(Some(inner)),
        _ => None,
    }
}

fn bin(op: IrOp, a: IrExpr, b: IrExpr) -> IrExpr {
    IrExpr::Binary(op, Box::new(a), Box::new(b))
}
