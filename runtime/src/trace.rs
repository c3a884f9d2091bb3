//! Provenance: which post statement wrote each output line, and for which
//! input event (`postc post --trace`, docs/trace.md).
//!
//! A run with a [`Tracer`] reports one [`TraceLine`] per block written, in
//! output order. The engine keeps what it is doing as it runs — the
//! handler, the chain of post functions called, the event being dispatched
//! — and after each statement hands every block that statement wrote to
//! the tracer with the statement's span ([`postc_ir::Stmt::Line`]) or, for
//! text a function returned, the `return` statement that returned it (the
//! latest [`postc_ir::Stmt::Origin`] the handler passed), else the
//! innermost function's. A run without a
//! tracer pays one branch per statement.

use postc_ir::{FileId, FunctionId, HandlerKey, Span};

/// One output line and where it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceLine<'a> {
    /// The tape-split part the line is in (0 for a program in one file).
    pub part: usize,
    /// The line's number in its part, from 1.
    pub line: u64,
    /// The statement that wrote the line: an output line's span, else the
    /// `return` statement that returned it, else the innermost post
    /// function's, else the handler's.
    pub span: Option<Span>,
    /// The post functions running when the line was written, outermost
    /// first, with where each is defined.
    pub calls: &'a [(FunctionId, Option<Span>)],
    /// The handler that was running (a section or an APT word), if any.
    pub handler: Option<&'a HandlerKey>,
    pub handler_span: Option<Span>,
    /// The input event being handled, counted from 0; `None` before the
    /// first event and after the last (the program's end).
    pub event: Option<u64>,
    /// Where that event is in the toolpath file.
    pub event_span: Option<Span>,
}

/// Receives the trace of a run.
pub type TraceSink = Box<dyn FnMut(&TraceLine<'_>)>;

/// What the engine keeps while tracing.
pub struct Tracer {
    sink: TraceSink,
    /// Post functions running, outermost first.
    pub(crate) calls: Vec<(FunctionId, Option<Span>)>,
    pub(crate) handler: Option<(HandlerKey, Option<Span>)>,
    pub(crate) event: Option<u64>,
    pub(crate) event_span: Option<Span>,
    /// The latest [`postc_ir::Stmt::Origin`] the running handler passed;
    /// with a host's API compiled with the post, the latest of the
    /// innermost post function still running (its callees' are dropped
    /// when they return, [`Tracer::enter`], [`Tracer::leave`]).
    pub(crate) origin: Option<Span>,
    /// The caller's origin for each function in `calls`.
    origins: Vec<Option<Span>>,
    /// The host's API compiled with the post (Fusion's): a line its code
    /// writes is the post statement's that called it.
    host_file: Option<FileId>,
    /// Blocks handed to the sink so far.
    traced: u64,
    part: usize,
}

impl Tracer {
    pub fn new(sink: TraceSink, host_file: Option<FileId>) -> Tracer {
        Tracer {
            sink,
            calls: Vec::new(),
            handler: None,
            event: None,
            event_span: None,
            origin: None,
            origins: Vec::new(),
            host_file,
            traced: 0,
            part: 0,
        }
    }

    /// A post function is called.
    pub(crate) fn enter(&mut self, f: FunctionId, span: Option<Span>) {
        self.calls.push((f, span));
        self.origins.push(self.origin);
    }

    /// The innermost post function returns: under a host's API compiled
    /// with the post, the statement that called it is the current one
    /// again (a CNC-Calc entry point's `return` stays the origin of the
    /// text the engine writes after it returns).
    pub(crate) fn leave(&mut self) {
        self.calls.pop();
        let caller = self.origins.pop().flatten();
        if self.host_file.is_some() {
            self.origin = caller;
        }
    }

    /// Reports the blocks written since the last report: `blocks` written
    /// in all, `in_part` of them in the current part.
    pub(crate) fn report(&mut self, blocks: u64, in_part: u64, span: Option<Span>) {
        let new = blocks.saturating_sub(self.traced);
        if new == 0 {
            return;
        }
        // A line the host's code wrote (Fusion's `writeln`) is the post
        // statement's that called it.
        let in_host = |s: &Span| Some(s.file) == self.host_file;
        let span = span
            .filter(|s| !in_host(s) || self.origin.is_none_or(|o| in_host(&o)))
            .or(self.origin)
            .or_else(|| self.calls.last().and_then(|c| c.1))
            .or(self.handler.as_ref().and_then(|h| h.1));
        let first = in_part + 1 - new.min(in_part);
        for line in first..=in_part {
            let record = TraceLine {
                part: self.part,
                line,
                span,
                calls: &self.calls,
                handler: self.handler.as_ref().map(|h| &h.0),
                handler_span: self.handler.as_ref().and_then(|h| h.1),
                event: self.event,
                event_span: self.event_span,
            };
            (self.sink)(&record);
        }
        self.traced = blocks;
    }

    /// A new tape-split part starts.
    pub(crate) fn new_part(&mut self) {
        self.part += 1;
    }
}
