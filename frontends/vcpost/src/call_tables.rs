//! Functions whose values come from the calls: VcPost composites'
//! `getNthLength1(tow)`, `getNthLength2`, `getNthLength3` (Vericut's post-processor notes,
//! GoTo) and `getNthAddCut(i)` (RestartBuffer), [`HOST_FUNCTIONS`].
//!
//! The lowering compiles a call of one of these names into a call of a
//! stub function that has no span and returns 0 (what it returns when a
//! post runs over toolpath events). Before a post runs over Sub calls,
//! [`lower`] gives each stub a body that reads a table of [`MAX_ENTRIES`]
//! hidden globals,
//!
//! ```text
//! If n = 0 Then Return getNthLength1#0 ElseIf n = 1 Then Return getNthLength1#1 ... Else Return 0
//! ```
//!
//! and names those globals in a [`CallList`] of the post, which the
//! runtime fills from each call's list of that name (`postc_ir::calls`).
//! An index outside the list (or not a whole number) gives 0.
//!
//! `postc convert` prints the post as compiled, with the stubs; the
//! tables are made when the post is about to run over calls
//! (`postc_driver::for_calls`).

use postc_ir::{BinaryOp, Body, CallList, Expr, Global, GlobalId, LocalId, Post, Stmt};

use crate::routines::HOST_FUNCTIONS;

/// Entries of one function's table: indexes 0 to `MAX_ENTRIES - 1`.
pub const MAX_ENTRIES: usize = 64;

/// The post with table bodies for its stubs; `None` when it calls none of
/// the table functions (or the hidden globals would not fit the ids).
pub fn lower(post: &Post) -> Option<Post> {
    let stubs: Vec<usize> = post
        .functions
        .iter()
        .enumerate()
        .filter(|(_, f)| f.span.is_none() && HOST_FUNCTIONS.iter().any(|(n, _)| n.eq_ignore_ascii_case(&f.name)))
        .map(|(i, _)| i)
        .collect();
    if stubs.is_empty() {
        return None;
    }
    let mut post = post.clone();
    for i in stubs {
        let base = post.globals.len();
        let first = u16::try_from(base).ok()?;
        if base + MAX_ENTRIES > usize::from(u16::MAX) {
            return None;
        }
        let name = post.functions[i].name.clone();
        for k in 0..MAX_ENTRIES {
            post.globals.push(Global {
                name: format!("{name}#{k}"),
                initial: Expr::Number(0.0),
                implicit: false,
                span: None,
            });
        }
        let branches = (0..MAX_ENTRIES)
            .map(|k| {
                let test = Expr::Binary(
                    BinaryOp::Eq,
                    Box::new(Expr::Local(LocalId::new(0))),
                    Box::new(Expr::Number(k as f64)),
                );
                (test, vec![Stmt::Return(Some(Expr::Global(GlobalId::new(first + k as u16))))])
            })
            .collect();
        let f = &mut post.functions[i];
        f.slots = f.slots.max(1);
        f.body = Body::Native(vec![Stmt::If { branches, otherwise: vec![Stmt::Return(Some(Expr::Number(0.0)))] }]);
        post.call_lists.push(CallList { name, first: GlobalId::new(first), len: MAX_ENTRIES as u16 });
    }
    Some(post)
}
