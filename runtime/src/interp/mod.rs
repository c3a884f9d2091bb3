//! The interpreter of the IR's statement language: assignments,
//! conditionals, loops, calls and expressions over [`Value`]s.
//!
//! Every statement costs one step; a handler call that runs past the post's
//! step budget stops with a diagnostic at the innermost loop, so a runaway
//! post never hangs.

use postc_ir::{
    BinaryOp, Builtin, Diagnostic, FunctionId, GlobalId, LocalId, Place, Quantity, Span, UnaryOp, ValueSource, VarId,
};

pub(crate) mod host_text;
pub(crate) mod objects;
pub(crate) mod ops;
pub(crate) mod protos;

use ops::{binary, builtin, compare, unary};

use crate::exec::{Body, Expr, Piece, Stmt, WordRun, WordsBefore};

use crate::engine::{Engine, KeptWord, is_modal, number_word, put_number, put_text};
use crate::value::{INLINE_TEXT, Text, Value};

/// How a block of statements ended.
#[doc(hidden)]
pub enum Flow {
    Normal,
    Break,
    Continue,
    Return(Value),
}

type Result<T> = std::result::Result<T, Box<Diagnostic>>;

/// The code of a text past [`MAX_TEXT_BYTES`].
pub const TEXT_BUDGET: &str = "RT031";

/// The error of a text past [`MAX_TEXT_BYTES`] (native code and scripts).
pub fn text_budget_error(len: usize) -> Diagnostic {
    Diagnostic::error(
        TEXT_BUDGET,
        format!(
            "the post built a text of more than {} MiB ({len} bytes) and was stopped (text doubled in a loop?)",
            MAX_TEXT_BYTES >> 20
        ),
    )
    .note("no output is written; a post writes its program block by block and never needs text this long")
}

/// The code of a value that is not a finite number given to a format.
pub const NON_FINITE: &str = "RT032";

/// The error of a value that is not a finite number given to a format,
/// at the post text that formats it.
#[cold]
pub fn non_finite_error(value: f64, span: Option<Span>) -> Box<Diagnostic> {
    let what = if value.is_nan() { "NaN (not a number)" } else { "an infinite number" };
    let d = Diagnostic::error(NON_FINITE, format!("the post formats {what} as a number word"))
        .note("no output is written: a word no controller reads, or a 0 in its place, would move the machine where the post never meant")
        .help("a division by zero, the square root of a negative number, a key missing from a table, `undefined` or text that is not a number gives NaN or infinity; check the value before formatting it");
    Box::new(match span {
        Some(s) => d.at(s, "this value is not a finite number"),
        None => d,
    })
}

/// The error of a setting the post cannot take ([`Builtin::SettingError`]):
/// placed nowhere, since neither the post nor the toolpath is at fault.
fn setting_error(message: String) -> Diagnostic {
    Diagnostic::error(postc_ir::codes::IO007.code, message)
        .note("nothing was posted; the setting comes from the command line (`--set property.NAME=VALUE`)")
}

/// Whether an error is about the command line's settings, which names no
/// place in the post or the toolpath.
pub fn is_setting_error(e: &Diagnostic) -> bool {
    e.code == postc_ir::codes::IO007.code && e.labels.is_empty()
}

/// At most this many emptied arrays are kept to be made again, each of at
/// most this many items' storage.
const SPARE_ARRAYS: usize = 64;
const SPARE_ARRAY_ITEMS: usize = 256;

/// Calls nest at most this deep.
const MAX_DEPTH: usize = 200;

/// Below this much stack left, a call runs on a new stack segment of
/// [`STACK_GROWTH`] bytes ([`stacker`]).
const STACK_RED_ZONE: usize = 128 * 1024;
const STACK_GROWTH: usize = 2 * 1024 * 1024;

/// The longest text a post's code may build, in bytes (16 MiB), in native
/// code and in scripts alike: a post is code from strangers, and
/// `s = s + s` in a loop doubles its memory every step, long before the
/// step budget stops it. No real post comes near: a whole program is
/// written block by block, never held in one value.
pub const MAX_TEXT_BYTES: usize = 16 << 20;

/// Text longer than this costs one more step per this many bytes, so that
/// a loop growing a long text (`s = s + "x"`, each step a copy of all of
/// it) meets the step budget in seconds rather than hours.
const TEXT_STEP_BYTES: usize = 256;

