//! Opening and closing blocks: finding the block a closing line closes,
//! reporting blocks that were never closed (VC005-VC009) and closing lines
//! with nothing to close (VC010), and turning a closed block into its
//! statement.

use postc_ir::{Diagnostic, Span};

use super::frame::{Frame, Want};
use super::{Builder, MAX_BLOCK_DEPTH, ProcRange};
use crate::ast::{CaseArm, Item, LoopKind, Procedure, Stmt, StmtKind};
use crate::diagnostics as codes;

impl Builder {
    pub(super) fn in_proc(&self) -> bool {
        self.stack.iter().any(|f| matches!(f, Frame::Proc { .. }))
    }

    pub(super) fn open(&mut self, frame: Frame) {
        let blocks = self.stack.iter().filter(|f| !matches!(f, Frame::Proc { .. })).count();
        if blocks >= MAX_BLOCK_DEPTH {
            let d = Diagnostic::error(
                codes::TOO_COMPLEX,
                format!("blocks are nested too deeply (at most {MAX_BLOCK_DEPTH} levels)"),
            )
            .at(frame.opener(), "this block and what it holds are skipped")
            .help("move the inner part into a Sub of its own");
            self.diagnostics.push(d);
            self.suppressed = 1;
            return;
        }
        self.stack.push(frame);
    }

    /// Closes unfinished blocks above the nearest frame matching `want`;
    /// false (and nothing closed) when no frame in the current Sub matches.
    pub(super) fn close_to(&mut self, want: Want, at: Span) -> bool {
        let mut found = None;
        for (i, f) in self.stack.iter().enumerate().rev() {
            if f.matches(want) {
                found = Some(i);
                break;
            }
            if matches!(f, Frame::Proc { .. }) {
                break;
            }
        }
        let Some(index) = found else { return false };
        while self.stack.len() > index + 1 {
            self.close_unfinished(at, "expected before this line");
        }
        true
    }

    /// For `Else` and `ElseIf`: closes up to the nearest `If` block, or to
    /// the one around it when the nearest is already in its `Else` part and
    /// the outer one is not (the inner one most likely lacks its `End If`).
    pub(super) fn close_to_open_if(&mut self, at: Span) -> bool {
        let mut ifs = Vec::new();
        for (i, f) in self.stack.iter().enumerate().rev() {
            match f {
                Frame::If { in_else, .. } => {
                    ifs.push((i, *in_else));
                    if ifs.len() == 2 {
                        break;
                    }
                }
                Frame::Proc { .. } => break,
                _ => {}
            }
        }
        let index = match ifs.as_slice() {
            [] => return false,
            [(_, true), (outer, false)] => *outer,
            [(nearest, _), ..] => *nearest,
        };
        while self.stack.len() > index + 1 {
            self.close_unfinished(at, "expected before this line");
        }
        true
    }

    pub(super) fn close(&mut self, want: Want, span: Span, stray: &str) {
        if self.close_to(want, span) {
            self.finish_top(Some(span), span);
        } else {
            self.stray(span, stray);
        }
    }

    pub(super) fn stray(&mut self, span: Span, what: &str) {
        self.diagnostics.push(
            Diagnostic::error(codes::STRAY_CLOSER, what.to_string())
                .at(span, "nothing open here for this to close")
                .help("remove this line, or add the line that opens the block above it"),
        );
    }

    pub(super) fn case(&mut self, tests: Option<Vec<crate::ast::CaseTest>>, span: Span) {
        if !self.close_to(Want::Select, span) {
            return self.stray(span, "`Case` without a `Select Case`");
        }
        if let Some(Frame::Select { arms, in_else, .. }) = self.stack.last_mut() {
            if *in_else {
                let d = Diagnostic::error(codes::MISPLACED, "`Case` after `Case Else`")
                    .at(span, "this `Case` can never be reached")
                    .help("put `Case Else` last");
                self.diagnostics.push(d);
                return;
            }
            match tests {
                Some(tests) => arms.push(CaseArm { tests, body: Vec::new(), span }),
                None => *in_else = true,
            }
        }
    }

