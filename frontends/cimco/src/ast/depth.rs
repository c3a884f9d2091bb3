//! How deep each node's children go, so that [`super::Expr::new`] and
//! [`super::Stmt::new`] can record a node's depth in constant time.

use super::*;

fn max_expr<'a>(exprs: impl IntoIterator<Item = &'a Expr>) -> u32 {
    exprs.into_iter().map(|e| e.depth).max().unwrap_or(0)
}

fn max_stmt<'a>(stmts: impl IntoIterator<Item = &'a Stmt>) -> u32 {
    stmts.into_iter().map(|s| s.depth).max().unwrap_or(0)
}

fn function_depth(f: &Function) -> u32 {
    1 + max_stmt(&f.body)
}

fn declarators_depth(decls: &[VarDeclarator]) -> u32 {
    1 + max_expr(decls.iter().filter_map(|d| d.init.as_ref()))
}

pub(super) fn expr_children_depth(kind: &ExprKind) -> u32 {
    match kind {
        ExprKind::Number(_)
        | ExprKind::String(_)
        | ExprKind::Bool(_)
        | ExprKind::Null
        | ExprKind::Undefined
        | ExprKind::This
        | ExprKind::Regex { .. }
        | ExprKind::Ident(_)
        | ExprKind::Error => 0,
        ExprKind::Array(items) | ExprKind::Sequence(items) | ExprKind::Template { exprs: items, .. } => max_expr(items),
        ExprKind::Object(props) => 1 + max_expr(props.iter().map(|p| &p.value)),
        ExprKind::Function(f) => function_depth(f),
        ExprKind::Member { object, .. } => object.depth,
        ExprKind::Unary { operand: e, .. } | ExprKind::Update { target: e, .. } => e.depth,
        ExprKind::Index { object: a, index: b }
        | ExprKind::Binary { left: a, right: b, .. }
        | ExprKind::Logical { left: a, right: b, .. }
        | ExprKind::Assign { target: a, value: b, .. } => a.depth.max(b.depth),
        ExprKind::Call { callee, args } | ExprKind::New { callee, args } => callee.depth.max(max_expr(args)),
        ExprKind::Conditional { test, consequent, alternate } => test.depth.max(consequent.depth).max(alternate.depth),
    }
}

pub(super) fn stmt_children_depth(kind: &StmtKind) -> u32 {
    match kind {
        StmtKind::Var(decls) => declarators_depth(decls),
        StmtKind::Function(f) => function_depth(f),
        StmtKind::Expr(e) | StmtKind::Throw(e) => e.depth,
        StmtKind::Return(e) => e.as_ref().map_or(0, |e| e.depth),
        StmtKind::Block(body) => max_stmt(body),
        StmtKind::Empty | StmtKind::Break | StmtKind::Continue | StmtKind::Error => 0,
        StmtKind::If { branches, otherwise } => branches
            .iter()
            .map(|b| b.cond.depth.max(b.body.depth))
            .chain(otherwise.iter().map(|s| s.depth))
            .max()
            .unwrap_or(0),
        StmtKind::Switch { discriminant, cases } => discriminant.depth.max(
            1 + cases.iter().map(|c| c.test.as_ref().map_or(0, |t| t.depth).max(max_stmt(&c.body))).max().unwrap_or(0),
        ),
        StmtKind::For { init, test, update, body } => {
            let init = match init {
                Some(ForInit::Var(d)) => declarators_depth(d),
                Some(ForInit::Expr(e)) => e.depth,
                None => 0,
            };
            init.max(max_expr(test.iter().chain(update.iter()))).max(body.depth)
        }
        StmtKind::ForIn { object, body, .. } => object.depth.max(body.depth),
        StmtKind::While { cond, body } | StmtKind::DoWhile { body, cond } => cond.depth.max(body.depth),
        StmtKind::Try { block, handler, finalizer } => max_stmt(block)
            .max(handler.as_ref().map_or(0, |h| 1 + max_stmt(&h.body)))
            .max(finalizer.as_ref().map_or(0, max_stmt)),
    }
}
