//! Constant folding over native IR, with JavaScript's meaning of each
//! operator: settings known at compile time (`if (showSequenceNumbers)`)
//! drop out of the post's functions.

use postc_ir::{BinaryOp, Expr, Stmt, UnaryOp};

use super::consts::{self, Const};

fn as_const(e: &Expr) -> Option<Const> {
    Some(match e {
        Expr::Number(n) => Const::Num(*n),
        Expr::Text(s) => Const::Str(s.clone()),
        Expr::Bool(b) => Const::Bool(*b),
        Expr::Null => Const::Null,
        Expr::Undefined => Const::Undefined,
        _ => return None,
    })
}

fn js_op(op: BinaryOp) -> Option<crate::ast::BinaryOp> {
    use crate::ast::BinaryOp as J;
    Some(match op {
        BinaryOp::Add => J::Add,
        BinaryOp::Sub => J::Sub,
        BinaryOp::Mul => J::Mul,
        BinaryOp::Div => J::Div,
        BinaryOp::Rem => J::Rem,
        BinaryOp::Eq | BinaryOp::JsEq => J::Eq,
        BinaryOp::Ne | BinaryOp::JsNe => J::Ne,
        BinaryOp::StrictEq => J::StrictEq,
        BinaryOp::StrictNe => J::StrictNe,
        BinaryOp::Lt | BinaryOp::JsLt => J::Lt,
        BinaryOp::Le | BinaryOp::JsLe => J::Le,
        BinaryOp::Gt | BinaryOp::JsGt => J::Gt,
        BinaryOp::Ge | BinaryOp::JsGe => J::Ge,
        _ => return None,
    })
}

/// Folds an expression.
pub fn expr(e: Expr) -> Expr {
    match e {
        Expr::Unary(op, a) => {
            let a = expr(*a);
            match (op, as_const(&a)) {
                (UnaryOp::Not, Some(c)) => Expr::Bool(!c.truthy()),
                (UnaryOp::Plus, Some(Const::Num(n))) => Expr::Number(n),
                (UnaryOp::Plus, None) if matches!(a, Expr::Quantity(q) if !q.is_text()) => a,
                (UnaryOp::Neg, Some(Const::Num(n))) => Expr::Number(-n),
                _ => Expr::Unary(op, Box::new(a)),
            }
        }
        Expr::Binary(op, a, b) => {
            let (a, b) = (expr(*a), expr(*b));
            match op {
                BinaryOp::And | BinaryOp::Or => match as_const(&a) {
                    Some(c) if c.truthy() == (op == BinaryOp::And) => b,
                    Some(_) => a,
                    None => Expr::Binary(op, Box::new(a), Box::new(b)),
                },
                _ => match (js_op(op), as_const(&a), as_const(&b)) {
                    (Some(j), Some(x), Some(y)) => match consts::binary(j, &x, &y) {
                        Some(Const::Num(n)) => Expr::Number(n),
                        Some(Const::Str(s)) => Expr::Text(s),
                        Some(Const::Bool(v)) => Expr::Bool(v),
                        _ => Expr::Binary(op, Box::new(a), Box::new(b)),
                    },
                    _ => Expr::Binary(op, Box::new(a), Box::new(b)),
                },
            }
        }
        Expr::Choose(c, a, b) => {
            let c = expr(*c);
            match as_const(&c) {
                Some(k) if k.truthy() => expr(*a),
                Some(_) => expr(*b),
                None => Expr::Choose(Box::new(c), Box::new(expr(*a)), Box::new(expr(*b))),
            }
        }
        Expr::FormatVar { var, value, span } => Expr::FormatVar { var, value: Box::new(expr(*value)), span },
        Expr::Format { format, value, span } => Expr::Format { format, value: Box::new(expr(*value)), span },
        Expr::Call(f, args) => Expr::Call(f, args.into_iter().map(expr).collect()),
        Expr::Builtin(b, args) => Expr::Builtin(b, args.into_iter().map(expr).collect()),
        other => other,
    }
}

/// Folds statements; branches known not to run are dropped.
pub fn stmts(body: Vec<Stmt>) -> Vec<Stmt> {
    let mut out = Vec::with_capacity(body.len());
    for s in body {
        match s {
            Stmt::If { branches, otherwise } => {
                let mut kept = Vec::new();
                let mut rest = stmts(otherwise);
                for (c, b) in branches {
                    let c = expr(c);
                    match as_const(&c) {
                        Some(k) if k.truthy() => {
                            rest = stmts(b);
                            break;
                        }
                        Some(_) => {}
                        None => kept.push((c, stmts(b))),
                    }
                }
                if kept.is_empty() {
                    out.extend(rest);
                } else {
                    out.push(Stmt::If { branches: kept, otherwise: rest });
                }
            }
            Stmt::While { cond, body, span, step } => {
                let cond = expr(cond);
                if as_const(&cond).is_some_and(|c| !c.truthy()) {
                    continue;
                }
                let mut body = stmts(body);
                // `while (true) { ...; break; }` with no other way out runs once.
                let step = stmts(step);
                if matches!(cond, Expr::Bool(true))
                    && step.is_empty()
                    && matches!(body.last(), Some(Stmt::Break))
                    && !leaves(&body[..body.len() - 1])
                {
                    body.pop();
                    out.extend(body);
                    continue;
                }
                out.push(Stmt::While { cond, body, span, step });
            }
            Stmt::Write(e) => out.push(Stmt::Write(expr(e))),
            Stmt::Assign(p, e) => out.push(Stmt::Assign(p, expr(e))),
            Stmt::Eval(e) => out.push(Stmt::Eval(expr(e))),
            Stmt::Return(e) => {
                out.push(Stmt::Return(e.map(expr)));
                // Nothing after a return runs.
                break;
            }
            other => out.push(other),
        }
    }
    out
}

/// Whether statements leave or restart the loop around them.
fn leaves(body: &[Stmt]) -> bool {
    body.iter().any(|s| match s {
        Stmt::Break | Stmt::Continue => true,
        Stmt::If { branches, otherwise } => branches.iter().any(|(_, b)| leaves(b)) || leaves(otherwise),
        _ => false,
    })
}