impl Engine<'_> {
    /// Fails at `span` when a format of this thread was given a value that
    /// is not a finite number since the last look.
    #[inline(always)]
    pub(crate) fn finite(&self, span: Option<Span>) -> Result<()> {
        match crate::number::take_non_finite() {
            None => Ok(()),
            Some(v) => Err(non_finite_error(v, span)),
        }
    }

    /// Runs statements with a frame of locals. An error raised in the
    /// host's API under one of them gets, once, the place of the post's
    /// statement that led there: the [`Stmt::Origin`] before it.
    #[doc(hidden)]
    pub fn exec(&mut self, stmts: &[Stmt], frame: &mut Vec<Value>) -> Result<Flow> {
        let mut rest = stmts.iter();
        match self.exec_from(stmts, &mut rest, frame) {
            Err(e) => Err(self.at_origin(e, &stmts[..stmts.len() - rest.len()])),
            flow => flow,
        }
    }

    /// The origin of the last statement of `ran` (the latest
    /// [`Stmt::Origin`] among them, in the post's own text) for an error
    /// raised in the host's API under it, or for one with no place of its
    /// own (a call of a value that is no function).
    #[cold]
    fn at_origin(&self, e: Box<Diagnostic>, ran: &[Stmt]) -> Box<Diagnostic> {
        let Some(host) = self.post.info.host_file else { return e };
        if is_setting_error(&e) {
            return e;
        }
        if e.primary_span().is_some() && !in_host_only(&e, host) {
            return e;
        }
        match ran.iter().rev().find_map(|s| if let Stmt::Origin(span) = s { Some(*span) } else { None }) {
            Some(span) if span.file != host && e.primary_span().is_none() => Box::new(e.at(span, "in this statement")),
            Some(span) if span.file != host => Box::new(e.also(span, "the post's statement that led there")),
            _ => e,
        }
    }

    #[inline(always)]
    fn exec_from<'s>(
        &mut self,
        stmts: &'s [Stmt],
        rest: &mut std::slice::Iter<'s, Stmt>,
        frame: &mut Vec<Value>,
    ) -> Result<Flow> {
        // Every statement costs one step. The steps of a block are counted
        // when it is entered, and those of the statements a jump skips are
        // given back when it leaves: a block run to its end costs what it
        // did counted statement by statement, checked once a block (a
        // runaway is stopped sooner by at most the statements not yet run
        // in the blocks around it).
        self.steps += stmts.len() as u64;
        if self.steps > self.post.options.step_budget {
            return Err(Box::new(self.budget_error(None)));
        }
        let tracing = self.trace.is_some();
        while let Some(stmt) = rest.next() {
            match stmt {
                Stmt::Assign(Place::Local(i), e) => {
                    // `x = xOutput.format(vx)`, a handler's commonest line,
                    // costs no pass through `eval`.
                    let v = match e {
                        Expr::FormatVar { var, value, span } => self.format_var_call(*var, value, *span, frame)?,
                        _ => self.eval(e, frame)?,
                    };
                    match frame.get_mut(i.index()) {
                        Some(slot) => {
                            // An array only this local held (`words =
                            // words.concat(...)`) is kept to be made again.
                            if let Value::Array(a) = slot
                                && std::rc::Rc::strong_count(a) == 1
                                && std::rc::Rc::weak_count(a) == 0
                            {
                                self.keep_array(slot);
                            }
                            std::mem::replace(slot, v).let_go();
                        }
                        None => self.assign(Place::Local(*i), v, frame),
                    }
                }
                Stmt::Assign(place, e) => self.assign_to(*place, e, frame)?,
                Stmt::Eval(e) => {
                    self.eval(e, frame)?;
                }
                Stmt::If { branches, otherwise } => {
                    let mut taken = None;
                    for (cond, body) in branches {
                        if self.test(cond, frame)? {
                            taken = Some(body);
                            break;
                        }
                    }
                    let body = taken.unwrap_or(otherwise);
                    // An `if` with nothing to run (most have no `else`)
                    // costs no call.
                    if !body.is_empty() {
                        match self.exec(body, frame)? {
                            Flow::Normal => {}
                            flow => return Ok(self.leave(flow, rest.len())),
                        }
                    }
                }
                Stmt::While { cond, body, span, step } => loop {
                    self.steps += 1;
                    if self.steps > self.post.options.step_budget {
                        return Err(Box::new(self.budget_error(*span)));
                    }
                    if !self.test(cond, frame)? {
                        break;
                    }
                    match self.exec(body, frame).map_err(|e| Self::in_loop(e, *span))? {
                        Flow::Break => break,
                        Flow::Return(v) => return Ok(self.leave(Flow::Return(v), rest.len())),
                        Flow::Normal | Flow::Continue => {}
                    }
                    if !step.is_empty() {
                        // A `for` loop's update has no jumps of its own.
                        self.exec(step, frame).map_err(|e| Self::in_loop(e, *span))?;
                    }
                },
                // `box[0] = v`, `list[i] = v` of a local: the value is
                // evaluated first and the object and key read in place
                // (no expression assigns a local of its frame, so they read
                // as they did before it).
                Stmt::SetMember { object, key, value, span } if is_frame_leaf(object) && is_frame_leaf(key) => {
                    let v = self.eval(value, frame)?;
                    let (mut to, mut tk) = (Value::Null, Value::Null);
                    let o = plain_leaf(object, frame, &self.globals, &mut to);
                    let k = plain_leaf(key, frame, &self.globals, &mut tk);
                    if self.is_global_object(o) {
                        let k = k.clone();
                        self.set_global_member(&k, v)?;
                    } else {
                        store_member(o, key, k, v).map_err(|e| at(e, span.0, "this assignment"))?;
                    }
                    to.let_go();
                    tk.let_go();
                }
                Stmt::SetMember { object, key, value, span } => {
                    let o = self.eval(object, frame)?;
                    let k = self.eval(key, frame)?;
                    let v = self.eval(value, frame)?;
                    if self.is_global_object(&o) {
                        self.set_global_member(&k, v)?;
                    } else {
                        store_member(&o, key, &k, v).map_err(|e| at(e, span.0, "this assignment"))?;
                    }
                }
                Stmt::Throw { value, span } => {
                    let v = self.eval(value, frame)?;
                    let error = objects::uncaught(&v, *span);
                    self.thrown = Some(v);
                    return Err(error);
                }
                Stmt::Try { body, catch, finally } => match self.run_try(body, catch.as_ref(), finally, frame)? {
                    Flow::Normal => {}
                    flow => return Ok(self.leave(flow, rest.len())),
                },
                Stmt::Break => return Ok(self.leave(Flow::Break, rest.len())),
                Stmt::Continue => return Ok(self.leave(Flow::Continue, rest.len())),
                Stmt::Emit(pieces) => self.emit_pieces(pieces, frame)?,
                Stmt::Mark(k) => {
                    let at = Value::Num(self.out.buf.len() as f64);
                    match frame.get_mut(k.index()) {
                        Some(slot) => *slot = at,
                        None => self.assign(Place::Local(*k), at, frame),
                    }
                }
                Stmt::Truncate(k) => {
                    let at = self.mark(*k, frame);
                    self.out.buf.truncate(at);
                }
                Stmt::Word { cond, word, sep, before } => self.word(cond, word, sep, *before, frame)?,
                Stmt::Words(run) => match self.words(run, frame)? {
                    Flow::Normal => {}
                    flow => return Ok(self.leave(flow, rest.len())),
                },
                Stmt::Origin(span) => {
                    if let Some(t) = self.trace.as_deref_mut() {
                        t.origin = Some(*span);
                    }
                }
                Stmt::Line { pieces, span } => {
                    self.write_line_in(pieces, frame)?;
                    self.finite(*span)?;
                }
                Stmt::Write(e) => {
                    // An entry point that returns nothing (`undefined`)
                    // writes nothing, as CNC-Calc does.
                    let v = self.eval(e, frame)?;
                    if !matches!(v, Value::Undefined) {
                        self.write_blocks(&v.to_text());
                    }
                }
                Stmt::Return(e) => {
                    let v = match e {
                        Some(e) => self.eval(e, frame)?,
                        None => Value::Null,
                    };
                    return Ok(self.leave(Flow::Return(v), rest.len()));
                }
                Stmt::MoveBack { to, from } => {
                    let (to, from) = (self.mark(*to, frame), self.mark(*from, frame));
                    if to < from {
                        move_back(&mut self.out.buf, to, from);
                    }
                }
                Stmt::Cut { at, chars } => {
                    let at = self.mark(*at, frame);
                    let written = &self.out.buf[at..];
                    let ascii = (*chars).min(written.len());
                    // Characters are bytes while they are ASCII.
                    let bytes = if written[..ascii].is_ascii() {
                        ascii
                    } else {
                        match std::str::from_utf8(written) {
                            Ok(t) => t.char_indices().nth(*chars).map_or(t.len(), |(i, _)| i),
                            Err(_) => ascii,
                        }
                    };
                    self.out.buf.drain(at..at + bytes);
                }
                Stmt::Blocks(k) => {
                    let at = self.mark(*k, frame);
                    self.blocks_since(at);
                }
                Stmt::Forget(v) => self.forget_var(*v),
                Stmt::Script(_) => self.warn_once(
                    Diagnostic::warning(
                        "RT003",
                        "this post calls Lua scripts, which postc does not run; those lines are skipped",
                    )
                    .note("the rest of the post runs as written"),
                ),
            }
            if tracing {
                let span = if let Stmt::Line { span, .. } = stmt { *span } else { None };
                self.trace_after(span);
            }
        }
        Ok(Flow::Normal)
    }

    /// A store to a global or a variable ([`Stmt::Assign`]; a local's is
    /// done in `exec`). A count kept in a global (`sequenceNumber +=
    /// increment`, in every field post) is bumped where it is.
    #[inline(never)]
    fn assign_to(&mut self, place: Place, e: &Expr, frame: &mut Vec<Value>) -> Result<()> {
        if let (Place::Global(g), Expr::Binary(BinaryOp::Add, a, b)) = (place, e)
            && let (Expr::Global(h), Expr::Number(step)) = (&**a, &**b)
            && *h == g
            && let Some(Value::Num(n)) = self.globals.get_mut(g.index())
        {
            *n += step;
            return Ok(());
        }
        let v = self.eval(e, frame)?;
        // A global's store, the commonest here, made where it is.
        if let Place::Global(g) = place
            && let Some(slot) = self.globals.get_mut(g.index())
        {
            std::mem::replace(slot, v).let_go();
            return Ok(());
        }
        self.assign(place, v, frame);
        Ok(())
    }

    /// A block left by a jump: the steps of the `skipped` statements after
    /// it, counted when the block was entered, are given back.
    #[inline(always)]
    fn leave(&mut self, flow: Flow, skipped: usize) -> Flow {
        self.steps = self.steps.saturating_sub(skipped as u64);
        flow
    }

    /// One word of a block built in the output ([`Stmt::Word`]): the
    /// statements it stands for, with their steps, in their order.
    fn word(
        &mut self,
        cond: &Expr,
        word: &[Piece],
        sep: &[u8],
        before: WordsBefore,
        frame: &mut Vec<Value>,
    ) -> Result<()> {
        // A word printed when it is not empty: `if (w)` or `if (w != "")`.
        let printed = match cond {
            Expr::Local(i) => frame.get(i.index()).is_some_and(Value::truthy),
            _ => self.test(cond, frame)?,
        };
        if !printed {
            return Ok(());
        }
        let after_first = match before {
            WordsBefore::Count(n) => match frame.get(n.index()) {
                Some(Value::Num(x)) => *x > 0.0,
                n => compare(BinaryOp::JsGt, n.unwrap_or(&Value::Null), &Value::Num(0.0)).unwrap_or(false),
            },
            WordsBefore::Written(m) => self.out.buf.len() > self.mark(m, frame),
        };
        // The steps of the statements it stands for: the inner `if`, then
        // the separator, the word and the count, or the cut and the word.
        self.steps += match before {
            WordsBefore::Count(_) => 3 + u64::from(after_first),
            WordsBefore::Written(_) => 2 + u64::from(!after_first),
        };
        if self.steps > self.post.options.step_budget {
            return Err(Box::new(self.budget_error(None)));
        }
        if after_first {
            push_short(&mut self.out.buf, sep);
        } else if let WordsBefore::Written(m) = before {
            let at = self.mark(m, frame);
            self.out.buf.truncate(at);
        }
        // The usual word, a local's text, is copied where it is.
        match word {
            [Piece::Expr(Expr::Local(i)) | Piece::Joined(Expr::Local(i))]
                if let Some(Value::Text(t)) = frame.get(i.index()) =>
            {
                t.append_to_bytes(&mut self.out.buf);
            }
            _ => self.emit_pieces(word, frame)?,
        }
        if let WordsBefore::Count(n) = before {
            if let Some(Value::Num(x)) = frame.get_mut(n.index()) {
                *x += 1.0;
                return Ok(());
            }
            let next = match frame.get(n.index()) {
                Some(v) => binary(BinaryOp::Add, v, &Value::Num(1.0)),
                None => binary(BinaryOp::Add, &Value::Null, &Value::Num(1.0)),
            };
            self.check_text(&next)?;
            self.assign(Place::Local(n), next, frame);
        }
        Ok(())
    }

    /// A run of words ([`Stmt::Words`]): when every word is a text, each
    /// one not empty is written, with the separator after the first, and
    /// the count or the mark, the steps and an empty block's truncation
    /// are what the run's statements make of them; otherwise they run.
    fn words(&mut self, run: &WordRun, frame: &mut Vec<Value>) -> Result<Flow> {
        let texts = run.locals.iter().all(|w| matches!(frame.get(w.index()), Some(Value::Text(_))));
        let (WordsBefore::Count(counter) | WordsBefore::Written(counter)) = run.before;
        if !texts || frame.len() <= counter.index() {
            // The run's statements count their steps when they are entered.
            self.steps = self.steps.saturating_sub(1);
            return self.exec(&run.general, frame);
        }
        let start = self.out.buf.len();
        let mut printed = 0u64;
        for w in &run.locals {
            let Some(Value::Text(t)) = frame.get(w.index()) else { continue };
            if t.is_empty() {
                continue;
            }
            if printed > 0 {
                push_short(&mut self.out.buf, &run.sep);
            }
            t.append_to_bytes(&mut self.out.buf);
            printed += 1;
        }
        // The statements it stands for beyond itself, and those each word
        // printed counts (see `word`).
        let inner = match run.before {
            WordsBefore::Count(_) => 3 * printed + printed.saturating_sub(1),
            WordsBefore::Written(_) => 2 * printed + u64::from(printed > 0),
        };
        self.steps += (run.general.len() - 1) as u64 + inner;
        if self.steps > self.post.options.step_budget {
            return Err(Box::new(self.budget_error(None)));
        }
        frame[counter.index()] = match run.before {
            WordsBefore::Count(_) => Value::Num(printed as f64),
            WordsBefore::Written(_) => Value::Num(start as f64),
        };
        if printed == 0
            && let Some(m) = run.empty
        {
            // The `if`'s body: the truncation and the `break`.
            self.steps += 2;
            let at = self.mark(m, frame);
            self.out.buf.truncate(at);
            return Ok(Flow::Break);
        }
        Ok(Flow::Normal)
    }

    /// Writes one block inside a function: its expression pieces read the
    /// function's locals (VcPost `Out "<N>" & Code`, with `Code` a `Dim`).
    fn write_line_in(&mut self, pieces: &[Piece], frame: &mut Vec<Value>) -> Result<()> {
        for piece in pieces {
            match piece {
                Piece::Text(bytes) => push_short(&mut self.out.buf, bytes),
                Piece::Var(id) => self.write_var(*id),
                Piece::Expr(Expr::FormatVar { var, value, span }) => {
                    let v = self.eval(value, frame)?;
                    self.write_assigned(*var, v);
                    self.finite(*span)?;
                }
                Piece::Expr(e) => {
                    let v = self.eval(e, frame)?;
                    self.write_value_text(&v);
                }
                Piece::Joined(e) => match self.eval(e, frame)? {
                    Value::Null | Value::Undefined => {}
                    v => self.write_value_text(&v),
                },
            }
        }
        self.end_block();
        Ok(())
    }

    /// The values of a list of expressions, in order.
    /// The list is spare storage ([`Self::spare`]): a call gives it back.
    fn eval_list(&mut self, list: &[Expr], frame: &mut Vec<Value>) -> Result<Vec<Value>> {
        let mut values = self.spare();
        for e in list {
            match self.eval(e, frame) {
                Ok(v) => values.push(v),
                Err(err) => {
                    self.give_back(values);
                    return Err(err);
                }
            }
        }
        Ok(values)
    }

    /// `try { body } catch (k) { handler } finally { last }`. A `throw` or
    /// a type error of the post's code in `body` runs the handler with
    /// what was thrown (a type error as an object with `name` and
    /// `message`); budget, depth and text errors, and a value that is not
    /// a number given to a format, are not caught. `last` runs however
    /// the rest ended; a jump or error of its own wins.
    fn run_try(
        &mut self,
        body: &[Stmt],
        catch: Option<&(LocalId, Vec<Stmt>)>,
        last: &[Stmt],
        frame: &mut Vec<Value>,
    ) -> Result<Flow> {
        let depth = (self.depth, self.this_stack.len());
        let mut result = self.exec(body, frame);
        if let (Err(e), Some((k, handler))) = (&result, catch)
            && (e.code == objects::THROWN || e.code == objects::TYPE_ERROR)
        {
            let caught = match self.thrown.take() {
                Some(v) if e.code == objects::THROWN => v,
                _ => {
                    let (name, message) = crate::js::error_parts(&e.message).unwrap_or(("TypeError", &e.message));
                    objects::object(vec![
                        (crate::value::Text::new("name"), Value::text(name)),
                        (crate::value::Text::new("message"), Value::text(message)),
                    ])
                }
            };
            // Calls the error left unfinished are over.
            (self.depth, _) = depth;
            self.this_stack.truncate(depth.1);
            self.assign(Place::Local(*k), caught, frame);
            result = self.exec(handler, frame);
        }
        if last.is_empty() {
            return result;
        }
        let held = std::mem::take(&mut self.thrown);
        match self.exec(last, frame)? {
            Flow::Normal => {
                self.thrown = held;
                result
            }
            flow => Ok(flow),
        }
    }

    /// A budget error from a loop's body points at the innermost loop.
    fn in_loop(e: Box<Diagnostic>, span: Option<postc_ir::Span>) -> Box<Diagnostic> {
        match span {
            Some(s) if e.code == "RT002" && e.labels.is_empty() => Box::new(e.at(s, "this loop did not finish")),
            Some(s) if e.code == TEXT_BUDGET && e.labels.is_empty() => Box::new(e.at(s, "this loop builds the text")),
            _ => e,
        }
    }

    fn budget_error(&self, span: Option<postc_ir::Span>) -> Diagnostic {
        let d = Diagnostic::error(
            "RT002",
            format!(
                "the post ran more than {} steps for one event and was stopped (a loop that never ends?)",
                self.post.options.step_budget
            ),
        );
        match span {
            Some(s) => d.at(s, "this loop did not finish"),
            None => d,
        }
    }

    /// Writes text as blocks: each line of it (`\n` separated) that is not
    /// empty becomes a block with the post's line ending.
    pub(crate) fn write_blocks(&mut self, text: &str) {
        for line in text.split('\n') {
            let line = line.strip_suffix('\r').unwrap_or(line);
            if line.is_empty() {
                continue;
            }
            self.out.buf.extend_from_slice(line.as_bytes());
            self.end_block();
        }
    }

    fn assign(&mut self, place: Place, v: Value, frame: &mut Vec<Value>) {
        match place {
            Place::Local(i) => {
                let i = i.index();
                if frame.len() <= i {
                    frame.resize(i + 1, Value::Null);
                }
                frame[i] = v;
            }
            Place::Global(i) => self.set_global(i, v),
            Place::Var(id) => self.set_var(id, v),
        }
    }

    /// Sets a global's value.
    pub fn set_global(&mut self, i: GlobalId, v: Value) {
        let i = i.index();
        if self.globals.len() <= i {
            self.globals.resize(i + 1, Value::Null);
        }
        std::mem::replace(&mut self.globals[i], v).let_go();
    }

    /// Sets a variable's value, keeping the old one as its previous value.
    pub fn set_var(&mut self, id: VarId, v: Value) {
        let state = &mut self.vars[id.index()];
        state.previous = std::mem::replace(&mut state.value, v);
    }

    /// A variable's current value.
    pub fn var_value(&self, id: VarId) -> Value {
        match self.post.variables[id.index()].source {
            ValueSource::Quantity(q) => self.quantity(q),
            ValueSource::Assigned => self.vars[id.index()].value.clone(),
        }
    }

    fn quantity(&self, q: Quantity) -> Value {
        if q.is_text() {
            Value::text(self.machine.text(q))
        } else if q == Quantity::BlockNumber {
            Value::Num(self.block.next)
        } else {
            // A quantity with no value reads as null: it prints nothing.
            let n = self.machine.number(q);
            if n.is_nan() { Value::Null } else { Value::Num(n) }
        }
    }

    /// Evaluates a condition: whether the value of `e` is truthy, with
    /// comparisons and `&&`, `||`, `!` of them answered without making a
    /// value (the effects and their order are those of [`Self::eval`]).
    #[inline]
    pub(crate) fn test(&mut self, e: &Expr, frame: &mut Vec<Value>) -> Result<bool> {
        // The commonest conditions are answered where the caller is, with
        // no call: a constant, whether text was written since a mark,
        // whether a local's text is "" (a local that is not text, and
        // everything else, goes to `test_any`).
        match e {
            Expr::Bool(b) => Ok(*b),
            Expr::Written(k) => Ok(self.out.buf.len() > self.mark(*k, frame)),
            Expr::LocalEmpty { local, op } if let Some(Value::Text(t)) = frame.get(local.index()) => {
                Ok(t.is_empty() == matches!(op, BinaryOp::JsEq | BinaryOp::StrictEq))
            }
            _ => self.test_any(e, frame),
        }
    }

    /// [`Self::test`] of the conditions it does not answer itself (a
    /// constant or a mark's `Written` reach here only through `eval`).
    fn test_any(&mut self, e: &Expr, frame: &mut Vec<Value>) -> Result<bool> {
        match e {
            Expr::Binary(BinaryOp::And, a, b) => Ok(self.test(a, frame)? && self.test(b, frame)?),
            Expr::Binary(BinaryOp::Or, a, b) => Ok(self.test(a, frame)? || self.test(b, frame)?),
            Expr::Unary(UnaryOp::Not, a) => Ok(!self.test(a, frame)?),
            Expr::Local(i) => Ok(frame.get(i.index()).is_some_and(Value::truthy)),
            // A number the machine knows (`isFeedPerRev ? a : b`).
            Expr::Quantity(_) if let Some(n) = self.known_number(e) => Ok(n != 0.0),
            // A local that is not text (`test` answers text): compared as
            // JavaScript compares it with "" (`0 == ""`).
            Expr::LocalEmpty { local, op } => {
                let (v, empty) =
                    (frame.get(local.index()).unwrap_or(&Value::Null), Value::Text(self.empty_text.clone()));
                Ok(compare(*op, v, &empty).unwrap_or_else(|| binary(*op, v, &empty).truthy()))
            }
            Expr::LocalIsText { local, is } => Ok(matches!(frame.get(local.index()), Some(Value::Text(_))) == *is),
            Expr::Chain { all, operands } => {
                for operand in operands {
                    // `typeof w == "string"` of every word (the guard of a
                    // spliced `writeBlock`) is answered here, with no call.
                    let holds = match operand {
                        Expr::LocalIsText { local, is } => {
                            matches!(frame.get(local.index()), Some(Value::Text(_))) == *is
                        }
                        _ => self.test(operand, frame)?,
                    };
                    if holds != *all {
                        return Ok(!*all);
                    }
                }
                Ok(*all)
            }
            // `x + y + z == ""` of texts (a field post asking whether any
            // word printed): empty when every part is, with no text made.
            Expr::Binary(op @ (BinaryOp::JsEq | BinaryOp::JsNe | BinaryOp::StrictEq | BinaryOp::StrictNe), a, b)
                if matches!(&**b, Expr::Text(t) if t.is_empty())
                    && let Some(empty) = texts_empty(a, frame, &self.globals) =>
            {
                Ok(empty == matches!(op, BinaryOp::JsEq | BinaryOp::StrictEq))
            }
            // `typeof w === "string"` (the guard of the join fast path):
            // the type's name compared, no text made.
            Expr::Binary(op @ (BinaryOp::StrictEq | BinaryOp::StrictNe), a, b)
                if let Expr::Unary(UnaryOp::Typeof, operand) = &**a
                    && is_leaf(operand)
                    && let Expr::Text(name) = &**b =>
            {
                let mut tmp = Value::Null;
                let kind = ops::type_name(leaf(operand, frame, &self.globals, &mut tmp));
                tmp.let_go();
                let Value::Text(name) = name.value() else { return Ok(*op == BinaryOp::StrictNe) };
                Ok((name.as_bytes() == kind.as_bytes()) == (*op == BinaryOp::StrictEq))
            }
            Expr::Binary(op, a, b) if is_leaf(a) && is_leaf(b) => {
                let (mut ta, mut tb) = (Value::Null, Value::Null);
                let x = leaf(a, frame, &self.globals, &mut ta);
                let y = leaf(b, frame, &self.globals, &mut tb);
                let r = compare(*op, x, y).unwrap_or_else(|| binary(*op, x, y).truthy());
                // The places of numbers read in place own nothing.
                ta.let_go();
                tb.let_go();
                Ok(r)
            }
            // A comparison of anything else (`kept.length == 0`): no
            // value made for the answer.
            Expr::Binary(op, a, b) if is_comparison(*op) => self.test_compare(*op, a, b, frame),
            _ => Ok(self.eval(e, frame)?.truthy()),
        }
    }

    /// Evaluates an expression.
    #[inline]
    pub(crate) fn eval(&mut self, e: &Expr, frame: &mut Vec<Value>) -> Result<Value> {
        // The commonest values are read where the caller is, with no call:
        // a local, a global, a constant (`undefined` and the booleans are
        // arguments of most host calls). (`leaf` reads the same ones
        // borrowed; a value is made here, straight from its slot.)
        match e {
            Expr::Local(i) => Ok(frame.get(i.index()).cloned().unwrap_or_default()),
            Expr::Global(i) => Ok(self.globals.get(i.index()).cloned().unwrap_or_default()),
            Expr::Number(n) => Ok(Value::Num(*n)),
            Expr::Text(t) => Ok(t.value().clone()),
            Expr::Null => Ok(Value::Null),
            Expr::Undefined => Ok(Value::Undefined),
            Expr::Bool(b) => Ok(Value::Bool(*b)),
            _ => self.eval_any(e, frame),
        }
    }

    /// [`Self::eval`] of the expressions it does not read itself.
    fn eval_any(&mut self, e: &Expr, frame: &mut Vec<Value>) -> Result<Value> {
        Ok(match e {
            Expr::Null | Expr::Number(_) | Expr::Text(_) | Expr::Local(_) | Expr::Global(_) => {
                return self.eval(e, frame);
            }
            Expr::Bool(b) => Value::Bool(*b),
            Expr::Undefined => Value::Undefined,
            Expr::This => self.this(),
            Expr::Output(o) => Value::Output(*o),
            Expr::Arguments => self.arguments.last().cloned().unwrap_or_else(|| Value::array(Vec::new())),
            Expr::Host { name, args } => {
                let args = self.eval_list(args, frame)?;
                self.call_host(name, args)?
            }
            Expr::Array(items) => {
                let values = self.eval_list(items, frame)?;
                self.new_array(values)
            }
            Expr::Object(props) => {
                let mut values = Vec::with_capacity(props.len());
                for (k, v) in props {
                    values.push((crate::value::Text::new(k), self.eval(v, frame)?));
                }
                objects::object(values)
            }
            Expr::Regex { literal, span } => match &literal.0 {
                Ok(regex) => Value::Regex(std::rc::Rc::new(crate::regex::RegExp(regex.clone()))),
                Err(why) => {
                    let d = Diagnostic::error("JS108", format!("postc cannot run this regular expression: {why}"));
                    return Err(Box::new(match span {
                        Some(s) => d.at(*s, "this regular expression"),
                        None => d,
                    }));
                }
            },
            // `list.length`, `drill.depth`, `axes[k]` of a local or a
            // global: read where the object is, no reference taken.
            // A name the post never declares is a property of the global
            // object when the post set one (`this._ = ...`), as JavaScript
            // resolves it.
            Expr::Undeclared { name, span } => match self.global_property(name) {
                Some(v) => v,
                None => return Err(at(objects::reference_error(name), span.0, "not defined")),
            },
            // `this.name` of a method's own object (an output variable's
            // `this.prefix`): read where the object is, no reference taken;
            // anything else `this` may be goes the general way below.
            Expr::Member(o, k, _)
                if matches!(**o, Expr::This)
                    && let Expr::Text(name) = &**k
                    && let Some(this @ Value::Object(_)) = self.this_stack.last()
                    && let Some(v) = self.own_hinted(this, name) =>
            {
                v
            }
            Expr::Member(o, k, span) if is_plain_leaf(o) && is_plain_leaf(k) => {
                let read = {
                    let (mut to, mut tk) = (Value::Null, Value::Null);
                    let object = plain_leaf(o, frame, &self.globals, &mut to);
                    let key = plain_leaf(k, frame, &self.globals, &mut tk);
                    let read = if self.is_global_object(object) {
                        None
                    } else if let Expr::Text(name) = &**k
                        && let Some(v) = self.own_hinted(object, name)
                    {
                        // `o.name` of an object's own property, found
                        // through the site's inline cache.
                        Some(Ok(v))
                    } else {
                        Some(objects::member(object, key, &self.protos))
                    };
                    to.let_go();
                    tk.let_go();
                    read
                };
                match read {
                    Some(v) => v.map_err(|e| at(e, span.0, "this property"))?,
                    None => {
                        let k = self.eval(k, frame)?;
                        self.global_member(&k)?
                    }
                }
            }
            Expr::Member(object, key, span) => {
                let mut o = self.eval(object, frame)?;
                let k = self.eval(key, frame)?;
                let v = if let Expr::Text(name) = &**key
                    && let Some(v) = self.own_hinted(&o, name)
                {
                    v
                } else if self.is_global_object(&o) {
                    self.global_member(&k)?
                } else {
                    objects::member(&o, &k, &self.protos).map_err(|e| at(e, span.0, "this property"))?
                };
                // An array made only to be read (`list.filter(f).length`)
                // is kept to be made again.
                if let Value::Array(a) = &o
                    && std::rc::Rc::strong_count(a) == 1
                    && std::rc::Rc::weak_count(a) == 0
                {
                    self.keep_array(&mut o);
                }
                v
            }
            Expr::Invoke { object, method, args, span } => {
                let o = self.eval(object, frame)?;
                let args = self.eval_list(args, frame)?;
                let empty;
                let name = match method.value() {
                    Value::Text(t) => t,
                    _ => {
                        empty = crate::value::Text::new("");
                        &empty
                    }
                };
                self.invoke(o, name, method.hint(), args, *span)?
            }
            // A function that captures nothing is one value however often
            // it is made: a top-level function is one object in
            // JavaScript, with one `prototype`.
            Expr::Closure { function, captures } if captures.is_empty() => self.function_value(*function),
            Expr::Closure { function, captures } => {
                let captured = self.eval_list(captures, frame)?;
                objects::closure(*function, captured)
            }
            Expr::CallValue(callee, args) => {
                let f = self.eval(callee, frame)?;
                let args = self.eval_list(args, frame)?;
                self.call_value(&f, Value::Undefined, args)?
            }
            Expr::Written(k) => Value::Bool(self.out.buf.len() > self.mark(*k, frame)),
            Expr::LocalEmpty { .. } | Expr::LocalIsText { .. } => Value::Bool(self.test(e, frame)?),
            // The value of `a && b && c` is the first operand that decides,
            // or the last.
            Expr::Chain { all, operands } => {
                let Some((last, first)) = operands.split_last() else { return Ok(Value::Bool(*all)) };
                for operand in first {
                    let v = self.eval(operand, frame)?;
                    if v.truthy() != *all {
                        return Ok(v);
                    }
                }
                self.eval(last, frame)?
            }
            Expr::ParseFloatFrom { value, from } => Value::Num(self.read_back(value, *from, frame)?),
            Expr::Quantity(q) => self.quantity(*q),
            Expr::Var(id) => self.var_value(*id),
            Expr::Previous(id) => self.vars[id.index()].previous.clone(),
            Expr::FormatVar { var, value, span } => self.format_var(*var, value, *span, frame)?,
            Expr::Format { format, value, span } => {
                let n = self.eval(value, frame)?.num();
                // The engine's reused buffer, as a variable's word is made.
                let mut buf = std::mem::take(&mut self.scratch);
                buf.clear();
                self.writers[format.index()].write(n, &mut buf);
                let word = self.scratch_text(buf);
                self.finite(*span)?;
                word
            }
            // `+k`, `-x` of a local: the operand read in place.
            Expr::Unary(op, a) if is_plain_leaf(a) => {
                let mut tmp = Value::Null;
                let v = unary(*op, plain_leaf(a, frame, &self.globals, &mut tmp));
                tmp.let_go();
                v
            }
            Expr::Unary(op, a) => {
                let a = self.eval(a, frame)?;
                unary(*op, &a)
            }
            Expr::Binary(BinaryOp::And, a, b) => {
                let a = self.eval(a, frame)?;
                if a.truthy() { self.eval(b, frame)? } else { a }
            }
            Expr::Binary(BinaryOp::Or, a, b) => {
                let a = self.eval(a, frame)?;
                if a.truthy() { a } else { self.eval(b, frame)? }
            }
            // Locals, globals and numbers are read in place: no reference
            // count changes hands (the common `x != ""`, `n + 1`).
            Expr::Binary(op, a, b) if is_leaf(a) && is_leaf(b) => {
                let (v, objects) = {
                    let (mut ta, mut tb) = (Value::Null, Value::Null);
                    let x = leaf(a, frame, &self.globals, &mut ta);
                    let y = leaf(b, frame, &self.globals, &mut tb);
                    let objects = matches!(op, BinaryOp::Add | BinaryOp::Concat)
                        && (matches!(x, Value::Object(_)) || matches!(y, Value::Object(_)));
                    let v = if objects { Value::Null } else { self.operate(*op, x, y) };
                    ta.let_go();
                    tb.let_go();
                    (v, objects)
                };
                let v = if objects {
                    let x = self.eval(a, frame)?;
                    let x = self.primitive(x)?;
                    let y = self.eval(b, frame)?;
                    let y = self.primitive(y)?;
                    self.operate(*op, &x, &y)
                } else {
                    v
                };
                self.check_text(&v)?;
                v
            }
            // A chain of `+` (`text + " " + word`): built in one buffer, so
            // only the result is allocated.
            Expr::Binary(BinaryOp::Add | BinaryOp::Concat, l, _)
                if matches!(**l, Expr::Binary(BinaryOp::Add | BinaryOp::Concat, ..)) =>
            {
                let mut buf = std::mem::take(&mut self.chain_text);
                buf.clear();
                let v = match self.chain(e, frame, &mut buf) {
                    Ok(Some(v)) => v,
                    Ok(None) => Value::Text(Text::new(buf.as_str())),
                    Err(err) => {
                        self.chain_text = buf;
                        return Err(err);
                    }
                };
                self.chain_text = buf;
                self.check_text(&v)?;
                v
            }
            // One operand a leaf: read in place, after the other is
            // evaluated ([`Self::binary_one_leaf`]).
            Expr::Binary(op, a, b) if is_leaf(b) || is_frame_leaf(a) => self.binary_one_leaf(*op, a, b, frame)?,
            Expr::Binary(op, a, b) => {
                let a = self.eval(a, frame)?;
                let b = self.eval(b, frame)?;
                let v = self.operate_values(*op, a, b)?;
                self.check_text(&v)?;
                v
            }
            Expr::Choose(c, a, b) => match if self.test(c, frame)? { &**a } else { &**b } {
                // `getFeedrate`'s choice of two formats: formatted here.
                Expr::FormatVar { var, value, span } => self.format_var(*var, value, *span, frame)?,
                pick => self.eval(pick, frame)?,
            },
            Expr::Call(f, args) => {
                let mut values = self.spare();
                for a in args {
                    values.push(self.eval(a, frame)?);
                }
                // A plain call inside a method: the callee's `this` is the
                // global object, not the method's.
                let plain =
                    !self.this_stack.is_empty() && self.code.functions.get(f.index()).is_some_and(|r| r.uses_this);
                if plain {
                    self.this_stack.push(Value::Undefined);
                }
                let result = self.call(*f, values);
                if plain {
                    self.this_stack.pop();
                }
                result?
            }
            Expr::Builtin(b, args) => {
                let mut values = self.spare();
                for a in args {
                    values.push(self.eval(a, frame)?);
                }
                let v = match b {
                    // The built-ins that can fail, and those that read the
                    // run's prototypes.
                    Builtin::HasProperty => {
                        let arg = |i: usize| values.get(i).unwrap_or(&Value::Undefined);
                        let found = objects::has_property(arg(0), arg(1), &self.protos);
                        self.give_back(values);
                        return found;
                    }
                    Builtin::Keys | Builtin::OwnKeys => {
                        let (value, chain) = (values.first().unwrap_or(&Value::Undefined), *b == Builtin::Keys);
                        let keys = objects::keys(value, chain.then_some(&self.protos));
                        self.give_back(values);
                        return Ok(keys);
                    }
                    // `String(null)` in a JavaScript post is `"null"`; the
                    // number-to-text built-in is also VcPost's `Str`, whose
                    // empty value is nothing.
                    Builtin::Str if self.js && matches!(values.first(), Some(Value::Null)) => {
                        self.give_back(values);
                        return Ok(Value::text("null"));
                    }
                    Builtin::JsString if matches!(values.first(), Some(Value::Object(_))) => {
                        let v = values.first().cloned().unwrap_or(Value::Undefined);
                        self.give_back(values);
                        return self.text_of(v);
                    }
                    // A setting the post cannot take: the command line's
                    // error, at no place of the post's or the toolpath's.
                    Builtin::SettingError => {
                        let message = values.first().map(|v| v.to_text().to_string()).unwrap_or_default();
                        self.give_back(values);
                        return Err(Box::new(setting_error(message)));
                    }
                    // The primitives of a host written in JavaScript, built
                    // in the scratch text of `+` chains.
                    Builtin::Property => {
                        let v = host_text::property(&values, &self.protos);
                        self.give_back(values);
                        return v;
                    }
                    Builtin::FormatNumber | Builtin::Words | Builtin::FormatOutput => {
                        let mut buf = std::mem::take(&mut self.chain_text);
                        let v = match b {
                            Builtin::Words => host_text::words(&values, &self.protos, &mut buf),
                            Builtin::FormatOutput => host_text::format_output(&values, &self.output_hints, &mut buf),
                            _ => {
                                let arg = |i: usize| values.get(i).unwrap_or(&Value::Undefined);
                                host_text::format_number(arg(0), arg(1), &mut buf)
                            }
                        };
                        self.chain_text = buf;
                        self.give_back(values);
                        let v = v?;
                        self.check_text(&v)?;
                        return Ok(v);
                    }
                    Builtin::NewRegExp => {
                        let mut values = values.into_iter();
                        let (pattern, flags) =
                            (values.next().unwrap_or(Value::Undefined), values.next().unwrap_or(Value::Undefined));
                        let (source, own_flags) = match &pattern {
                            Value::Regex(r) => (r.0.source().to_string(), r.0.flags().to_string()),
                            Value::Undefined => ("(?:)".to_string(), String::new()),
                            other => (other.to_text().to_string(), String::new()),
                        };
                        let flags = match flags {
                            Value::Undefined => own_flags,
                            f => f.to_text().to_string(),
                        };
                        return match crate::regex::Regex::new(&source, &flags) {
                            Ok(re) => Ok(Value::Regex(std::rc::Rc::new(crate::regex::RegExp(std::rc::Rc::new(re))))),
                            Err(why) => Err(Box::new(Diagnostic::error(
                                "JS108",
                                format!("postc cannot run this regular expression: {why}"),
                            ))),
                        };
                    }
                    Builtin::Construct => {
                        let mut values = values.into_iter();
                        let callee = values.next().unwrap_or(Value::Undefined);
                        let proto = protos::proto_for_new(&callee)?;
                        let this = Value::object(crate::value::Object { proto, ..Default::default() });
                        let made = self.call_value(&callee, this.clone(), values.collect())?;
                        return Ok(match made {
                            Value::Object(_) | Value::Array(_) | Value::Func(_) => made,
                            _ => this,
                        });
                    }
                    Builtin::Prototype => {
                        let kind = match values.first() {
                            Some(Value::Text(name)) => crate::js::ProtoKind::of_constructor(name),
                            _ => None,
                        };
                        self.give_back(values);
                        return Ok(match kind {
                            Some(kind) => Value::Object(self.protos.get(kind).clone()),
                            None => Value::Undefined,
                        });
                    }
                    Builtin::CreateObject => {
                        let proto = protos::proto_of_new(values.first().unwrap_or(&Value::Undefined));
                        self.give_back(values);
                        return Ok(Value::object(crate::value::Object { proto: proto?, ..Default::default() }));
                    }
                    Builtin::InstanceOf => {
                        let arg = |i: usize| values.get(i).unwrap_or(&Value::Undefined);
                        let found = match arg(1) {
                            Value::Object(p) => Ok(Value::Bool(protos::chain_has(arg(0), p, &self.protos))),
                            other => Err(objects::type_error(format!(
                                "the right-hand side of 'instanceof' has no prototype object ({} instead)",
                                objects::describe(other)
                            ))),
                        };
                        self.give_back(values);
                        return found;
                    }
                    _ => builtin(*b, &values),
                };
                self.give_back(values);
                self.check_text(&v)?;
                v
            }
        })
    }

    /// The own property `name` of `value`, found through the literal's
    /// inline cache ([`crate::exec::Text`]); `None` for any other value,
    /// the global object, a built-in prototype, or an object without the
    /// property (the general read answers those).
    #[inline]
    fn own_hinted(&self, value: &Value, name: &crate::exec::Text) -> Option<Value> {
        let (Value::Object(object), Value::Text(key)) = (value, name.value()) else { return None };
        if self.is_global_object(value) {
            return None;
        }
        let object = object.borrow();
        match object.builtin {
            None => object.find_hinted(key.as_bytes(), name.hint()).map(|i| object.values[i].clone()),
            Some(_) => None,
        }
    }

    /// An empty list for arguments or a frame, from the spares: a call's
    /// argument list, frame and a method's snapshot reuse storage instead
    /// of allocating ([`Self::give_back`] returns it).
    #[inline]
    pub(crate) fn spare(&mut self) -> Vec<Value> {
        // A new one holds a frame's usual few values without growing.
        self.spare_frames.pop().unwrap_or_else(|| Vec::with_capacity(8))
    }

    /// Returns an argument list or frame to the spares, emptied. An array
    /// it held that nothing else refers to is kept to be made again
    /// ([`Self::new_array`]).
    #[inline]
    pub(crate) fn give_back(&mut self, mut frame: Vec<Value>) {
        // One pass from the end: each value let go where it is, with no
        // call to drop it (`Value::let_go`), or its array kept.
        while let Some(v) = frame.pop() {
            match v {
                Value::Array(a) if std::rc::Rc::strong_count(&a) == 1 && std::rc::Rc::weak_count(&a) == 0 => {
                    self.keep_array(&mut Value::Array(a));
                }
                other => other.let_go(),
            }
        }
        // Bounded by the deepest nesting of calls; more is never needed.
        if self.spare_frames.len() < 64 {
            self.spare_frames.push(frame);
        }
    }

    /// Keeps the array `v` holds, which nothing else refers to, emptied,
    /// for [`Self::new_array`]; `v` is left undefined.
    #[cold]
    fn keep_array(&mut self, v: &mut Value) {
        let Value::Array(a) = std::mem::take(v) else { return };
        if self.spare_arrays.len() < SPARE_ARRAYS && a.borrow().capacity() <= SPARE_ARRAY_ITEMS {
            // Its items may hold arrays of their own: those go as it
            // empties (nothing else refers to it, so nothing borrows it).
            {
                let mut items = a.borrow_mut();
                while let Some(v) = items.pop() {
                    v.let_go();
                }
            }
            self.spare_arrays.push(a);
        }
    }

    /// A new array holding `values`: one kept by [`Self::keep_array`]
    /// when there is one (its emptied list then kept as a spare for
    /// arguments and frames), so that an array made and
    /// dropped in every call allocates nothing once the run is warm. Its
    /// identity is new: nothing referred to the kept array.
    pub(crate) fn new_array(&mut self, values: Vec<Value>) -> Value {
        let a = match self.spare_arrays.pop() {
            Some(a) => {
                // The values' list becomes the array's; the kept array's
                // emptied list is kept as a spare in its place (no copy).
                let emptied = std::mem::replace(&mut *a.borrow_mut(), values);
                if self.spare_frames.len() < 64 {
                    self.spare_frames.push(emptied);
                }
                a
            }
            None => std::rc::Rc::new(std::cell::RefCell::new(values)),
        };
        Value::Array(a)
    }

    /// Text a post built: past [`MAX_TEXT_BYTES`] the run stops (RT031);
    /// long text costs steps by its length.
    #[inline]
    fn check_text(&mut self, v: &Value) -> Result<()> {
        let Value::Text(t) = v else { return Ok(()) };
        if t.len() > TEXT_STEP_BYTES {
            self.steps += (t.len() / TEXT_STEP_BYTES) as u64;
            if t.len() > MAX_TEXT_BYTES {
                return Err(Box::new(text_budget_error(t.len())));
            }
        }
        Ok(())
    }

    /// Formats a value through a variable (prefix, format, modality) and
    /// returns the text; an on-change variable returns "" when the text is
    /// the one it returned last.
    pub fn format_through_var(&mut self, id: VarId, v: Value) -> Value {
        let mut buf = std::mem::take(&mut self.scratch);
        buf.clear();
        self.format_into(id, v, &mut buf);
        self.scratch_text(buf)
    }

    /// [`Self::format_through_var`], the text appended to `buf`.
    fn format_into(&mut self, id: VarId, v: Value, buf: &mut Vec<u8>) {
        let post = self.post;
        let var = &post.variables[id.index()];
        let (state, prefix) = (&mut self.vars[id.index()], &self.prefixes[id.index()]);
        match &v {
            Value::Text(s) => put_text(is_modal(var), state, prefix, s.as_bytes(), &post.options.substitutions, buf),
            other => put_number(is_modal(var), &self.writers[var.format.index()], state, prefix, other.num(), buf),
        }
        self.set_var(id, v);
    }

    /// [`Self::format_var`] as a call of its own: exec's local store calls
    /// it, and stays small.
    #[inline(never)]
    fn format_var_call(
        &mut self,
        var: VarId,
        value: &Expr,
        span: Option<Span>,
        frame: &mut Vec<Value>,
    ) -> Result<Value> {
        self.format_var(var, value, span, frame)
    }

    /// The text of a value formatted through a variable
    /// ([`Expr::FormatVar`]).
    #[inline(always)]
    fn format_var(&mut self, var: VarId, value: &Expr, span: Option<Span>, frame: &mut Vec<Value>) -> Result<Value> {
        // A number the machine knows needs no value made first, nor does
        // one read back from a word (a field post's feed).
        let word = if let Some(n) = self.known_number(value) {
            self.format_number_through_var(var, n)
        } else if let Expr::ParseFloatFrom { value: text, from } = value {
            let n = self.read_back(text, *from, frame)?;
            self.format_number_through_var(var, n)
        } else {
            let v = self.eval(value, frame)?;
            self.format_through_var(var, v)
        };
        self.finite(span)?;
        Ok(word)
    }

    /// The number `parseFloat(text.substring(from))` reads from the text of
    /// `text` ([`Expr::ParseFloatFrom`]), with no value made: most often a
    /// local's word, read in place, or a word formatted into a reused buffer.
    fn read_back(&mut self, text: &Expr, from: usize, frame: &mut Vec<Value>) -> Result<f64> {
        if let Expr::Local(i) = text
            && let Some(Value::Text(t)) = frame.get(i.index())
        {
            return Ok(parse_float_from(t.as_bytes(), from));
        }
        let mut chosen = text;
        while let Expr::Choose(c, a, b) = chosen {
            chosen = if self.test(c, frame)? { a } else { b };
        }
        // A word of a number formatted through a variable (a field post's
        // feed): read from the word formatted as a value; a word kept by a
        // variable that always prints is read once.
        if let Expr::FormatVar { var, value, span } = chosen
            && let Some(n) = self.known_number(value)
        {
            let word = self.format_number_through_var(*var, n);
            self.finite(*span)?;
            if let Some(kept) = self.vars[var.index()].kept.as_mut().filter(|k| k.bits == n.to_bits()) {
                return Ok(match kept.read {
                    Some((at, read)) if at == from => read,
                    _ => {
                        let read = parse_float_from(kept.word.as_bytes(), from);
                        kept.read = Some((from, read));
                        read
                    }
                });
            }
            return Ok(parse_float_from(word.to_text().as_bytes(), from));
        }
        let mut buf = std::mem::take(&mut self.float_text);
        buf.clear();
        let written = self.text_into(chosen, frame, &mut buf);
        let n = parse_float_from(&buf, from);
        self.float_text = buf;
        written.map(|()| n)
    }

    /// The number an expression is when it is a constant or names a
    /// numeric quantity the machine has a value for, alone or under a
    /// unary `+` (a handler's `vx` coerced to a number): no value made to
    /// read it.
    #[inline(always)]
    fn known_number(&self, e: &Expr) -> Option<f64> {
        let q = match e {
            Expr::Number(n) => return Some(*n),
            Expr::Unary(UnaryOp::Plus, q) if let Expr::Quantity(q) = &**q => *q,
            Expr::Quantity(q) => *q,
            _ => return None,
        };
        if q.is_text() || q == Quantity::BlockNumber {
            return None;
        }
        Some(self.machine.number(q)).filter(|n| !n.is_nan())
    }

    /// Appends the text of an expression to `buf`: a formatted variable is
    /// formatted there, a choice chooses; any other value as its text.
    fn text_into(&mut self, e: &Expr, frame: &mut Vec<Value>, buf: &mut Vec<u8>) -> Result<()> {
        match e {
            Expr::FormatVar { var, value, span } => {
                if let Some(n) = self.known_number(value) {
                    self.format_number_into(*var, n, buf);
                } else {
                    let v = self.eval(value, frame)?;
                    self.format_into(*var, v, buf);
                }
                self.finite(*span)?;
            }
            Expr::Choose(c, a, b) => {
                let pick = if self.test(c, frame)? { a } else { b };
                self.text_into(pick, frame, buf)?;
            }
            other => buf.extend_from_slice(self.eval(other, frame)?.to_text().as_bytes()),
        }
        Ok(())
    }

    /// The text formatted into `buf` (the engine's scratch buffer, given
    /// back): the shared empty text, or the bytes as a value.
    #[inline]
    pub(super) fn scratch_text(&mut self, mut buf: Vec<u8>) -> Value {
        let len = buf.len();
        let text = if len == 0 {
            self.empty_text.clone()
        } else if len <= INLINE_TEXT {
            // A word: zeros after it, so that it is taken as a whole array
            // (fixed-size copies, no `memcpy` call).
            buf.extend_from_slice(&[0; INLINE_TEXT]);
            match buf.first_chunk::<INLINE_TEXT>() {
                Some(padded) => Text::from_padded(padded, len),
                None => Text::from_bytes(&buf[..len]),
            }
        } else {
            Text::from_bytes(&buf)
        };
        self.scratch = buf;
        Value::Text(text)
    }

    /// [`Self::format_through_var`] of a number.
    #[inline]
    fn format_number_through_var(&mut self, id: VarId, n: f64) -> Value {
        // The word made straight into its value, on the fast path.
        let post = self.post;
        let var = &post.variables[id.index()];
        let (state, prefix) = (&mut self.vars[id.index()], &self.prefixes[id.index()]);
        let modal = is_modal(var);
        // A variable that always prints makes the same word of the same
        // number: the one kept is taken.
        if !modal && let Some(kept) = state.reprint(n) {
            return Value::Text(kept.word.clone());
        }
        if let Some(word) = number_word(modal, &self.writers[var.format.index()], state, prefix, n, &self.empty_text) {
            if !modal && let Some(rounded) = state.key {
                state.kept = Some(KeptWord { bits: n.to_bits(), rounded, word: word.clone(), read: None });
            }
            state.previous = std::mem::replace(&mut state.value, Value::Num(n));
            return Value::Text(word);
        }
        let mut buf = std::mem::take(&mut self.scratch);
        buf.clear();
        self.format_number_into(id, n, &mut buf);
        self.scratch_text(buf)
    }

    /// [`Self::format_into`] of a number.
    #[inline]
    fn format_number_into(&mut self, id: VarId, n: f64, buf: &mut Vec<u8>) {
        let post = self.post;
        let var = &post.variables[id.index()];
        let (state, prefix) = (&mut self.vars[id.index()], &self.prefixes[id.index()]);
        put_number(is_modal(var), &self.writers[var.format.index()], state, prefix, n, buf);
        state.previous = std::mem::replace(&mut state.value, Value::Num(n));
    }

    /// Calls a post function with arguments.
    pub fn call(&mut self, f: FunctionId, args: Vec<Value>) -> Result<Value> {
        let (post, code) = (self.post, self.code);
        let Some(runnable) = code.functions.get(f.index()) else { return Ok(Value::Null) };
        // A specialised copy reports as the function it was made from.
        let f = runnable.origin;
        let Some(function) = post.functions.get(f.index()) else { return Ok(Value::Null) };
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            self.depth -= 1;
            let d =
                Diagnostic::error("RT004", format!("calls nest deeper than {MAX_DEPTH} levels (endless recursion?)"));
            return Err(Box::new(match function.span {
                Some(s) => d.at(s, "in this function"),
                None => d,
            }));
        }
        if let Some(t) = self.trace.as_deref_mut() {
            t.enter(f, function.span);
        }
        if let Some(p) = self.profile.as_deref_mut() {
            p.enter(crate::profile::Frame::Function(f));
        }
        let result = match &runnable.body {
            Body::Native(body) => {
                let mut frame = args;
                if runnable.uses_arguments {
                    let mut list = self.spare();
                    list.extend_from_slice(&frame);
                    let arguments = self.new_array(list);
                    self.arguments.push(arguments);
                }
                fill_frame(runnable, &mut frame);
                // Calls nest up to MAX_DEPTH whatever the thread's stack
                // (a debug build's frames are large, a host's thread may be
                // small): the stack grows on the heap when it runs low.
                // A function that only returns an expression that calls
                // nothing (`return word !== ""`, a callback) is that
                // expression: its one step counted as `exec` counts it,
                // with no statement loop and no stack to grow.
                let ran = match &runnable.returns {
                    Some(e) => {
                        self.steps += 1;
                        if self.steps > self.post.options.step_budget {
                            Err(Box::new(self.budget_error(None)))
                        } else {
                            self.eval(e, &mut frame).map(Flow::Return)
                        }
                    }
                    None => stacker::maybe_grow(STACK_RED_ZONE, STACK_GROWTH, || self.exec(body, &mut frame)),
                };
                let result = match ran {
                    Ok(Flow::Return(v)) => Ok(v),
                    Ok(_) if runnable.starts_undefined => Ok(Value::Undefined),
                    Ok(_) => Ok(Value::Null),
                    Err(e) => Err(placed(post, function, e)),
                };
                self.give_back(frame);
                if runnable.uses_arguments
                    && let Some(mut arguments) = self.arguments.pop()
                    && matches!(&arguments, Value::Array(a) if std::rc::Rc::strong_count(a) == 1 && std::rc::Rc::weak_count(a) == 0)
                {
                    self.keep_array(&mut arguments);
                }
                result
            }
            Body::Script(id) => self.call_script(*id, &function.name, args),
        };
        if let Some(p) = self.profile.as_deref_mut() {
            p.exit();
        }
        if self.trace.is_some() {
            // Blocks a script wrote belong to the function that ran it.
            self.trace_after(None);
            if let Some(t) = self.trace.as_deref_mut() {
                t.leave();
            }
        }
        self.depth -= 1;
        match (result, function.span) {
            (Err(e), Some(s))
                if (e.code == TEXT_BUDGET || e.code == crate::regex::UNSUPPORTED) && e.labels.is_empty() =>
            {
                Err(Box::new(e.at(s, "in this function")))
            }
            (result, _) => result,
        }
    }

    /// The function of a callback an array method may run as
    /// [`Self::run_callback_in`] (`list.filter(isWord)`): a post function
    /// that captures nothing, takes no `arguments` and only returns a
    /// plain expression ([`crate::exec::Function::returns`]), while calls
    /// are neither traced nor profiled; `None` otherwise (then the method
    /// calls it as any function value).
    pub(crate) fn callback_function(&self, f: &Value) -> Option<FunctionId> {
        let Value::Func(closure) = f else { return None };
        let crate::value::Callee::Post(id) = closure.callee else { return None };
        let runnable = self.code.functions.get(id.index())?;
        let plain = closure.captures.is_empty()
            && runnable.returns.is_some()
            && !runnable.uses_arguments
            && self.trace.is_none()
            && self.profile.is_none();
        plain.then_some(id)
    }

    /// Runs a function [`Self::callback_function`] gave for one item of an
    /// array method's walk (`list.filter(f)`), as [`Self::call`] would (the
    /// same step, depth limit and placed errors), with no call made: its
    /// expression evaluated in `frame`, emptied and filled again for each
    /// item, and only the arguments its parameters read are made (an item
    /// and its index; the array only for a third parameter).
    pub(crate) fn run_callback_in(
        &mut self,
        id: FunctionId,
        args: [&Value; 2],
        items: &std::rc::Rc<std::cell::RefCell<Vec<Value>>>,
        frame: &mut Vec<Value>,
    ) -> Result<Value> {
        let (post, code) = (self.post, self.code);
        let runnable = &code.functions[id.index()];
        let (Some(e), Some(function)) = (&runnable.returns, post.functions.get(runnable.origin.index())) else {
            return Ok(Value::Null);
        };
        if self.depth + 1 > MAX_DEPTH {
            let mut values = self.spare();
            values.extend([args[0].clone(), args[1].clone(), Value::Array(items.clone())]);
            return self.call(id, values);
        }
        // Arguments past the parameters are dropped by `fill_frame` when
        // the function starts its slots undefined: those are not made.
        let wanted = if runnable.starts_undefined { runnable.params } else { 3 };
        // The last item's values, let go as a spent frame's are.
        while let Some(v) = frame.pop() {
            v.let_go();
        }
        // Pushed one by one: most callbacks read the item alone.
        if wanted > 0 {
            frame.push(args[0].clone());
        }
        if wanted > 1 {
            frame.push(args[1].clone());
        }
        if wanted > 2 {
            frame.push(Value::Array(items.clone()));
        }
        fill_frame(runnable, frame);
        self.steps += 1;
        let result = if self.steps > self.post.options.step_budget {
            Err(Box::new(self.budget_error(None)))
        } else {
            self.eval(e, frame)
        };
        result.map_err(|e| placed(post, function, e))
    }

    /// A mark stored by [`Stmt::Mark`], within the output buffer.
    fn mark(&self, k: LocalId, frame: &[Value]) -> usize {
        let at = frame.get(k.index()).map_or(0.0, Value::num);
        (at.max(0.0) as usize).min(self.out.buf.len())
    }

    /// Writes pieces into the output with the frame's locals in reach.
    fn emit_pieces(&mut self, pieces: &[Piece], frame: &mut Vec<Value>) -> Result<()> {
        for piece in pieces {
            match piece {
                Piece::Text(bytes) => push_short(&mut self.out.buf, bytes),
                Piece::Var(id) => self.write_var(*id),
                Piece::Expr(Expr::FormatVar { var, value, span }) => {
                    let n = match &**value {
                        Expr::Quantity(q) if !q.is_text() && *q != Quantity::BlockNumber => {
                            match self.machine.number(*q) {
                                // No value: nothing prints and the variable holds null.
                                n if n.is_nan() => {
                                    self.set_var(*var, Value::Null);
                                    continue;
                                }
                                n => n,
                            }
                        }
                        Expr::Number(n) => *n,
                        // A feed read back from its word (a field post's
                        // `fOutput.format(parseFloat(...))`): no value made.
                        Expr::ParseFloatFrom { value: text, from } => self.read_back(text, *from, frame)?,
                        // `+x` of a number the runtime knows (CIMCO's
                        // arguments): the number, NaN when there is none.
                        other => match plus_quantity(other) {
                            Some(q) => self.machine.number(q),
                            None => match self.eval(other, frame)? {
                                Value::Num(n) => n,
                                v => {
                                    self.write_assigned(*var, v);
                                    self.finite(*span)?;
                                    continue;
                                }
                            },
                        },
                    };
                    self.write_number_var(*var, n);
                    self.finite(*span)?;
                }
                Piece::Expr(Expr::Local(i)) if matches!(frame.get(i.index()), Some(Value::Text(_))) => {
                    if let Some(Value::Text(t)) = frame.get(i.index()) {
                        t.append_to_bytes(&mut self.out.buf);
                    }
                }
                // `text.substring(k)` of ASCII text in a local (a field
                // post's `writeBlock` dropping its leading blank): the
                // bytes from `k` on, with no text made.
                Piece::Expr(Expr::Builtin(Builtin::Substring, args))
                    if let [Expr::Local(i), Expr::Number(k)] = args.as_slice()
                        && *k >= 0.0
                        && let Some(Value::Text(t)) = frame.get(i.index())
                        && t.is_ascii() =>
                {
                    let from = (k.trunc() as usize).min(t.len());
                    self.out.buf.extend_from_slice(&t.as_bytes()[from..]);
                }
                Piece::Expr(e) => match self.eval(e, frame)? {
                    Value::Num(n) if n == n.trunc() && n.abs() < 1e15 => {
                        crate::number::push_integer(&mut self.out.buf, n as i64)
                    }
                    v => self.write_value_text(&v),
                },
                Piece::Joined(e) => match self.eval(e, frame)? {
                    Value::Null | Value::Undefined => {}
                    Value::Num(n) if n == n.trunc() && n.abs() < 1e15 => {
                        crate::number::push_integer(&mut self.out.buf, n as i64)
                    }
                    v => self.write_value_text(&v),
                },
            }
        }
        Ok(())
    }

    /// Prints a number through an assigned variable and keeps it as its value.
    fn write_number_var(&mut self, id: VarId, n: f64) {
        let post = self.post;
        let var = &post.variables[id.index()];
        let (state, prefix) = (&mut self.vars[id.index()], &self.prefixes[id.index()]);
        put_number(is_modal(var), &self.writers[var.format.index()], state, prefix, n, &mut self.out.buf);
        state.previous = std::mem::replace(&mut state.value, Value::Num(n));
    }
}

