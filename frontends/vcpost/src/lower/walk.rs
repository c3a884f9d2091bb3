//! Walking the syntax tree: every statement, every expression, in file
//! order. The lowering's pre-passes use these to find registers, string
//! variables and the names a post assigns before lowering any body.

use crate::ast::{CaseTest, Expr, ExprKind, LoopTest, Stmt, StmtKind};

/// Calls `f` on each statement of `stmts` and of every nested body, parents
/// before children.
pub fn each_stmt<'a>(stmts: &'a [Stmt], f: &mut impl FnMut(&'a Stmt)) {
    for s in stmts {
        f(s);
        match &s.kind {
            StmtKind::If { branches, otherwise } => {
                for (_, body) in branches {
                    each_stmt(body, f);
                }
                each_stmt(otherwise, f);
            }
            StmtKind::Select { cases, otherwise, .. } => {
                for arm in cases {
                    each_stmt(&arm.body, f);
                }
                each_stmt(otherwise, f);
            }
            StmtKind::For(l) => each_stmt(&l.body, f),
            StmtKind::Loop { body, .. } => each_stmt(body, f),
            _ => {}
        }
    }
}

/// Calls `f` on each top-level expression a statement holds (not those of
/// nested bodies).
pub fn stmt_exprs<'a>(s: &'a Stmt, f: &mut impl FnMut(&'a Expr)) {
    match &s.kind {
        StmtKind::Assign { value, .. } | StmtKind::SetProperty { value, .. } => f(value),
        StmtKind::Dim(items) => items.iter().filter_map(|i| i.init.as_ref()).for_each(f),
        StmtKind::Const(items) => items.iter().for_each(|(_, e)| f(e)),
        StmtKind::Call { args, .. } => args.iter().for_each(f),
        StmtKind::Out(Some(e)) => f(e),
        StmtKind::If { branches, .. } => branches.iter().for_each(|(c, _)| f(c)),
        StmtKind::Select { subject, cases, .. } => {
            f(subject);
            for arm in cases {
                for t in &arm.tests {
                    match t {
                        CaseTest::Value(e) | CaseTest::Is(_, e) => f(e),
                        CaseTest::Range(a, b) => {
                            f(a);
                            f(b);
                        }
                    }
                }
            }
        }
        StmtKind::For(l) => {
            f(&l.from);
            f(&l.to);
            if let Some(s) = &l.step {
                f(s);
            }
        }
        StmtKind::Loop { test: Some(LoopTest { cond, .. }), .. } => f(cond),
        _ => {}
    }
}

/// Calls `f` on an expression and every sub-expression.
pub fn each_expr<'a>(e: &'a Expr, f: &mut impl FnMut(&'a Expr)) {
    f(e);
    match &e.kind {
        ExprKind::Call { args, .. } => args.iter().for_each(|a| each_expr(a, f)),
        ExprKind::Unary(_, inner) | ExprKind::Paren(inner) => each_expr(inner, f),
        ExprKind::Binary(_, a, b) => {
            each_expr(a, f);
            each_expr(b, f);
        }
        _ => {}
    }
}
