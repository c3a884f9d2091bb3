//! The blocks the builder keeps open, and what a closing line closes.

use postc_ir::Span;

use crate::ast::{CaseArm, Expr, ForLoop, FormalParam, LoopKind, LoopTest, Name, ProcKind, Stmt};

pub(super) enum Frame {
    Proc {
        kind: ProcKind,
        name: Name,
        params: Vec<FormalParam>,
        header: Span,
        body: Vec<Stmt>,
    },
    If {
        span: Span,
        branches: Vec<(Expr, Vec<Stmt>)>,
        otherwise: Vec<Stmt>,
        in_else: bool,
        /// Opened by `Else If` on one line.
        after_else: bool,
        /// A nested block opened by `Else If` on one line, which took an
        /// `End If` meant for this one.
        else_if_child: Option<Span>,
    },
    Select {
        span: Span,
        subject: Expr,
        arms: Vec<CaseArm>,
        otherwise: Vec<Stmt>,
        in_else: bool,
    },
    For {
        span: Span,
        looped: Box<ForLoop>,
    },
    Loop {
        span: Span,
        kind: LoopKind,
        test: Option<LoopTest>,
        body: Vec<Stmt>,
    },
}

/// What a closing line closes.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Want {
    Proc,
    If,
    Select,
    For,
    Loop(LoopKind),
}

impl Frame {
    pub(super) fn matches(&self, want: Want) -> bool {
        matches!(
            (self, want),
            (Frame::Proc { .. }, Want::Proc)
                | (Frame::If { .. }, Want::If)
                | (Frame::Select { .. }, Want::Select)
                | (Frame::For { .. }, Want::For)
        ) || matches!(self, Frame::Loop { kind, .. } if want == Want::Loop(*kind))
    }

    pub(super) fn opener(&self) -> Span {
        match self {
            Frame::Proc { header, .. } => *header,
            Frame::If { span, .. }
            | Frame::Select { span, .. }
            | Frame::For { span, .. }
            | Frame::Loop { span, .. } => *span,
        }
    }
}
