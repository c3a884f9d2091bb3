//! LN013: a VcPost `Out` template prints a register (`<Name>`) that
//! nothing sets: no statement assigns it, the runtime does not load it
//! (the APT record registers, the composites variables), and no table or
//! application passes it as a Sub parameter. It prints empty every time —
//! usually a misspelt register name.

use postc_ir::codes;
use std::collections::BTreeSet;

use postc_ir::visit::{Visit, walk_stmt};
use postc_ir::{Diagnostic, Dialect, Piece, Place, Stmt, ValueSource};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN013.code, name: "register-never-set", check };

/// Registers assigned anywhere, and where each is printed first.
#[derive(Default)]
struct Registers {
    assigned: BTreeSet<usize>,
    printed: Vec<(usize, Option<postc_ir::Span>)>,
}

impl Visit for Registers {
    fn visit_stmt(&mut self, stmt: &Stmt) {
        match stmt {
            Stmt::Assign(Place::Var(v), _) => {
                self.assigned.insert(v.index());
            }
            Stmt::Line { pieces, span } => {
                for p in pieces {
                    if let Piece::Var(v) = p
                        && !self.printed.iter().any(|(i, _)| *i == v.index())
                    {
                        self.printed.push((v.index(), *span));
                    }
                }
            }
            _ => {}
        }
        walk_stmt(self, stmt);
    }

    fn visit_expr(&mut self, e: &postc_ir::Expr) {
        if let postc_ir::Expr::FormatVar { var, .. } = e {
            self.assigned.insert(var.index());
        }
        postc_ir::visit::walk_expr(self, e);
    }
}

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    let post = cx.post;
    if post.info.dialect != Dialect::VcPost {
        return;
    }
    let mut r = Registers::default();
    r.visit_post(post);
    let params: BTreeSet<String> =
        post.info.subs.iter().flat_map(|s| s.params.iter().map(|p| p.name.to_ascii_lowercase())).collect();
    for (i, span) in r.printed {
        let v = &post.variables[i];
        if v.source != ValueSource::Assigned
            || r.assigned.contains(&i)
            || postc_front_vcpost::routines::runtime_variable(&v.name).is_some()
            || params.contains(&v.name.to_ascii_lowercase())
        {
            continue;
        }
        let mut d = Diagnostic::warning(
            RULE.code,
            format!("`<{}>` is printed but nothing sets it: it prints empty every time", v.name),
        )
        .help("check the register's name, or assign it before the Out");
        if let Some(at) = span.or(v.span) {
            d = d.at(at, "printed here");
        }
        out.push(d);
    }
}