impl Engine<'_> {
    /// JavaScript's ToPrimitive for `+`: an object's `valueOf` (its own or
    /// its prototypes'), when it gives a value that is not an object, else
    /// its `toString`'s; other values (and objects without them) are
    /// themselves.
    #[inline]
    fn primitive(&mut self, v: Value) -> Result<Value> {
        // Only an object asks its methods: any other value is itself,
        // decided where the operator is.
        if !matches!(v, Value::Object(_)) {
            return Ok(v);
        }
        self.primitive_by(v, [&b"valueOf"[..], &b"toString"[..]])
    }

    /// JavaScript's ToString (`String(v)`, a template literal's
    /// substitution, an array's `join`): an object's `toString` is asked
    /// first, then its `valueOf` (ToPrimitive with the hint string).
    pub(crate) fn text_of(&mut self, v: Value) -> Result<Value> {
        let p = self.primitive_by(v, [&b"toString"[..], &b"valueOf"[..]])?;
        Ok(Value::Text(p.to_text()))
    }

    /// ToPrimitive asking an object's methods in the order given, its own
    /// or its prototypes' (`Object.prototype`'s built-in ones give the
    /// object, and then its text `[object Object]`, as the object is).
    fn primitive_by(&mut self, v: Value, order: [&[u8]; 2]) -> Result<Value> {
        let Value::Object(o) = &v else { return Ok(v) };
        for name in order {
            let f = match protos::find_in(&o.borrow(), name, &self.protos, false) {
                Some(protos::Found::Value(f)) => Some(f),
                _ => None,
            };
            if let Some(f @ Value::Func(_)) = f {
                let r = self.call_value(&f, v.clone(), Vec::new())?;
                if !matches!(r, Value::Object(_) | Value::Array(_) | Value::Func(_)) {
                    return Ok(r);
                }
            }
        }
        Ok(v)
    }

    /// A binary operator of two values: JavaScript's `+` in a JavaScript
    /// post ([`ops::add_js`]), else [`binary`].
    #[inline]
    fn operate(&self, op: BinaryOp, a: &Value, b: &Value) -> Value {
        if self.js && op == BinaryOp::Add { ops::add_js(a, b) } else { binary(op, a, b) }
    }

    /// A binary operator of two values evaluated in their order: `+` of
    /// an object first asks its methods for a primitive ([`Self::primitive`],
    /// left then right); any other operands are used as they are.
    #[inline]
    fn operate_values(&mut self, op: BinaryOp, a: Value, b: Value) -> Result<Value> {
        if matches!(op, BinaryOp::Add | BinaryOp::Concat)
            && (matches!(a, Value::Object(_)) || matches!(b, Value::Object(_)))
        {
            let a = self.primitive(a)?;
            let b = self.primitive(b)?;
            return Ok(self.operate(op, &a, &b));
        }
        Ok(self.operate(op, &a, &b))
    }

    /// `a op b` where one operand is a leaf that is read in place instead
    /// of copied: a right-hand leaf ([`is_leaf`]) after the left operand is
    /// evaluated, as it is read then anyway; a left-hand one only when it
    /// lives in the frame ([`is_frame_leaf`]), which no expression
    /// assigns (a local closures share is held in an array), so that it
    /// reads the same after the right operand is evaluated. `+` of an
    /// object takes the values themselves ([`Self::operate_values`]).
    #[inline(never)]
    fn binary_one_leaf(&mut self, op: BinaryOp, a: &Expr, b: &Expr, frame: &mut Vec<Value>) -> Result<Value> {
        let (left, other) = if is_leaf(b) { (true, self.eval(a, frame)?) } else { (false, self.eval(b, frame)?) };
        let mut tmp = Value::Null;
        let leaf_value = leaf(if left { b } else { a }, frame, &self.globals, &mut tmp);
        let (x, y) = if left { (&other, leaf_value) } else { (leaf_value, &other) };
        let v = if matches!(op, BinaryOp::Add | BinaryOp::Concat)
            && (matches!(x, Value::Object(_)) || matches!(y, Value::Object(_)))
        {
            let (x, y) = (x.clone(), y.clone());
            other.let_go();
            self.operate_values(op, x, y)?
        } else {
            let v = self.operate(op, x, y);
            other.let_go();
            v
        };
        tmp.let_go();
        self.check_text(&v)?;
        Ok(v)
    }

    /// `a op b` of a comparison as a condition: the operands evaluated in
    /// their order (a leaf read in place as [`Self::binary_one_leaf`]
    /// reads it), compared with no value made for the answer.
    #[inline(never)]
    fn test_compare(&mut self, op: BinaryOp, a: &Expr, b: &Expr, frame: &mut Vec<Value>) -> Result<bool> {
        let decide = |x: &Value, y: &Value| compare(op, x, y).unwrap_or_else(|| binary(op, x, y).truthy());
        if is_leaf(b) || is_frame_leaf(a) {
            let (left, other) = if is_leaf(b) { (true, self.eval(a, frame)?) } else { (false, self.eval(b, frame)?) };
            let mut tmp = Value::Null;
            let leaf_value = leaf(if left { b } else { a }, frame, &self.globals, &mut tmp);
            let r = if left { decide(&other, leaf_value) } else { decide(leaf_value, &other) };
            other.let_go();
            tmp.let_go();
            return Ok(r);
        }
        let x = self.eval(a, frame)?;
        let y = self.eval(b, frame)?;
        let r = decide(&x, &y);
        x.let_go();
        y.let_go();
        Ok(r)
    }

    /// Evaluates a left-nested chain of `+`/`&` as [`binary`] would, one
    /// operator at a time from the left: `None` when the value so far is
    /// text, which is then in `buf`; the value itself while it is not
    /// (numbers add until a text joins them).
    fn chain(&mut self, e: &Expr, frame: &mut Vec<Value>, buf: &mut String) -> Result<Option<Value>> {
        let Expr::Binary(op @ (BinaryOp::Add | BinaryOp::Concat), l, r) = e else {
            return Ok(Some(self.eval(e, frame)?));
        };
        let left = match self.chain(l, frame, buf)? {
            Some(v) => Some(self.primitive(v)?),
            None => None,
        };
        let right = self.eval(r, frame)?;
        let right = self.primitive(right)?;
        // JavaScript's `+` writes null as `null` ([`ops::add_js`]).
        let js = self.js && *op == BinaryOp::Add;
        let append = |v: &Value, buf: &mut String| if js { v.append_js(buf) } else { v.append_to(buf) };
        Ok(match left {
            None => {
                append(&right, buf);
                None
            }
            Some(left) => {
                let text = if js {
                    ops::joins_as_text(&left) || ops::joins_as_text(&right)
                } else {
                    *op == BinaryOp::Concat || matches!(left, Value::Text(_)) || matches!(right, Value::Text(_))
                };
                if text {
                    append(&left, buf);
                    append(&right, buf);
                    None
                } else {
                    Some(binary(*op, &left, &right))
                }
            }
        })
    }
}

