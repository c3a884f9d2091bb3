mod emit;
mod fresh;
mod fuse;
mod locals;
mod splice;
mod unshift;

/// What the passes' tests build code from.
pub mod testing {
    use postc_ir::{LocalId, Place};

    use postc_runtime::exec::{Expr, Stmt};

    /// A read of local `i`.
    pub fn local(i: u16) -> Expr {
        Expr::Local(LocalId::new(i))
    }

    /// `local i = e`.
    pub fn set(i: u16, e: Expr) -> Stmt {
        Stmt::Assign(Place::Local(LocalId::new(i)), e)
    }
}
