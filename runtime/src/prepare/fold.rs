//! Constant folding over the runtime's code, with the interpreter's own
//! operators ([`crate::interp`]): what the fast path's inlining makes
//! constant (`movement == 0` once `movement` is known to be 1) is computed
//! once, and branches known not to run are dropped. The meaning of every
//! operator is the one the interpreter gives it, so folding never changes
//! what a post writes.

use crate::exec::{Expr, Piece, Stmt, Text};
use crate::interp::ops::{binary, unary};
use crate::value::Value;
use postc_ir::{BinaryOp, OutputRef, UnaryOp};

/// The value of a literal.
fn constant(e: &Expr) -> Option<Value> {
    Some(match e {
        Expr::Number(n) => Value::Num(*n),
        Expr::Text(t) => t.value().clone(),
        Expr::Bool(b) => Value::Bool(*b),
        Expr::Null => Value::Null,
        Expr::Undefined => Value::Undefined,
        _ => return None,
    })
}

/// The expression of a constant; `None` for arrays, objects, functions
/// and regular expressions, which are made anew each time.
fn literal(v: Value) -> Option<Expr> {
    Some(match v {
        Value::Num(n) => Expr::Number(n),
        Value::Text(s) => Expr::Text(Text::new(s)),
        Value::Bool(b) => Expr::Bool(b),
        Value::Null => Expr::Null,
        Value::Undefined => Expr::Undefined,
        Value::Array(_) | Value::Object(_) | Value::Func(_) | Value::Output(_) | Value::Regex(_) => return None,
    })
}

/// Folds an expression.
pub fn expr(e: Expr) -> Expr {
    match e {
        Expr::Unary(op, a) => {
            let a = expr(*a);
            match constant(&a).and_then(|v| literal(unary(op, &v))) {
                Some(folded) => folded,
                None => Expr::Unary(op, Box::new(a)),
            }
        }
        Expr::Binary(op, a, b) => {
            let (a, b) = (expr(*a), expr(*b));
            match (op, constant(&a), constant(&b)) {
                // `a && b` is `a` when `a` is falsy, else `b` (and `||` the other way).
                (BinaryOp::And | BinaryOp::Or, Some(x), _) => {
                    if x.truthy() == (op == BinaryOp::And) {
                        b
                    } else {
                        a
                    }
                }
                (BinaryOp::And | BinaryOp::Or, None, _) => Expr::Binary(op, Box::new(a), Box::new(b)),
                // Null joined to text is `null` in JavaScript and nothing
                // in the other dialects: left for the engine, which reads
                // the post's `js_text`.
                (BinaryOp::Add, Some(x), Some(y))
                    if matches!((&x, &y), (Value::Null, Value::Text(_)) | (Value::Text(_), Value::Null)) =>
                {
                    Expr::Binary(op, Box::new(a), Box::new(b))
                }
                (_, Some(x), Some(y)) => match literal(binary(op, &x, &y)) {
                    Some(folded) => folded,
                    None => Expr::Binary(op, Box::new(a), Box::new(b)),
                },
                _ => Expr::Binary(op, Box::new(a), Box::new(b)),
            }
        }
        Expr::Choose(c, a, b) => {
            let c = expr(*c);
            match constant(&c) {
                Some(k) if k.truthy() => expr(*a),
                Some(_) => expr(*b),
                None => Expr::Choose(Box::new(c), Box::new(expr(*a)), Box::new(expr(*b))),
            }
        }
        Expr::FormatVar { var, value, span } => Expr::FormatVar { var, value: Box::new(expr(*value)), span },
        Expr::Format { format, value, span } => Expr::Format { format, value: Box::new(expr(*value)), span },
        // `f.format(v)` of a format or an output variable the code names
        // as a constant (a factory's capture once specialised): what the
        // method does, as the expression of a named format's or variable's
        // `format` (the format reads its value as JavaScript's `Number`).
        Expr::Invoke { object, method, mut args, span }
            if matches!(*object, Expr::Output(_)) && &*method == "format" && args.len() == 1 =>
        {
            let value = Box::new(expr(args.remove(0)));
            match *object {
                Expr::Output(OutputRef::Format(format)) => {
                    Expr::Format { format, value: Box::new(Expr::Unary(UnaryOp::Plus, value)), span }
                }
                Expr::Output(OutputRef::Variable(var)) => Expr::FormatVar { var, value, span },
                object => Expr::Invoke { object: Box::new(object), method, args: vec![*value], span },
            }
        }
        Expr::Call(f, args) => Expr::Call(f, args.into_iter().map(expr).collect()),
        Expr::Builtin(b, args) => Expr::Builtin(b, args.into_iter().map(expr).collect()),
        other => other,
    }
}

/// Folds statements; branches known not to run are dropped, and nothing
/// after a `return`, `break` or `continue` is kept.
pub fn stmts(body: Vec<Stmt>) -> Vec<Stmt> {
    let mut out = Vec::with_capacity(body.len());
    for s in body {
        match s {
            Stmt::If { branches, otherwise } => {
                let mut kept = Vec::new();
                let mut rest = stmts(otherwise);
                for (c, b) in branches {
                    let c = expr(c);
                    match constant(&c) {
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
                if constant(&cond).is_some_and(|c| !c.truthy()) {
                    continue;
                }
                let mut body = stmts(body);
                let step = stmts(step);
                // `while (true) { ...; break; }` with no other way out runs once.
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
            Stmt::Emit(pieces) => out.push(Stmt::Emit(pieces.into_iter().map(piece).collect())),
            Stmt::Line { pieces, span } => {
                out.push(Stmt::Line { pieces: pieces.into_iter().map(piece).collect(), span })
            }
            Stmt::Assign(p, e) => out.push(Stmt::Assign(p, expr(e))),
            Stmt::Eval(e) => out.push(Stmt::Eval(expr(e))),
            Stmt::Return(e) => out.push(Stmt::Return(e.map(expr))),
            other => out.push(other),
        }
        // What follows a jump never runs (a branch kept in place may end in one).
        if matches!(out.last(), Some(Stmt::Return(_) | Stmt::Break | Stmt::Continue)) {
            break;
        }
    }
    out
}

/// A piece whose expression folds to text is that text.
fn piece(p: Piece) -> Piece {
    match p {
        Piece::Expr(e) => match expr(e) {
            Expr::Text(t) => Piece::Text(t.as_bytes().to_vec()),
            e => Piece::Expr(e),
        },
        Piece::Joined(e) => match expr(e) {
            Expr::Text(t) => Piece::Text(t.as_bytes().to_vec()),
            Expr::Null | Expr::Undefined => Piece::Text(Vec::new()),
            e => Piece::Joined(e),
        },
        other => other,
    }
}

/// Whether statements leave or restart the loop around them.
fn leaves(body: &[Stmt]) -> bool {
    body.iter().any(|s| match s {
        Stmt::Break | Stmt::Continue => true,
        Stmt::If { branches, otherwise } => branches.iter().any(|(_, b)| leaves(b)) || leaves(otherwise),
        _ => false,
    })
}