/// `o[k] = v` of a value that is not the global object: `o.name = v` of
/// an object finds the property through the site's inline cache
/// ([`crate::exec::Text`]); any other store is [`objects::set_member`]'s.
fn store_member(o: &Value, key: &Expr, k: &Value, v: Value) -> Result<()> {
    match (key, o, k) {
        (Expr::Text(name), Value::Object(target), Value::Text(k)) => {
            target.borrow_mut().set_hinted(k, v, name.hint());
            Ok(())
        }
        _ => objects::set_member(o, k, v),
    }
}

/// An error at the post text that made it (`span`), when it has no place
/// of its own yet: the innermost place is the one to show.
#[cold]
fn at(e: Box<Diagnostic>, span: Option<Span>, label: &str) -> Box<Diagnostic> {
    match span {
        Some(span) if e.primary_span().is_none() => Box::new(e.at(span, label)),
        _ => e,
    }
}

/// Whether an error is placed in the host's API only (`host`, the code
/// compiled with the post) and nowhere in the post's own text.
fn in_host_only(e: &Diagnostic, host: postc_ir::FileId) -> bool {
    e.primary_span().is_some_and(|p| p.file == host) && e.labels.iter().all(|l| l.span.file == host)
}

/// The first bytes of a function's text (`function`), where a label names
/// the function an error is in.
fn header(f: Span) -> Span {
    Span::new(f.file, f.start, f.start.saturating_add(8).min(f.end))
}

