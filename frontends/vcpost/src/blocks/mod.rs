//! Block structure: nests the parsed lines into Subs, `If` blocks, `Select
//! Case`, `For`, `While` and `Do` loops.
//!
//! A stack of open blocks is kept. A closing line (`End If`, `Next`,
//! `Wend`, ...) closes the nearest open block of its kind; blocks opened
//! after that one and never closed are reported at their opening line
//! (VC005-VC009) and closed there, so one forgotten `End If` gives one
//! diagnostic and the rest of the file still reads. A closing line with no
//! block to close is VC010. Closing lines never reach past the Sub they are
//! in, and a `Sub` line closes everything still open.

use postc_ir::{Diagnostic, FileId, Span};

use crate::ast::{ForLoop, Item, LoopKind, Stmt, StmtKind};
use crate::diagnostics as codes;
use crate::parser::LineItem;

/// Deepest nesting of blocks inside one Sub.
pub const MAX_BLOCK_DEPTH: usize = 32;

/// A Procedure item and the byte range its keyword comments may sit in.
#[derive(Clone, Copy, Debug)]
pub struct ProcRange {
    pub item: usize,
    pub start: usize,
    pub end: usize,
}

/// The nested items and, for each Sub, its range.
pub struct Built {
    pub items: Vec<Item>,
    pub ranges: Vec<ProcRange>,
    pub diagnostics: Vec<Diagnostic>,
}

mod closing;
mod frame;

use frame::{Frame, Want};

struct Builder {
    items: Vec<Item>,
    ranges: Vec<ProcRange>,
    stack: Vec<Frame>,
    diagnostics: Vec<Diagnostic>,
    /// Openers ignored because nesting was too deep, not yet closed.
    suppressed: usize,
}

/// Nests lines into blocks.
pub fn build(lines: Vec<Vec<LineItem>>, text_len: usize, file: FileId) -> Built {
    let mut b =
        Builder { items: Vec::new(), ranges: Vec::new(), stack: Vec::new(), diagnostics: Vec::new(), suppressed: 0 };
    for line in lines {
        let mut after_else = false;
        for item in line {
            let is_else = matches!(item, LineItem::Else { .. });
            b.item(item, after_else);
            after_else = is_else;
        }
    }
    let eof = Span::new(file, text_len, text_len);
    while !b.stack.is_empty() {
        b.close_unfinished(eof, "the file ends here");
    }
    Built { items: b.items, ranges: b.ranges, diagnostics: b.diagnostics }
}

