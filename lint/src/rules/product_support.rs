//! LN006: with `postc check --product NAME`, what the chosen Vectric
//! product's post processor does not support (the 2012 Vectric post guide's table, in
//! `crate::product`): such a statement, section or variable is rejected
//! or silently ignored by that product.

use postc_ir::codes;
use postc_ir::{Diagnostic, Piece, Stmt};

use crate::product::{self, Support};
use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN006.code, name: "product-unsupported", check };

fn check(cx: &Context, options: &Options, out: &mut Vec<Diagnostic>) {
    let Some(p) = options.product else { return };
    let title = p.title();
    let said = |s: Support| match s {
        Support::No => "does not support",
        Support::Ignored => "accepts but does not use",
    };
    for (statement, support) in product::statements(cx.post, p) {
        let mut d = Diagnostic::warning(RULE.code, format!("{title} {} {statement}", said(support)));
        if let Some(span) = cx.post.info.span {
            d = d.at(span, format!("in this post, for {title}"));
        }
        out.push(d);
    }
    for h in &cx.post.handlers {
        let postc_ir::HandlerKey::Section(s) = h.key else { continue };
        if let Some(support) = product::section(p, s) {
            let mut d = Diagnostic::warning(RULE.code, format!("{title} {} the section {}", said(support), s.name()));
            if let Some(span) = h.span {
                d = d.at(span, "this section");
            }
            out.push(d);
        }
    }
    let mut seen = std::collections::BTreeSet::new();
    for h in &cx.post.handlers {
        for stmt in &h.body {
            let Stmt::Line { pieces, span } = stmt else { continue };
            for piece in pieces {
                let Piece::Var(v) = piece else { continue };
                let Some(q) = cx.quantity(piece) else { continue };
                let Some(support) = product::quantity(p, q) else { continue };
                if !seen.insert(q.label()) {
                    continue;
                }
                let mut d = Diagnostic::warning(RULE.code, format!("{title} {} [{}]", said(support), q.label()));
                if let Some(at) = cx.post.variables[v.index()].span.or(*span) {
                    d = d.at(at, "printed here");
                }
                out.push(d);
            }
        }
    }
}
