//! What a line that does not parse still says about block structure.
//!
//! A line with an error is reported once and replaced by what its first
//! and last words show: `If ... Then` still opens an `If` block, `For ...`
//! a loop, `Sub ...` a Sub, `Next ...` closes a loop, and so on, with the
//! unreadable parts as error expressions. That way one typing mistake in a
//! block's first line does not also make its `End If` a stray closing line.

use postc_ir::Span;

use super::LineItem;
use crate::ast::{Expr, ExprKind, LoopKind, LoopTest, Name, ProcKind, Stmt, StmtKind};
use crate::token::{Kw, Token};

/// The items a line that could not be parsed stands for.
#[doc(hidden)]
pub fn line(tokens: &[Token], span: Span) -> Vec<LineItem> {
    let error = || Expr { kind: ExprKind::Error, span };
    let name_after = |i: usize| Name {
        text: match tokens.get(i) {
            Some(Token::Ident(n)) => n.clone(),
            _ => "?".to_string(),
        },
        span,
    };
    let kw = |i: usize| match tokens.get(i) {
        Some(Token::Kw(k)) => Some(*k),
        _ => None,
    };
    let last = tokens.last();
    let proc_kind = |k: Option<Kw>| match k {
        Some(Kw::Sub) => Some(ProcKind::Sub),
        Some(Kw::Function) => Some(ProcKind::Function),
        _ => None,
    };
    let item = match (kw(0), kw(1)) {
        (Some(Kw::If), _) if last == Some(&Token::Kw(Kw::Then)) => LineItem::IfStart { cond: error(), span },
        (Some(Kw::ElseIf), _) => LineItem::ElseIf { cond: error(), span },
        (Some(Kw::Else), _) => return vec![LineItem::Else { span }, LineItem::Error { span }],
        (Some(Kw::Select), _) => LineItem::SelectStart { subject: error(), span },
        (Some(Kw::Case), Some(Kw::Else)) => LineItem::CaseElse { span },
        (Some(Kw::Case), _) => LineItem::Case { tests: Vec::new(), span },
        (Some(Kw::For), _) => LineItem::ForStart { var: name_after(1), from: error(), to: error(), step: None, span },
        (Some(Kw::Next), _) => LineItem::Next { var: None, span },
        (Some(Kw::While), _) => {
            LineItem::LoopStart { kind: LoopKind::While, test: Some(LoopTest { until: false, cond: error() }), span }
        }
        (Some(Kw::Wend), _) => LineItem::LoopEnd { kind: LoopKind::While, test: None, span },
        (Some(Kw::Do), _) => LineItem::LoopStart { kind: LoopKind::Do, test: None, span },
        (Some(Kw::Loop), _) => LineItem::LoopEnd { kind: LoopKind::Do, test: None, span },
        (Some(Kw::End), Some(Kw::If)) => LineItem::EndIf { span },
        (Some(Kw::End), Some(Kw::Select)) => LineItem::EndSelect { span },
        (Some(Kw::End), Some(Kw::While)) => LineItem::LoopEnd { kind: LoopKind::While, test: None, span },
        (Some(Kw::End), k) if proc_kind(k).is_some() => {
            LineItem::ProcEnd { kind: proc_kind(k).unwrap_or(ProcKind::Sub), span }
        }
        (k, _) if proc_kind(k).is_some() => LineItem::ProcStart {
            kind: proc_kind(k).unwrap_or(ProcKind::Sub),
            name: name_after(1),
            params: Vec::new(),
            span,
        },
        (Some(Kw::Public | Kw::Private), k) if proc_kind(k).is_some() => LineItem::ProcStart {
            kind: proc_kind(k).unwrap_or(ProcKind::Sub),
            name: name_after(2),
            params: Vec::new(),
            span,
        },
        _ => LineItem::Stmt(Stmt { kind: StmtKind::Error, span }),
    };
    vec![item]
}