/// An error a post function stopped with, placed: one with no place of
/// its own in the function; one in the host's API (code compiled with
/// the post) also at the first function of the post it passes through.
fn placed(post: &postc_ir::Post, function: &postc_ir::Function, e: Box<Diagnostic>) -> Box<Diagnostic> {
    if is_setting_error(&e) {
        return e;
    }
    if e.primary_span().is_none()
        && let Some(span) = function.span
    {
        return Box::new(e.at(span, format!("in function `{}`", function.name)));
    }
    // An error placed in this function's own text: the function it is in,
    // once, for the reader who has the post open.
    if let Some(f) = function.span
        && e.labels.len() == 1
        && e.primary_span().is_some_and(|p| p.file == f.file && f.start <= p.start && p.end <= f.end)
    {
        return Box::new(e.also(header(f), format!("in function `{}`", function.name)));
    }
    if let Some(f) = function.span
        && post.info.host_file.is_some_and(|h| f.file != h && in_host_only(&e, h))
    {
        return Box::new(e.also(header(f), format!("in the post's function `{}`", function.name)));
    }
    e
}

/// The quantity of `+q`, a number the runtime knows read as a JavaScript
/// number.
fn plus_quantity(e: &Expr) -> Option<Quantity> {
    match e {
        Expr::Unary(UnaryOp::Plus, inner) => match **inner {
            Expr::Quantity(q) if !q.is_text() && q != Quantity::BlockNumber => Some(q),
            _ => None,
        },
        _ => None,
    }
}

