//! Looking into a prepared post (`postc_runtime::prepare`) by what its
//! statements and expressions are, with the runtime's own walkers, rather
//! than by their debug text.

use postc_ir::{FunctionId, Post};
pub use postc_runtime::exec::{Expr as XExpr, Stmt as XStmt};

/// The id of the post's function `name`.
pub fn function(post: &Post, name: &str) -> FunctionId {
    FunctionId::new(post.functions.iter().position(|f| f.name == name).expect("the function") as u16)
}

/// How many statements of a prepared `body`, at any depth, satisfy `p`.
pub fn count_stmts(body: &[XStmt], p: &impl Fn(&XStmt) -> bool) -> usize {
    body.iter()
        .map(|s| {
            let mut n = usize::from(p(s));
            s.clone().for_each_body_mut(|b| n += count_stmts(b, p));
            n
        })
        .sum()
}

/// Whether an expression of a prepared `body`, at any depth, satisfies `p`.
pub fn any_expr(body: &[XStmt], p: &impl Fn(&XExpr) -> bool) -> bool {
    fn expr(e: &mut XExpr, p: &impl Fn(&XExpr) -> bool) -> bool {
        let mut found = p(e);
        e.for_each_operand_mut(|o| found |= expr(o, p));
        found
    }
    body.iter().any(|s| {
        let mut s = s.clone();
        let mut found = false;
        s.for_each_expr_mut(|e| found |= expr(e, p));
        s.for_each_body_mut(|b| found |= any_expr(b, p));
        found
    })
}

/// Whether a prepared `body` calls `f` anywhere.
pub fn calls(body: &[XStmt], f: FunctionId) -> bool {
    any_expr(body, &|e| matches!(e, XExpr::Call(g, _) if *g == f))
}

/// Whether the IR `body` calls `f` anywhere.
pub fn ir_calls(body: &[postc_ir::Stmt], f: FunctionId) -> bool {
    struct Calls(FunctionId, bool);
    impl postc_ir::visit::Visit for Calls {
        fn visit_expr(&mut self, e: &postc_ir::Expr) {
            self.1 |= matches!(e, postc_ir::Expr::Call(g, _) if *g == self.0);
            postc_ir::visit::walk_expr(self, e);
        }
    }
    let mut v = Calls(f, false);
    body.iter().for_each(|s| postc_ir::visit::Visit::visit_stmt(&mut v, s));
    v.1
}
