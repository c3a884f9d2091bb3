//! Walking the code of a post: [`Visit`] reads every statement, piece and
//! expression in order, [`VisitMut`] may change them. A visitor overrides
//! the methods for what it cares about and calls the `walk_` function to go
//! on into the children, as `syn` and `naga` visitors do.
//!
//! [`Visit::visit_post`] goes through `init`, every handler and every
//! native function body, in that order.

use crate::code::{Expr, Piece, Stmt};
use crate::post::{Body, Post};

/// Reads a post's code.
pub trait Visit {
    fn visit_post(&mut self, post: &Post) {
        walk_post(self, post);
    }
    fn visit_stmt(&mut self, stmt: &Stmt) {
        walk_stmt(self, stmt);
    }
    fn visit_piece(&mut self, piece: &Piece) {
        walk_piece(self, piece);
    }
    fn visit_expr(&mut self, expr: &Expr) {
        walk_expr(self, expr);
    }
}

pub fn walk_post<V: Visit + ?Sized>(v: &mut V, post: &Post) {
    for s in &post.init {
        v.visit_stmt(s);
    }
    for h in &post.handlers {
        for s in &h.body {
            v.visit_stmt(s);
        }
    }
    for f in &post.functions {
        if let Body::Native(body) = &f.body {
            for s in body {
                v.visit_stmt(s);
            }
        }
    }
}

pub fn walk_stmt<V: Visit + ?Sized>(v: &mut V, stmt: &Stmt) {
    match stmt {
        Stmt::Line { pieces, .. } => pieces.iter().for_each(|p| v.visit_piece(p)),
        Stmt::Write(e) | Stmt::Assign(_, e) | Stmt::Eval(e) | Stmt::Return(Some(e)) => v.visit_expr(e),
        Stmt::If { branches, otherwise } => {
            for (cond, body) in branches {
                v.visit_expr(cond);
                body.iter().for_each(|s| v.visit_stmt(s));
            }
            otherwise.iter().for_each(|s| v.visit_stmt(s));
        }
        Stmt::While { cond, body, step, .. } => {
            v.visit_expr(cond);
            body.iter().for_each(|s| v.visit_stmt(s));
            step.iter().for_each(|s| v.visit_stmt(s));
        }
        Stmt::SetMember { object, key, value, .. } => {
            v.visit_expr(object);
            v.visit_expr(key);
            v.visit_expr(value);
        }
        Stmt::Throw { value, .. } => v.visit_expr(value),
        Stmt::Try { body, catch, finally } => {
            body.iter().for_each(|s| v.visit_stmt(s));
            if let Some((_, handler)) = catch {
                handler.iter().for_each(|s| v.visit_stmt(s));
            }
            finally.iter().for_each(|s| v.visit_stmt(s));
        }
        Stmt::Break | Stmt::Continue | Stmt::Return(None) | Stmt::Script(_) | Stmt::Forget(_) | Stmt::Origin(_) => {}
    }
}

/// Calls `f` on each statement list nested in `stmt` (a branch, a loop's
/// body and update, a `try`'s blocks).
pub fn for_each_body_mut(stmt: &mut Stmt, mut f: impl FnMut(&mut Vec<Stmt>)) {
    match stmt {
        Stmt::If { branches, otherwise } => {
            branches.iter_mut().for_each(|(_, b)| f(b));
            f(otherwise);
        }
        Stmt::While { body, step, .. } => {
            f(body);
            f(step);
        }
        Stmt::Try { body, catch, finally } => {
            f(body);
            if let Some((_, handler)) = catch {
                f(handler);
            }
            f(finally);
        }
        _ => {}
    }
}

pub fn walk_piece<V: Visit + ?Sized>(v: &mut V, piece: &Piece) {
    if let Piece::Expr(e) = piece {
        v.visit_expr(e);
    }
}

pub fn walk_expr<V: Visit + ?Sized>(v: &mut V, expr: &Expr) {
    match expr {
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => v.visit_expr(value),
        Expr::Binary(_, a, b) => {
            v.visit_expr(a);
            v.visit_expr(b);
        }
        Expr::Choose(c, a, b) => {
            v.visit_expr(c);
            v.visit_expr(a);
            v.visit_expr(b);
        }
        Expr::Call(_, args) | Expr::Builtin(_, args) | Expr::Array(args) => args.iter().for_each(|a| v.visit_expr(a)),
        Expr::Closure { captures, .. } | Expr::Host { args: captures, .. } => {
            captures.iter().for_each(|a| v.visit_expr(a))
        }
        Expr::Object(props) => props.iter().for_each(|(_, a)| v.visit_expr(a)),
        Expr::Member { object, key, .. } => {
            v.visit_expr(object);
            v.visit_expr(key);
        }
        Expr::Invoke { object, args, .. } | Expr::CallValue(object, args) => {
            v.visit_expr(object);
            args.iter().for_each(|a| v.visit_expr(a));
        }
        Expr::Number(_)
        | Expr::Text(_)
        | Expr::Regex { .. }
        | Expr::Undeclared { .. }
        | Expr::Bool(_)
        | Expr::Null
        | Expr::Undefined
        | Expr::This
        | Expr::Arguments
        | Expr::Output(_)
        | Expr::Quantity(_)
        | Expr::Local(_)
        | Expr::Global(_)
        | Expr::Var(_)
        | Expr::Previous(_) => {}
    }
}