/// Whether a left-nested chain of `+` over leaves that are all text is
/// empty; `None` when a part is not a leaf or not text (then `+` may add
/// numbers, and the chain is evaluated as it is).
#[doc(hidden)]
pub fn texts_empty(e: &Expr, frame: &[Value], globals: &[Value]) -> Option<bool> {
    match e {
        Expr::Binary(BinaryOp::Add, a, b) => Some(texts_empty(a, frame, globals)? && texts_empty(b, frame, globals)?),
        Expr::Text(t) => Some(t.is_empty()),
        Expr::Local(i) => match frame.get(i.index())? {
            Value::Text(t) => Some(t.is_empty()),
            _ => None,
        },
        Expr::Global(i) => match globals.get(i.index())? {
            Value::Text(t) => Some(t.is_empty()),
            _ => None,
        },
        _ => None,
    }
}

/// Appends constant bytes that are most often one or two (a word's
/// separator, a line's end, `N` before a block number) with no `memcpy`
/// call.
#[inline(always)]
fn push_short(out: &mut Vec<u8>, bytes: &[u8]) {
    match *bytes {
        [b] => out.push(b),
        [a, b] => out.extend_from_slice(&[a, b]),
        _ => out.extend_from_slice(bytes),
    }
}

/// Moves the text written from `from` on back to `to`, before the text
/// between them (`to < from <= buf.len()`): a short text (a separator, a
/// block number) through a window on the stack, a longer one rotated.
#[inline]
#[doc(hidden)]
pub fn move_back(buf: &mut [u8], to: usize, from: usize) {
    const WINDOW: usize = 16;
    let moved = buf.len() - from;
    if moved == 1 {
        let b = buf[from];
        buf.copy_within(to..from, to + 1);
        buf[to] = b;
    } else if moved <= WINDOW {
        let mut window = [0u8; WINDOW];
        window[..moved].copy_from_slice(&buf[from..]);
        buf.copy_within(to..from, to + moved);
        buf[to..to + moved].copy_from_slice(&window[..moved]);
    } else {
        buf[to..].rotate_right(moved);
    }
}

