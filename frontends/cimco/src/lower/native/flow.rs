//! `switch` statements whose cases fall through, or whose `default` is not
//! last.

use postc_ir::{BinaryOp as IrBin, Expr as Ir, Place, Stmt as IrStmt};

use crate::ast::*;

use super::{Native, R, has_continue, why};

impl Native<'_, '_> {
    /// The general `switch`: the index of the case that matches (the first
    /// whose test is `===` the value, tested in order, else the
    /// `default`'s), then every case body in order, each run when it
    /// matched or an earlier one ran, inside a loop that runs once so that
    /// `break` leaves it.
    pub(super) fn switch_fallthrough(
        &mut self,
        disc: &Expr,
        cases: &[SwitchCase],
        at: postc_ir::Span,
        out: &mut Vec<IrStmt>,
    ) -> R<()> {
        if cases.iter().any(|c| c.body.iter().any(has_continue)) {
            return Err(why(disc.span, "`continue` in a `switch` whose cases fall through"));
        }
        let value = self.temp();
        out.push(IrStmt::Assign(Place::Local(value), self.expr(disc)?));
        let default = cases.iter().position(|c| c.test.is_none());
        let mut tests = Vec::new();
        for (i, c) in cases.iter().enumerate() {
            if let Some(t) = &c.test {
                tests.push((i, self.expr(t)?));
            }
        }
        let mut matched = Ir::Number(default.map_or(-1.0, |d| d as f64));
        for (i, t) in tests.into_iter().rev() {
            let eq = Ir::Binary(IrBin::StrictEq, Box::new(Ir::Local(value)), Box::new(t));
            matched = Ir::Choose(Box::new(eq), Box::new(Ir::Number(i as f64)), Box::new(matched));
        }
        let case = self.temp();
        out.push(IrStmt::Assign(Place::Local(case), matched));
        let running = self.temp();
        out.push(IrStmt::Assign(Place::Local(running), Ir::Bool(false)));
        let mut body = Vec::new();
        for (i, c) in cases.iter().enumerate() {
            let mut b = vec![IrStmt::Assign(Place::Local(running), Ir::Bool(true))];
            b.extend(self.stmts(&c.body)?);
            let this = Ir::Binary(IrBin::StrictEq, Box::new(Ir::Local(case)), Box::new(Ir::Number(i as f64)));
            let cond = Ir::Binary(IrBin::Or, Box::new(Ir::Local(running)), Box::new(this));
            body.push(IrStmt::If { branches: vec![(cond, b)], otherwise: vec![] });
        }
        body.push(IrStmt::Break);
        out.push(IrStmt::While { cond: Ir::Bool(true), body, span: Some(at), step: vec![] });
        Ok(())
    }
}
