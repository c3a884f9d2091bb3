//! LN015: a CIMCO global that is read but never given a value: declared
//! without one (`var drill;`), assigned nowhere — not at the top level,
//! not in any function, native or script. Every read gets `undefined`,
//! which prints as `undefined` or turns arithmetic into NaN.

use std::collections::BTreeSet;

use postc_ir::visit::{Visit, walk_expr, walk_stmt};
use postc_ir::{Diagnostic, Dialect, Expr, Place, Stmt};

use postc_ir::codes;

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN015.code, name: "global-never-assigned", check };

#[derive(Default)]
struct Globals {
    read: BTreeSet<usize>,
    written: BTreeSet<usize>,
}

impl Visit for Globals {
    fn visit_stmt(&mut self, stmt: &Stmt) {
        if let Stmt::Assign(Place::Global(g), _) = stmt {
            self.written.insert(g.index());
        }
        walk_stmt(self, stmt);
    }

    fn visit_expr(&mut self, e: &Expr) {
        if let Expr::Global(g) = e {
            self.read.insert(g.index());
        }
        walk_expr(self, e);
    }
}

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    let post = cx.post;
    if post.info.dialect != Dialect::Cimco {
        return;
    }
    let mut g = Globals::default();
    g.visit_post(post);
    // Script functions read and write globals through __gg(i) / __gs(i, v).
    for s in &post.scripts {
        for (prefix, set) in [("__gg(", &mut g.read), ("__gs(", &mut g.written)] {
            for (i, _) in s.source.match_indices(prefix) {
                let digits: String = s.source[i + prefix.len()..].chars().take_while(char::is_ascii_digit).collect();
                if let Ok(n) = digits.parse() {
                    set.insert(n);
                }
            }
        }
    }
    for (i, global) in post.globals.iter().enumerate() {
        if global.name.starts_with("__postc")
            || !matches!(global.initial, Expr::Undefined | Expr::Null)
            || g.written.contains(&i)
            || !g.read.contains(&i)
        {
            continue;
        }
        // Script globals of the host (PostInfo, globals, ...) are set by it.
        if post.scripts.iter().any(|s| s.source.contains(&format!("\"{}\"", global.name))) {
            continue;
        }
        let mut d = Diagnostic::warning(RULE.code, format!("global `{}` is read but never given a value", global.name))
            .help("give it a value where it is declared, or assign it before it is read");
        if let Some(span) = global.span {
            d = d.at(span, "declared here, without a value");
        }
        out.push(d);
    }
}