/// Changes a post's code in place.
pub trait VisitMut {
    fn visit_post_mut(&mut self, post: &mut Post) {
        walk_post_mut(self, post);
    }
    fn visit_stmt_mut(&mut self, stmt: &mut Stmt) {
        walk_stmt_mut(self, stmt);
    }
    fn visit_expr_mut(&mut self, expr: &mut Expr) {
        walk_expr_mut(self, expr);
    }
}

pub fn walk_post_mut<V: VisitMut + ?Sized>(v: &mut V, post: &mut Post) {
    for s in &mut post.init {
        v.visit_stmt_mut(s);
    }
    for h in &mut post.handlers {
        for s in &mut h.body {
            v.visit_stmt_mut(s);
        }
    }
    for f in &mut post.functions {
        if let Body::Native(body) = &mut f.body {
            for s in body {
                v.visit_stmt_mut(s);
            }
        }
    }
}

pub fn walk_stmt_mut<V: VisitMut + ?Sized>(v: &mut V, stmt: &mut Stmt) {
    match stmt {
        Stmt::Line { pieces, .. } => {
            for p in pieces {
                if let Piece::Expr(e) = p {
                    v.visit_expr_mut(e);
                }
            }
        }
        Stmt::Write(e) | Stmt::Assign(_, e) | Stmt::Eval(e) | Stmt::Return(Some(e)) => v.visit_expr_mut(e),
        Stmt::If { branches, otherwise } => {
            for (cond, body) in branches {
                v.visit_expr_mut(cond);
                body.iter_mut().for_each(|s| v.visit_stmt_mut(s));
            }
            otherwise.iter_mut().for_each(|s| v.visit_stmt_mut(s));
        }
        Stmt::While { cond, body, step, .. } => {
            v.visit_expr_mut(cond);
            body.iter_mut().for_each(|s| v.visit_stmt_mut(s));
            step.iter_mut().for_each(|s| v.visit_stmt_mut(s));
        }
        Stmt::SetMember { object, key, value, .. } => {
            v.visit_expr_mut(object);
            v.visit_expr_mut(key);
            v.visit_expr_mut(value);
        }
        Stmt::Throw { value, .. } => v.visit_expr_mut(value),
        Stmt::Try { body, catch, finally } => {
            body.iter_mut().for_each(|s| v.visit_stmt_mut(s));
            if let Some((_, handler)) = catch {
                handler.iter_mut().for_each(|s| v.visit_stmt_mut(s));
            }
            finally.iter_mut().for_each(|s| v.visit_stmt_mut(s));
        }
        Stmt::Break | Stmt::Continue | Stmt::Return(None) | Stmt::Script(_) | Stmt::Forget(_) | Stmt::Origin(_) => {}
    }
}

pub fn walk_expr_mut<V: VisitMut + ?Sized>(v: &mut V, expr: &mut Expr) {
    match expr {
        Expr::FormatVar { value, .. } | Expr::Format { value, .. } | Expr::Unary(_, value) => v.visit_expr_mut(value),
        Expr::Binary(_, a, b) => {
            v.visit_expr_mut(a);
            v.visit_expr_mut(b);
        }
        Expr::Choose(c, a, b) => {
            v.visit_expr_mut(c);
            v.visit_expr_mut(a);
            v.visit_expr_mut(b);
        }
        Expr::Call(_, args) | Expr::Builtin(_, args) | Expr::Array(args) => {
            args.iter_mut().for_each(|a| v.visit_expr_mut(a))
        }
        Expr::Closure { captures, .. } | Expr::Host { args: captures, .. } => {
            captures.iter_mut().for_each(|a| v.visit_expr_mut(a))
        }
        Expr::Object(props) => props.iter_mut().for_each(|(_, a)| v.visit_expr_mut(a)),
        Expr::Member { object, key, .. } => {
            v.visit_expr_mut(object);
            v.visit_expr_mut(key);
        }
        Expr::Invoke { object, args, .. } | Expr::CallValue(object, args) => {
            v.visit_expr_mut(object);
            args.iter_mut().for_each(|a| v.visit_expr_mut(a));
        }
        Expr::Number(_)
        | Expr::Text(_)
        | Expr::Regex { .. }
        | Expr::Undeclared { .. }
        | Expr::Bool(_)
        | Expr::Null
        | Expr::Undefined
        | Expr::This
        | Expr::Arguments
        | Expr::Output(_)
        | Expr::Quantity(_)
        | Expr::Local(_)
        | Expr::Global(_)
        | Expr::Var(_)
        | Expr::Previous(_) => {}
    }
}

/// Calls `f` on every local a statement names, where it reads one
/// (`Expr::Local`) and where it stores one (`Place::Local`, the value a
/// `catch` takes), in order, through nested statements and expressions:
/// the one use/def walk of the IR's locals.
pub fn locals_mut(stmt: &mut Stmt, f: &mut dyn FnMut(&mut crate::LocalId)) {
    struct Locals<'f>(&'f mut dyn FnMut(&mut crate::LocalId));
    impl VisitMut for Locals<'_> {
        fn visit_stmt_mut(&mut self, stmt: &mut Stmt) {
            match stmt {
                Stmt::Assign(crate::Place::Local(k), _) => (self.0)(k),
                Stmt::Try { catch: Some((k, _)), .. } => (self.0)(k),
                _ => {}
            }
            walk_stmt_mut(self, stmt);
        }
        fn visit_expr_mut(&mut self, expr: &mut Expr) {
            if let Expr::Local(k) = expr {
                (self.0)(k);
            }
            walk_expr_mut(self, expr);
        }
    }
    Locals(f).visit_stmt_mut(stmt);
}
