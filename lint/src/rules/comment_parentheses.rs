//! LN003: a comment line prints text the user chose (a tool or toolpath
//! name, notes, a file name) between `(` and `)`; a name with a `)` in it
//! ends the comment early and the controller reads the rest as words.

use postc_ir::codes;
use postc_ir::{Diagnostic, Piece, Quantity};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN003.code, name: "comment-can-break", check };

const FREE_TEXT: &[Quantity] = &[
    Quantity::ToolName,
    Quantity::ToolNotes,
    Quantity::ToolpathName,
    Quantity::ToolpathNotes,
    Quantity::FileName,
    Quantity::FileDir,
    Quantity::PathName,
    Quantity::FileNotes,
    Quantity::ToolsUsed,
    Quantity::ToolpathsOutput,
    Quantity::CommentText,
];

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    let subs = &cx.post.options.substitutions;
    let replaced = |c: u8| subs.iter().any(|s| s.from == [c]);
    if replaced(b'(') && replaced(b')') {
        return;
    }
    let mut seen = std::collections::BTreeSet::new();
    for h in &cx.post.handlers {
        for stmt in &h.body {
            let postc_ir::Stmt::Line { pieces, span } = stmt else { continue };
            let Some(Piece::Text(first)) = pieces.first() else { continue };
            if !first.starts_with(b"(") {
                continue;
            }
            for p in pieces {
                let Some(q) = cx.quantity(p) else { continue };
                if !FREE_TEXT.contains(&q) || !seen.insert((q.label(), span.map(|s| s.start))) {
                    continue;
                }
                let mut d = Diagnostic::warning(
                    RULE.code,
                    format!("[{}] is printed inside a ( ) comment; a `)` in it ends the comment early", q.label()),
                )
                .help("add `SUBSTITUTE = \"({)}\"` so that parentheses in names print as braces");
                if let Some(span) = span {
                    d = d.at(*span, "this comment");
                }
                out.push(d);
            }
        }
    }
}