/// `parseFloat(text.substring(from))` of the bytes of a text (replacing
/// what is not UTF-8, as a text value does).
fn parse_float_from(bytes: &[u8], from: usize) -> f64 {
    // The usual text, a word the post formatted (`F1000.` from 1): its
    // characters before `from` are bytes, and the rest one short decimal.
    if let Some((head, rest)) = bytes.split_at_checked(from)
        && head.is_ascii()
        && let Some(n) = crate::js::parse_short_decimal(rest)
    {
        return n;
    }
    let text = String::from_utf8_lossy(bytes);
    let rest = if text.is_ascii() {
        &text[from.min(text.len())..]
    } else {
        text.char_indices().nth(from).map_or("", |(i, _)| &text[i..])
    };
    crate::js::parse_float(rest)
}

/// A local, a global, a number or a text, or a unary operator of one
/// (`+k`, `-x`, `!done`): read in place by [`leaf`]. A unary operator
/// runs no post code ([`unary`] is pure), so reading one in place does
/// what evaluating it does.
fn is_leaf(e: &Expr) -> bool {
    match e {
        Expr::Unary(_, a) => is_plain_leaf(a),
        e => is_plain_leaf(e),
    }
}

/// A local, a global, a number or a text.
#[inline(always)]
fn is_plain_leaf(e: &Expr) -> bool {
    matches!(e, Expr::Local(_) | Expr::Global(_) | Expr::Number(_) | Expr::Text(_))
}