impl Builder {
    fn item(&mut self, item: LineItem, after_else: bool) {
        if self.suppressed > 0 && !matches!(item, LineItem::ProcStart { .. } | LineItem::ProcEnd { .. }) {
            match item {
                LineItem::IfStart { .. }
                | LineItem::SelectStart { .. }
                | LineItem::ForStart { .. }
                | LineItem::LoopStart { .. } => self.suppressed += 1,
                LineItem::EndIf { .. }
                | LineItem::EndSelect { .. }
                | LineItem::Next { .. }
                | LineItem::LoopEnd { .. } => self.suppressed -= 1,
                _ => {}
            }
            return;
        }
        match item {
            LineItem::Stmt(s) => self.push(s),
            LineItem::Error { span } => self.push(Stmt { kind: StmtKind::Error, span }),
            LineItem::ProcStart { kind, name, params, span } => {
                self.suppressed = 0;
                while !self.stack.is_empty() {
                    let why = if self.in_proc() { "the next Sub starts here" } else { "a Sub starts here" };
                    self.close_unfinished(span, why);
                }
                self.stack.push(Frame::Proc { kind, name, params, header: span, body: Vec::new() });
            }
            LineItem::ProcEnd { kind, span } => {
                self.suppressed = 0;
                if self.close_to(Want::Proc, span) {
                    if let Some(Frame::Proc { kind: open, name, .. }) = self.stack.last()
                        && *open != kind
                    {
                        let d = Diagnostic::error(
                            codes::MISPLACED,
                            format!("`End {}` closes {} `{}`", kind.as_str(), open.as_str(), name.text),
                        )
                        .at(span, format!("write `End {}` here", open.as_str()));
                        self.diagnostics.push(d);
                    }
                    self.finish_top(Some(span), span);
                } else {
                    self.stray(span, &format!("`End {}` without a `{}`", kind.as_str(), kind.as_str()));
                }
            }
            LineItem::IfStart { cond, span } => self.open(Frame::If {
                span,
                branches: vec![(cond, Vec::new())],
                otherwise: Vec::new(),
                in_else: false,
                after_else,
                else_if_child: None,
            }),
            LineItem::ElseIf { cond, span } => {
                if !self.close_to_open_if(span) {
                    return self.stray(span, "`ElseIf` without an `If ... Then` block");
                }
                if let Some(Frame::If { branches, in_else, .. }) = self.stack.last_mut() {
                    if *in_else {
                        self.diagnostics.push(
                            Diagnostic::error(codes::MISPLACED, "`ElseIf` after `Else`")
                                .at(span, "this `ElseIf` can never be reached")
                                .help("put every `ElseIf` before the `Else`"),
                        );
                    } else {
                        branches.push((cond, Vec::new()));
                    }
                }
            }
            LineItem::Else { span } => {
                if !self.close_to_open_if(span) {
                    return self.stray(span, "`Else` without an `If ... Then` block");
                }
                if let Some(Frame::If { in_else, .. }) = self.stack.last_mut() {
                    if *in_else {
                        self.diagnostics.push(
                            Diagnostic::error(codes::MISPLACED, "a second `Else` in one `If` block")
                                .at(span, "second `Else`"),
                        );
                    }
                    *in_else = true;
                }
            }
            LineItem::EndIf { span } => self.close(Want::If, span, "`End If` without an `If ... Then` block"),
            LineItem::SelectStart { subject, span } => {
                self.open(Frame::Select { span, subject, arms: Vec::new(), otherwise: Vec::new(), in_else: false })
            }
            LineItem::Case { tests, span } => self.case(Some(tests), span),
            LineItem::CaseElse { span } => self.case(None, span),
            LineItem::EndSelect { span } => self.close(Want::Select, span, "`End Select` without a `Select Case`"),
            LineItem::ForStart { var, from, to, step, span } => {
                self.open(Frame::For { span, looped: Box::new(ForLoop { var, from, to, step, body: Vec::new() }) })
            }
            LineItem::Next { var, span } => {
                if !self.close_to(Want::For, span) {
                    return self.stray(span, "`Next` without a `For`");
                }
                if let (Some(var), Some(Frame::For { looped, .. })) = (&var, self.stack.last())
                    && let open = &looped.var
                    && var.key() != open.key()
                {
                    let d =
                        Diagnostic::error(codes::MISPLACED, format!("`Next {}` closes `For {}`", var.text, open.text))
                            .at(var.span, format!("expected `{}`", open.text))
                            .also(open.span, "the loop that is open");
                    self.diagnostics.push(d);
                }
                self.finish_top(Some(span), span);
            }
            LineItem::LoopStart { kind, test, span } => self.open(Frame::Loop { span, kind, test, body: Vec::new() }),
            LineItem::LoopEnd { kind, test, span } => {
                let what = match kind {
                    LoopKind::While => "`Wend` without a `While`",
                    LoopKind::Do => "`Loop` without a `Do`",
                };
                if !self.close_to(Want::Loop(kind), span) {
                    return self.stray(span, what);
                }
                if let (Some(end_test), Some(Frame::Loop { test: start_test, .. })) = (test, self.stack.last_mut()) {
                    if start_test.is_some() {
                        let d = Diagnostic::error(
                            codes::MISPLACED,
                            "a `Do` loop tests at its top or at its bottom, not both",
                        )
                        .at(span, "second test")
                        .help("keep `Do While c ... Loop` or `Do ... Loop While c`");
                        self.diagnostics.push(d);
                    } else {
                        *start_test = Some(end_test);
                        self.finish_loop_at_end();
                        return;
                    }
                }
                self.finish_top(Some(span), span);
            }
        }
    }

    /// Adds a statement to the innermost open body.
    fn push(&mut self, stmt: Stmt) {
        let Some(frame) = self.stack.last_mut() else {
            self.items.push(Item::Stmt(stmt));
            return;
        };
        let body = match frame {
            Frame::Proc { body, .. } | Frame::Loop { body, .. } => body,
            Frame::For { looped, .. } => &mut looped.body,
            Frame::If { branches, otherwise, in_else, .. } => {
                if *in_else {
                    otherwise
                } else {
                    match branches.last_mut() {
                        Some(b) => &mut b.1,
                        None => otherwise,
                    }
                }
            }
            Frame::Select { arms, otherwise, in_else, .. } => {
                if *in_else {
                    otherwise
                } else if let Some(arm) = arms.last_mut() {
                    &mut arm.body
                } else {
                    if !matches!(stmt.kind, StmtKind::Error) {
                        let d = Diagnostic::error(
                            codes::MISPLACED,
                            "a statement between `Select Case` and the first `Case`",
                        )
                        .at(stmt.span, "this is never run")
                        .help("move it above the `Select Case` or below a `Case` line");
                        self.diagnostics.push(d);
                    }
                    return;
                }
            }
        };
        body.push(stmt);
    }
}
