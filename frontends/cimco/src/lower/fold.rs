//! Clean-up passes over native IR: constant folding (so that settings
//! known at compile time, `if (showSequenceNumbers)`, drop out), and
//! interning of text literals into constant globals, so that reading one
//! costs a reference count instead of an allocation.

use postc_ir::{BinaryOp, Expr, Piece, Stmt, UnaryOp};

use super::consts::{self, Const};
use super::layout::Layout;

fn as_const(e: &Expr) -> Option<Const> {
    Some(match e {
        Expr::Number(n) => Const::Num(*n),
        Expr::Text(s) => Const::Str(s.clone()),
        Expr::Bool(b) => Const::Bool(*b),
        Expr::Null => Const::Undefined,
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
        Expr::FormatVar { var, value } => Expr::FormatVar { var, value: Box::new(expr(*value)) },
        Expr::Format { format, value } => Expr::Format { format, value: Box::new(expr(*value)) },
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
            Stmt::While { cond, body, span } => {
                let cond = expr(cond);
                if as_const(&cond).is_some_and(|c| !c.truthy()) {
                    continue;
                }
                let mut body = stmts(body);
                // `while (true) { ...; break; }` with no other way out runs once.
                if matches!(cond, Expr::Bool(true))
                    && matches!(body.last(), Some(Stmt::Break))
                    && !leaves(&body[..body.len() - 1])
                {
                    body.pop();
                    out.extend(body);
                    continue;
                }
                out.push(Stmt::While { cond, body, span });
            }
            Stmt::Write(e) => out.push(Stmt::Write(expr(e))),
            Stmt::Emit(pieces) => out.push(Stmt::Emit(
                pieces
                    .into_iter()
                    .map(|p| match p {
                        Piece::Expr(e) => match expr(e) {
                            Expr::Text(t) => Piece::Text(t.into_bytes()),
                            e => Piece::Expr(e),
                        },
                        other => other,
                    })
                    .collect(),
            )),
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

/// Replaces text literals read as values by constant globals.
pub fn intern_stmts(body: &mut [Stmt], layout: &mut Layout) {
    for s in body {
        match s {
            Stmt::Line { pieces, .. } | Stmt::Emit(pieces) => {
                for p in pieces {
                    if let Piece::Expr(e) = p {
                        intern(e, layout);
                    }
                }
            }
            Stmt::Write(e) | Stmt::Assign(_, e) | Stmt::Eval(e) => intern(e, layout),
            Stmt::Return(Some(e)) => intern(e, layout),
            Stmt::If { branches, otherwise } => {
                for (c, b) in branches {
                    intern(c, layout);
                    intern_stmts(b, layout);
                }
                intern_stmts(otherwise, layout);
            }
            Stmt::While { cond, body, .. } => {
                intern(cond, layout);
                intern_stmts(body, layout);
            }
            _ => {}
        }
    }
}

fn intern(e: &mut Expr, layout: &mut Layout) {
    match e {
        Expr::Text(s) => *e = Expr::Global(layout.text_constant(s)),
        Expr::Unary(_, a) | Expr::FormatVar { value: a, .. } | Expr::Format { value: a, .. } => intern(a, layout),
        Expr::Binary(_, a, b) => {
            intern(a, layout);
            intern(b, layout);
        }
        Expr::Choose(c, a, b) => {
            intern(c, layout);
            intern(a, layout);
            intern(b, layout);
        }
        Expr::Call(_, args) | Expr::Builtin(_, args) => args.iter_mut().for_each(|a| intern(a, layout)),
        _ => {}
    }
}