/// A local, a number or a text: a leaf no expression's evaluation can
/// change (an expression assigns no local of its frame; a local that
/// closures share is an array the local holds), unlike a global, which a
/// call may assign.
#[inline(always)]
fn is_frame_leaf(e: &Expr) -> bool {
    matches!(e, Expr::Local(_) | Expr::Number(_) | Expr::Text(_))
}

/// An operator whose value is a boolean that [`compare`] or [`binary`]
/// gives, with no post code run.
#[inline(always)]
fn is_comparison(op: BinaryOp) -> bool {
    use BinaryOp::*;
    matches!(op, Eq | Ne | Lt | Le | Gt | Ge | JsEq | JsNe | JsLt | JsLe | JsGt | JsGe | StrictEq | StrictNe)
}

/// The value of a leaf expression, borrowed where it lives (`tmp` holds a
/// number, or null for a slot that does not exist).
#[inline(always)]
fn leaf<'v>(e: &'v Expr, frame: &'v [Value], globals: &'v [Value], tmp: &'v mut Value) -> &'v Value {
    match e {
        Expr::Local(i) => match frame.get(i.index()) {
            Some(v) => v,
            None => tmp,
        },
        Expr::Global(i) => match globals.get(i.index()) {
            Some(v) => v,
            None => tmp,
        },
        Expr::Number(n) => {
            *tmp = Value::Num(*n);
            tmp
        }
        Expr::Text(t) => t.value(),
        // `+k`: the operator of the operand read in place, kept in `tmp`.
        Expr::Unary(op, a) => {
            let mut inner = Value::Null;
            *tmp = unary(*op, plain_leaf(a, frame, globals, &mut inner));
            tmp
        }
        _ => tmp,
    }
}

/// [`leaf`] of a local, a global, a number or a text.
#[inline(always)]
fn plain_leaf<'v>(e: &'v Expr, frame: &'v [Value], globals: &'v [Value], tmp: &'v mut Value) -> &'v Value {
    match e {
        Expr::Local(i) => frame.get(i.index()).unwrap_or(tmp),
        Expr::Global(i) => globals.get(i.index()).unwrap_or(tmp),
        Expr::Number(n) => {
            *tmp = Value::Num(*n);
            tmp
        }
        Expr::Text(t) => t.value(),
        _ => tmp,
    }
}

/// A call's frame from its arguments: the parameters, then the function's
/// other slots, `undefined` where JavaScript starts them so (arguments
/// past the parameters are only in `arguments` then), `null` otherwise.
#[inline(always)]
fn fill_frame(runnable: &crate::exec::Function, frame: &mut Vec<Value>) {
    // Pushed in place, room reserved once: the fill owns nothing, so no
    // clone of it is made, nor a value of it dropped (a frame's few slots
    // cost less pushed than through a general `extend`).
    let slots = runnable.slots as usize;
    if runnable.starts_undefined && frame.len() > runnable.params {
        frame.truncate(runnable.params);
    }
    if frame.len() < slots {
        frame.reserve(slots - frame.len());
        let fill = || if runnable.starts_undefined { Value::Undefined } else { Value::Null };
        while frame.len() < slots {
            frame.push(fill());
        }
    }
}
