//! Functions the runtime provides to a post, with values that change at
//! every call: VcPost composites' `getNthLength1(tow)`, `getNthLength2`,
//! `getNthLength3` (seed 003, GoTo) and `getNthAddCut(i)` (RestartBuffer).
//!
//! The VcPost frontend compiles a call of one of these names into a call of
//! a stub function that has no span and returns 0. Before a run over Sub
//! calls, [`patch`] replaces each stub, by name, with a body that reads a
//! table of [`MAX_ENTRIES`] hidden globals:
//!
//! ```text
//! If n = 0 Then Return getNthLength1#0 ElseIf n = 1 Then Return getNthLength1#1 ... Else Return 0
//! ```
//!
//! and a call that carries a [`postc_ir::CallValue::List`] of that name fills
//! the table ([`Tables::fill`]). An index outside the list (or not a whole
//! number) gives 0. The IR needs no new construct for this.

use postc_ir::{BinaryOp, Body, Expr, Global, Post, Stmt};

use crate::engine::Engine;
use crate::value::Value;

/// Functions whose values come from the calls' lists.
pub const TABLE_FUNCTIONS: &[&str] = &["getNthLength1", "getNthLength2", "getNthLength3", "getNthAddCut"];

/// Entries of one function's table: indexes 0 to `MAX_ENTRIES - 1`.
pub const MAX_ENTRIES: usize = 64;

/// The tables of a patched post.
#[derive(Debug, Default)]
pub(crate) struct Tables {
    /// Upper-case function name, first hidden global, entries set last time.
    tables: Vec<(String, u16, usize)>,
}

/// Replaces the stubs of the table functions; `None` when the post calls
/// none of them.
pub(crate) fn patch(post: &Post) -> Option<(Post, Tables)> {
    let stubs: Vec<usize> = post
        .functions
        .iter()
        .enumerate()
        .filter(|(_, f)| f.span.is_none() && TABLE_FUNCTIONS.iter().any(|n| n.eq_ignore_ascii_case(&f.name)))
        .map(|(i, _)| i)
        .collect();
    if stubs.is_empty() {
        return None;
    }
    let mut post = post.clone();
    let mut tables = Tables::default();
    for i in stubs {
        let base = post.globals.len();
        let Ok(first) = u16::try_from(base) else { return None };
        if base + MAX_ENTRIES > usize::from(u16::MAX) {
            return None;
        }
        let name = post.functions[i].name.clone();
        for k in 0..MAX_ENTRIES {
            post.globals.push(Global { name: format!("{name}#{k}"), initial: Expr::Number(0.0) });
        }
        let branches = (0..MAX_ENTRIES)
            .map(|k| {
                let test = Expr::Binary(
                    BinaryOp::Eq,
                    Box::new(Expr::Local(postc_ir::LocalId::new(0))),
                    Box::new(Expr::Number(k as f64)),
                );
                (test, vec![Stmt::Return(Some(Expr::Global(postc_ir::GlobalId::new(first + k as u16))))])
            })
            .collect();
        let f = &mut post.functions[i];
        f.slots = f.slots.max(1);
        f.body = Body::Native(vec![Stmt::If { branches, otherwise: vec![Stmt::Return(Some(Expr::Number(0.0)))] }]);
        tables.tables.push((name.to_ascii_uppercase(), first, 0));
    }
    Some((post, tables))
}

impl Tables {
    /// Whether `upper` names a patched function.
    pub(crate) fn has(&self, upper: &str) -> bool {
        self.tables.iter().any(|(n, ..)| n == upper)
    }

    /// Fills a function's table from a call's list; entries past the list
    /// (and past [`MAX_ENTRIES`]) read 0.
    pub(crate) fn fill(&mut self, eng: &mut Engine, upper: &str, values: &[f64]) {
        let Some((_, first, used)) = self.tables.iter_mut().find(|(n, ..)| n == upper) else { return };
        let n = values.len().min(MAX_ENTRIES);
        for (k, v) in values.iter().take(n).enumerate() {
            eng.set_global(postc_ir::GlobalId::new(*first + k as u16), Value::Num(*v));
        }
        for k in n..*used {
            eng.set_global(postc_ir::GlobalId::new(*first + k as u16), Value::Num(0.0));
        }
        *used = n;
    }

    /// Empties the tables a call did not fill, so no value outlives its call.
    pub(crate) fn clear_except(&mut self, eng: &mut Engine, filled: &[String]) {
        let names: Vec<String> = self
            .tables
            .iter()
            .filter(|(n, _, used)| *used > 0 && !filled.contains(n))
            .map(|(n, ..)| n.clone())
            .collect();
        for name in names {
            self.fill(eng, &name, &[]);
        }
    }
}