    /// Reports the top frame as never closed and closes it.
    pub(super) fn close_unfinished(&mut self, at: Span, why: &str) {
        let Some(top) = self.stack.last() else { return };
        let (code, message, help) = match top {
            Frame::Proc { kind, name, .. } => (
                codes::MISSING_END_SUB,
                format!("{} `{}` has no `End {}`", kind.as_str(), name.text, kind.as_str()),
                format!("add `End {}` after its last statement", kind.as_str()),
            ),
            Frame::If { after_else, else_if_child, .. } => (
                codes::MISSING_END_IF,
                "this `If` block has no `End If`".to_string(),
                if *after_else || else_if_child.is_some() {
                    "`Else If` on one line opens a new `If` block; write `ElseIf` (one word) to go on with the same block".to_string()
                } else {
                    "add `End If` after the last statement of the block".to_string()
                },
            ),
            Frame::Select { .. } => (
                codes::MISSING_END_SELECT,
                "this `Select Case` has no `End Select`".to_string(),
                "add `End Select` after the last `Case`".to_string(),
            ),
            Frame::For { looped, .. } => (
                codes::MISSING_NEXT,
                format!("this `For {}` has no `Next`", looped.var.text),
                "add `Next` after the last statement of the loop".to_string(),
            ),
            Frame::Loop { kind: LoopKind::While, .. } => (
                codes::MISSING_LOOP_END,
                "this `While` has no `Wend`".to_string(),
                "add `Wend` after the last statement of the loop".to_string(),
            ),
            Frame::Loop { kind: LoopKind::Do, .. } => (
                codes::MISSING_LOOP_END,
                "this `Do` has no `Loop`".to_string(),
                "add `Loop` after the last statement of the loop".to_string(),
            ),
        };
        let mut d =
            Diagnostic::error(code, message).at(top.opener(), "opened here and never closed").also(at, why).help(help);
        if let Frame::If { else_if_child: Some(child), .. } = top {
            d = d.also(*child, "this `Else If` opened a new block, which took the `End If`");
        }
        self.diagnostics.push(d);
        self.finish_top(None, at);
    }

    /// Pops the top frame and adds what it built to its parent.
    pub(super) fn finish_top(&mut self, end: Option<Span>, at: Span) {
        let Some(frame) = self.stack.pop() else { return };
        let stmt = match frame {
            Frame::Proc { kind, name, params, header, body } => {
                let stop = end.map_or(at.start, |e| e.start);
                self.ranges.push(ProcRange { item: self.items.len(), start: header.end, end: stop });
                self.items.push(Item::Proc(Procedure {
                    kind,
                    name,
                    params,
                    body,
                    header,
                    end,
                    keyword_comments: Vec::new(),
                    doc: Vec::new(),
                }));
                return;
            }
            Frame::If { span, branches, otherwise, after_else, .. } => {
                if after_else
                    && end.is_some()
                    && let Some(Frame::If { else_if_child, .. }) = self.stack.last_mut()
                {
                    *else_if_child = Some(span);
                }
                Stmt { kind: StmtKind::If { branches, otherwise }, span }
            }
            Frame::Select { span, subject, arms, otherwise, .. } => {
                Stmt { kind: StmtKind::Select { subject, cases: arms, otherwise }, span }
            }
            Frame::For { span, looped } => Stmt { kind: StmtKind::For(looped), span },
            Frame::Loop { span, kind, test, body } => {
                Stmt { kind: StmtKind::Loop { test, at_end: false, body, kind }, span }
            }
        };
        self.push(stmt);
    }

    pub(super) fn finish_loop_at_end(&mut self) {
        if let Some(Frame::Loop { span, kind, test, body }) = self.stack.pop() {
            self.push(Stmt { kind: StmtKind::Loop { test, at_end: true, body, kind }, span });
        }
    }
}
