//! The engine: runs handler bodies against the machine state and writes
//! blocks to the output.
//!
//! [`Engine`] owns everything mutable in a run: the [`MachineState`], the
//! [`Output`], each variable's modal memory and value, block numbering,
//! globals, and the collected warnings. [`Engine::run_handler`] is the hot
//! path for Vectric sections: each [`Stmt::Line`] writes literal bytes and
//! formats variables straight into the output buffer. The rest of the
//! statement language (assignments, conditionals, loops, calls) is
//! interpreted by the `interp` module on the same engine.

use postc_ir::post::Substitution;
use postc_ir::{
    Diagnostic, FormatId, HandlerKey, Modality, Piece as IrPiece, Post, Quantity, Section, Span, Stmt as IrStmt,
    ValueSource, VarId, Variable,
};

use crate::exec::{Code, Expr, Piece, Stmt};

use crate::machine::MachineState;
use crate::number::{NumberWriter, Rounded};
use crate::output::Output;
use crate::value::{Text, Value};

/// Per-variable run state.
#[derive(Clone, Debug)]
pub struct VarState {
    /// What the variable printed last, for on-change variables: the rounded
    /// number (`key`) when it printed a number on the fast path, else the
    /// text (`last`, prefix included, valid when `has_last`).
    pub(crate) key: Option<Rounded>,
    pub(crate) last: Vec<u8>,
    pub(crate) has_last: bool,
    /// The number an on-change variable that compares values
    /// ([`Modal::Value`]) printed last; NaN when it has printed none since
    /// its memory was cleared (NaN equals nothing).
    pub(crate) last_value: f64,
    /// Current and previous value (registers, output variables).
    pub(crate) value: Value,
    pub(crate) previous: Value,
    /// For a variable that always prints: the last word it made of a
    /// number. The same number makes the same word, so a feed formatted
    /// every move (`getFeedrate(m)`) is made, and read back, once.
    pub(crate) kept: Option<KeptWord>,
}

impl Default for VarState {
    fn default() -> VarState {
        VarState {
            key: None,
            last: Vec::new(),
            has_last: false,
            last_value: f64::NAN,
            value: Value::default(),
            previous: Value::default(),
            kept: None,
        }
    }
}

/// A word a variable that always prints made of a number ([`VarState::kept`]).
#[derive(Clone, Debug)]
#[doc(hidden)]
pub struct KeptWord {
    /// The number's bits.
    pub bits: u64,
    /// The number as rounded, the variable's modal key after printing it.
    pub rounded: Rounded,
    pub word: Text,
    /// `parseFloat(word.substring(from))` once read: `from` and the number.
    pub read: Option<(usize, f64)>,
}

impl VarState {
    /// The word kept for `n`, the variable left as printing it leaves it;
    /// `None` when none is kept for that number.
    #[inline(always)]
    pub(crate) fn reprint(&mut self, n: f64) -> Option<&mut KeptWord> {
        let kept = self.kept.as_mut().filter(|k| k.bits == n.to_bits())?;
        self.key = Some(kept.rounded);
        self.has_last = false;
        self.previous = std::mem::replace(&mut self.value, Value::Num(n));
        Some(kept)
    }
}

/// Block numbering state.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BlockCounter {
    pub next: f64,
    pub printed: bool,
}

/// Runs a post's handlers.
pub struct Engine<'p> {
    pub post: &'p Post,
    /// The post's code as the runtime runs it ([`crate::prepare`]).
    pub(crate) code: &'p Code,
    pub machine: MachineState,
    pub out: Output,
    pub(crate) writers: Vec<NumberWriter>,
    pub(crate) vars: Vec<VarState>,
    /// Prefix of each variable as printed (rotary wrap may change a letter).
    pub(crate) prefixes: Vec<Vec<u8>>,
    pub(crate) globals: Vec<Value>,
    pub(crate) block: BlockCounter,
    /// Handler index of each section, if the post has it.
    sections: Vec<Option<u16>>,
    /// The line ending, for appending as one fixed-size copy.
    line_ending: Option<SmallBytes>,
    /// Each handler's body, prepared for the hot path.
    prepared: Vec<std::rc::Rc<Vec<Prepared<'p>>>>,
    /// Warnings collected during the run (each said once).
    pub warnings: Vec<Diagnostic>,
    #[doc(hidden)]
    pub steps: u64,
    pub(crate) depth: usize,
    /// `this` of each method call in progress (`Expr::This` reads the last).
    pub(crate) this_stack: Vec<Value>,
    /// JavaScript's global object, what `this` is outside a method
    /// ([`crate::interp::objects`]), made when first read.
    pub(crate) global_object: std::cell::OnceCell<crate::interp::objects::GlobalObject>,
    /// The value a `throw` is carrying up to its `try`.
    pub(crate) thrown: Option<Value>,
    /// The built-in prototypes of the run (`Object.prototype`, ...).
    pub(crate) protos: crate::interp::protos::Protos,
    /// The one value of each post function that captures nothing, by
    /// function, made when first needed.
    pub(crate) function_values: Vec<Option<Value>>,
    /// The arguments of each call in progress of a function that reads
    /// `arguments`.
    pub(crate) arguments: Vec<Value>,
    /// Where the event being handled came from.
    pub event_span: Span,
    /// The run's script host ([`crate::script_host`]), if the post has scripts.
    pub(crate) script_host: Option<Box<dyn crate::script_host::ScriptHost>>,
    /// A frame reused by handler bodies, sized once for all of them and
    /// never cleared, so that their locals cost nothing per event (a
    /// handler starts as `null` the locals it needs so, see
    /// [`Code::handler_slots`]).
    handler_frame: Vec<Value>,
    /// Emptied argument lists and function frames, kept with their
    /// capacity: a call or built-in takes one and gives it back, so that
    /// calls cost no allocation per event once the run is warm.
    pub(crate) spare_frames: Vec<Vec<Value>>,
    /// Arrays no value refers to any more, emptied, kept with their
    /// storage: an array a call made and dropped (`[x, y, z]`, a
    /// `filter`'s result) is made again from them with no allocation
    /// ([`Engine::new_array`]).
    pub(crate) spare_arrays: Vec<std::rc::Rc<std::cell::RefCell<Vec<Value>>>>,
    /// The text of a chain of `+` being built (`text + " " + word`), kept
    /// with its capacity: a chain allocates only its result.
    pub(crate) chain_text: String,
    /// Where the host's output variables and formats keep the properties
    /// `Builtin::FormatOutput` reads (one inline cache a property name:
    /// the host makes them all in one order).
    pub(crate) output_hints: crate::interp::host_text::OutputHints,
    /// Counts the clearings of modal memory ([`Engine::clear_modal`]).
    pub(crate) modal_epoch: u64,
    /// Provenance of each block, when the run is traced.
    pub(crate) trace: Option<Box<crate::trace::Tracer>>,
    /// Told of handler runs and calls, when the run is profiled.
    pub(crate) profile: Option<Box<dyn crate::profile::CallObserver>>,
    /// A buffer reused to format values into text, and the empty text
    /// shared by every modal variable that prints nothing: formatting into
    /// a value allocates only when there is text.
    pub(crate) scratch: Vec<u8>,
    /// The text `parseFloat(text.substring(k))` reads, reused.
    pub(crate) float_text: Vec<u8>,
    pub(crate) empty_text: crate::value::Text,
    /// The post's text is JavaScript's (`OutputOptions::js_text`): `+`
    /// and a block's pieces write null as `null`, as JavaScript's ToString
    /// does ([`crate::interp::ops::add_js`]); otherwise null is a value
    /// that prints nothing.
    pub(crate) js: bool,
}

impl<'p> Engine<'p> {
    /// An engine for `post`, whose code `code` is ([`crate::prepare::prepare`]).
    pub fn new(post: &'p Post, code: &'p Code, mut machine: MachineState, out: Output) -> Engine<'p> {
        machine.revision.clone_from(&post.info.revision);
        let writers = post.formats.iter().map(NumberWriter::new).collect();
        let mut sections = vec![None; Section::ALL.len()];
        for (i, h) in post.handlers.iter().enumerate() {
            if let HandlerKey::Section(s) = h.key {
                sections[s as usize] = Some(i as u16);
            }
        }
        let prefixes = post
            .variables
            .iter()
            .map(|v| post.options.rotary_wrap.map_or_else(|| v.prefix.clone(), |w| w.prefix(v)))
            .collect();
        let prepared = post
            .handlers
            .iter()
            .zip(&code.handlers)
            .map(|(h, body)| std::rc::Rc::new(prepare_lines(post, body, is_move_section(&h.key))))
            .collect();
        Engine {
            post,
            code,
            machine,
            out,
            writers,
            vars: vec![VarState::default(); post.variables.len()],
            prefixes,
            globals: Vec::new(),
            block: BlockCounter { next: post.options.block_numbers.start, printed: false },
            sections,
            line_ending: SmallBytes::new(&post.options.line_ending),
            prepared,
            warnings: Vec::new(),
            steps: 0,
            depth: 0,
            this_stack: Vec::new(),
            global_object: std::cell::OnceCell::new(),
            thrown: None,
            protos: Default::default(),
            function_values: Vec::new(),
            arguments: Vec::new(),
            event_span: Span::default(),
            script_host: None,
            handler_frame: vec![Value::Null; code.handler_slots],
            spare_frames: Vec::new(),
            spare_arrays: Vec::new(),
            chain_text: String::new(),
            output_hints: Default::default(),
            modal_epoch: 0,
            trace: None,
            profile: None,
            scratch: Vec::with_capacity(64),
            float_text: Vec::with_capacity(64),
            empty_text: crate::value::Text::new(""),
            js: post.options.js_text,
        }
    }

    /// Whether the post has a handler for the section.
    #[inline]
    pub fn has(&self, section: Section) -> bool {
        self.sections[section as usize].is_some()
    }

    /// Runs the post's one-time code: global initial values, then `init`
    /// (VcPost statements outside any Sub, CIMCO top-level code).
    pub fn init(&mut self) -> Result<(), Box<Diagnostic>> {
        let code = self.code;
        let mut frame = Vec::new();
        self.globals = Vec::with_capacity(code.globals.len());
        for initial in &code.globals {
            let v = self.eval(initial, &mut frame)?;
            self.globals.push(v);
        }
        self.steps = 0;
        self.exec(&code.init, &mut frame)?;
        Ok(())
    }

    /// Runs the handler at `index` of the post's handlers.
    pub fn run_handler(&mut self, index: usize) -> Result<(), Box<Diagnostic>> {
        let body = self.prepared[index].clone();
        self.run_prepared(&body)?;
        self.finite(self.post.handlers[index].span)
    }

    /// Runs the section's handler; false when the post has none.
    #[inline]
    pub fn run_section(&mut self, section: Section) -> Result<bool, Box<Diagnostic>> {
        match self.sections[section as usize] {
            Some(i) => {
                let body = self.prepared[i as usize].clone();
                if let Some(t) = self.trace.as_deref_mut() {
                    let h = &self.post.handlers[i as usize];
                    t.handler = Some((h.key.clone(), h.span));
                    t.origin = None;
                }
                if let Some(p) = self.profile.as_deref_mut() {
                    p.enter(crate::profile::Frame::Handler(i as usize));
                }
                let result = self.run_prepared(&body);
                if let Some(p) = self.profile.as_deref_mut() {
                    p.exit();
                }
                result?;
                // A block's formats are checked where they are written;
                // this finds any other (a section's line of words).
                self.finite(self.post.handlers[i as usize].span)?;
                Ok(true)
            }
            None => Ok(false),
        }
    }

    /// Tells the tracer that a new tape-split part starts.
    pub(crate) fn trace_new_part(&mut self) {
        if let Some(t) = self.trace.as_deref_mut() {
            t.new_part();
        }
    }

    /// Hands the blocks written since the last call to the tracer, with
    /// the span of the statement that wrote them.
    #[cold]
    pub(crate) fn trace_after(&mut self, span: Option<Span>) {
        if let Some(t) = self.trace.as_deref_mut() {
            t.report(self.out.blocks(), self.out.blocks_in_part(), span);
        }
    }

    /// Whether the section prints the given quantity (Vectric's helical
    /// fallback asks whether an arc section prints `[Z]`).
    pub fn section_prints(&self, section: Section, q: Quantity) -> bool {
        let Some(i) = self.sections[section as usize] else { return false };
        self.post.handlers[i as usize].body.iter().any(|s| match s {
            IrStmt::Line { pieces, .. } => pieces.iter().any(
                |p| matches!(p, IrPiece::Var(v) if self.post.variables[v.index()].source == ValueSource::Quantity(q)),
            ),
            _ => false,
        })
    }

    /// Forgets what every variable printed last: the next output prints every word.
    pub fn clear_modal(&mut self) {
        self.modal_epoch += 1;
        for v in &mut self.vars {
            v.forget();
        }
    }

    /// Forgets what one variable printed last (`xOutput.reset()`): its next
    /// value prints whatever it is.
    pub fn forget_var(&mut self, var: VarId) {
        if let Some(v) = self.vars.get_mut(var.index()) {
            v.forget();
        }
    }

    /// Runs a prepared handler body: the hot path.
    fn run_prepared(&mut self, body: &[Prepared<'p>]) -> Result<(), Box<Diagnostic>> {
        for stmt in body {
            match stmt {
                Prepared::Line(ops, span) => {
                    for op in ops {
                        match op {
                            Op::Text(bytes) => self.out.buf.extend_from_slice(bytes),
                            Op::ShortText(small) => small.append_to(&mut self.out.buf),
                            Op::Number { var, quantity, format, modal } => {
                                let n = self.machine.number(*quantity);
                                let (state, prefix) = (&mut self.vars[var.index()], &self.prefixes[var.index()]);
                                put_modal::<true>(
                                    *modal,
                                    &self.writers[format.index()],
                                    state,
                                    prefix,
                                    n,
                                    &mut self.out.buf,
                                );
                            }
                            Op::Position { var, axis, format, modal } => {
                                let n = self.machine.pos[*axis as usize];
                                let (state, prefix) = (&mut self.vars[var.index()], &self.prefixes[var.index()]);
                                put_modal::<true>(
                                    *modal,
                                    &self.writers[format.index()],
                                    state,
                                    prefix,
                                    n,
                                    &mut self.out.buf,
                                );
                            }
                            Op::Piece(piece) => self.write_piece(piece)?,
                        }
                    }
                    self.end_block();
                    if self.trace.is_some() {
                        self.trace_after(*span);
                    }
                }
                Prepared::OptionalLine(ops, span) => self.write_optional_line(ops, *span)?,
                Prepared::Stmts(stmts, steps) => {
                    self.steps = *steps;
                    // One frame, kept between events as they leave it.
                    let mut frame = std::mem::take(&mut self.handler_frame);
                    let result = self.exec(stmts, &mut frame);
                    self.handler_frame = frame;
                    result?;
                }
            }
        }
        Ok(())
    }

    /// Runs a handler body: the hot path for plain lines.
    pub fn run_body(&mut self, body: &[Stmt]) -> Result<(), Box<Diagnostic>> {
        for stmt in body {
            match stmt {
                Stmt::Line { pieces, span } => {
                    self.write_line(pieces)?;
                    if self.trace.is_some() {
                        self.trace_after(*span);
                    }
                }
                other => {
                    self.steps = 0;
                    let mut frame = Vec::new();
                    self.exec(std::slice::from_ref(other), &mut frame)?;
                }
            }
        }
        Ok(())
    }

    /// Writes one block: its pieces, then the line ending.
    pub(crate) fn write_line(&mut self, pieces: &[Piece]) -> Result<(), Box<Diagnostic>> {
        for piece in pieces {
            self.write_piece(piece)?;
        }
        self.end_block();
        Ok(())
    }

    /// Writes one piece of a block.
    #[inline]
    fn write_piece(&mut self, piece: &Piece) -> Result<(), Box<Diagnostic>> {
        match piece {
            Piece::Text(bytes) => self.out.buf.extend_from_slice(bytes),
            Piece::Var(id) => self.write_var(*id),
            Piece::Expr(Expr::FormatVar { var, value, span }) => {
                let mut frame = Vec::new();
                let v = self.eval(value, &mut frame)?;
                self.write_assigned(*var, v);
                self.finite(*span)?;
            }
            Piece::Expr(e) => {
                let mut frame = Vec::new();
                let v = self.eval(e, &mut frame)?;
                self.write_value_text(&v);
            }
            Piece::Joined(e) => {
                let mut frame = Vec::new();
                let v = self.eval(e, &mut frame)?;
                if !matches!(v, Value::Null | Value::Undefined) {
                    self.write_value_text(&v);
                }
            }
        }
        Ok(())
    }

    /// Writes a [`Prepared::OptionalLine`]: as a line, unless every value
    /// it prints is one the job does not have, in which case nothing of it
    /// is written (its block number is not used) and a warning names the
    /// post line. A value missing right after a letter of the line's text
    /// (`T[T]` printing `T`) is a warning too: an address with no number.
    #[inline(never)]
    fn write_optional_line(&mut self, ops: &[Op<'_>], span: Option<Span>) -> Result<(), Box<Diagnostic>> {
        let start = self.out.buf.len();
        let (mut values, mut missing, mut missing_text) = (0usize, Vec::new(), 0usize);
        let mut bare_letter = None;
        let mut letter_before = None;
        for op in ops {
            let letter = match op {
                Op::Text(bytes) => {
                    self.out.buf.extend_from_slice(bytes);
                    bytes.last().copied()
                }
                Op::ShortText(small) => {
                    small.append_to(&mut self.out.buf);
                    self.out.buf.last().copied()
                }
                Op::Number { var, quantity, format, modal } => {
                    let n = self.machine.number(*quantity);
                    values += 1;
                    if n.is_nan() {
                        missing.push(*var);
                        if bare_letter.is_none() && self.prefixes[var.index()].is_empty() {
                            bare_letter = letter_before.map(|l: u8| (l, *var));
                        }
                    }
                    let (state, prefix) = (&mut self.vars[var.index()], &self.prefixes[var.index()]);
                    put_modal::<true>(*modal, &self.writers[format.index()], state, prefix, n, &mut self.out.buf);
                    None
                }
                Op::Position { var, axis, format, modal } => {
                    let n = self.machine.pos[*axis as usize];
                    let (state, prefix) = (&mut self.vars[var.index()], &self.prefixes[var.index()]);
                    put_modal::<true>(*modal, &self.writers[format.index()], state, prefix, n, &mut self.out.buf);
                    values += 1;
                    None
                }
                Op::Piece(piece) => {
                    if let Some(q) = text_quantity(self.post, piece) {
                        values += 1;
                        if self.machine.text(q).is_empty() {
                            missing_text += 1;
                        }
                    }
                    self.write_piece(piece)?;
                    None
                }
            };
            letter_before = letter.filter(u8::is_ascii_alphabetic);
        }
        let names = |eng: &Self, vars: &[VarId]| {
            let label = |v: &VarId| {
                let var = &eng.post.variables[v.index()];
                match var.source {
                    ValueSource::Quantity(q) => format!("[{}]", q.label()),
                    _ => var.name.clone(),
                }
            };
            vars.iter().map(label).collect::<Vec<_>>().join(" ")
        };
        if values > 0 && missing.len() + missing_text == values {
            // A line of empty texts only, or a comment (its text starts
            // with `(`, `;` or `'`), goes without a word: it changes
            // nothing on the part.
            let comment =
                matches!(self.out.buf[start..].iter().find(|b| !b.is_ascii_whitespace()), Some(b'(' | b';' | b'\''));
            self.out.buf.truncate(start);
            self.block.printed = false;
            if missing.is_empty() || comment {
                return Ok(());
            }
            let d = Diagnostic::warning(
                "RT033",
                format!(
                    "this line prints only {}, which this job does not give; it is left out",
                    names(self, &missing)
                ),
            )
            .help("a job with no tool, no home position or no material size has nothing for such a line to print");
            self.warn_once_at(match span {
                Some(s) => d.at(s, "left out"),
                None => d,
            });
            return Ok(());
        }
        if let Some((letter, var)) = bare_letter {
            let d = Diagnostic::warning(
                "RT034",
                format!(
                    "this line prints the address `{}` with no number: the job gives no {}",
                    letter as char,
                    names(self, &[var])
                ),
            )
            .help("a controller reads a letter with no number as an error, or as zero; print the letter with the value (the variable's prefix), or give the job the value");
            self.warn_once_at(match span {
                Some(s) => d.at(s, "an address with no number"),
                None => d,
            });
        }
        self.end_block();
        if self.trace.is_some() {
            self.trace_after(span);
        }
        Ok(())
    }

    /// Writes the line ending and advances block numbering.
    pub(crate) fn end_block(&mut self) {
        match &self.line_ending {
            Some(small) => small.append_to(&mut self.out.buf),
            None => self.out.buf.extend_from_slice(&self.post.options.line_ending),
        }
        self.out.end_block();
        self.advance_block_number();
    }

    /// After a block that printed `[N]`: the next block number, wrapping
    /// past the maximum to the start.
    #[inline]
    pub(crate) fn advance_block_number(&mut self) {
        if self.block.printed {
            self.block.printed = false;
            let b = self.post.options.block_numbers;
            self.block.next += b.increment;
            if self.block.next > b.maximum {
                self.block.next = b.start;
            }
        }
    }

    pub(crate) fn write_value_text(&mut self, v: &Value) {
        match v {
            Value::Text(s) => s.append_to_bytes(&mut self.out.buf),
            Value::Null if self.js => self.out.buf.extend_from_slice(b"null"),
            other => {
                // A number's text, made in the engine's reused buffer.
                let mut s = std::mem::take(&mut self.chain_text);
                s.clear();
                other.append_to(&mut s);
                self.out.buf.extend_from_slice(s.as_bytes());
                self.chain_text = s;
            }
        }
    }

    /// Formats a variable from its source into the output, honouring its modality.
    #[inline]
    pub(crate) fn write_var(&mut self, id: VarId) {
        let post = self.post;
        let var = &post.variables[id.index()];
        let (state, prefix) = (&mut self.vars[id.index()], &self.prefixes[id.index()]);
        match var.source {
            ValueSource::Quantity(q) if q.is_text() => put_text(
                is_modal(var),
                state,
                prefix,
                self.machine.text(q).as_bytes(),
                &post.options.substitutions,
                &mut self.out.buf,
            ),
            ValueSource::Quantity(Quantity::BlockNumber) => {
                self.block.printed = true;
                let w = &self.writers[var.format.index()];
                put_modal::<false>(modal_of(post, var), w, state, prefix, self.block.next, &mut self.out.buf);
            }
            ValueSource::Quantity(q) => {
                let w = &self.writers[var.format.index()];
                put_modal::<true>(modal_of(post, var), w, state, prefix, self.machine.number(q), &mut self.out.buf);
            }
            ValueSource::Assigned => {
                let v = state.value.clone();
                self.print_value(id, &v);
            }
        }
    }

    /// Gives a variable a value and prints it (CIMCO `xOutput.format(v)` in a block).
    pub(crate) fn write_assigned(&mut self, id: VarId, v: Value) {
        self.print_value(id, &v);
        self.set_var(id, v);
    }

    /// Prints a value through a variable's prefix, format and modality.
    fn print_value(&mut self, id: VarId, v: &Value) {
        let post = self.post;
        let var = &post.variables[id.index()];
        let (state, prefix) = (&mut self.vars[id.index()], &self.prefixes[id.index()]);
        match v {
            Value::Text(s) => {
                put_text(is_modal(var), state, prefix, s.as_bytes(), &post.options.substitutions, &mut self.out.buf)
            }
            other => {
                let w = &self.writers[var.format.index()];
                put_number(is_modal(var), w, state, prefix, other.num(), &mut self.out.buf);
            }
        }
    }

    /// Records a warning once; the same warning at another place of the
    /// post adds that place to it (up to ten), so each line is named once.
    pub fn warn_once_at(&mut self, d: Diagnostic) {
        let Some(w) = self.warnings.iter_mut().find(|w| w.code == d.code && w.message == d.message) else {
            self.warnings.push(d);
            return;
        };
        if let Some(label) = d.labels.into_iter().find(|l| l.primary)
            && w.labels.len() < 10
            && !w.labels.iter().any(|l| l.span == label.span)
        {
            w.labels.push(postc_ir::diagnostic::Label { primary: false, ..label });
        }
    }

    /// Records a warning once.
    pub fn warn_once(&mut self, d: Diagnostic) {
        if !self.warnings.iter().any(|w| w.code == d.code && w.message == d.message) {
            self.warnings.push(d);
        }
    }
}

/// Copies text, replacing substituted characters.
pub(crate) fn substitute_into(text: &[u8], subs: &[Substitution], out: &mut Vec<u8>) {
    if subs.is_empty() {
        out.extend_from_slice(text);
        return;
    }
    let mut i = 0;
    'outer: while i < text.len() {
        for s in subs {
            if !s.from.is_empty() && text[i..].starts_with(&s.from) {
                out.extend_from_slice(&s.to);
                i += s.from.len();
                continue 'outer;
            }
        }
        out.push(text[i]);
        i += 1;
    }
}

/// Prints a number through a variable, unless it is on-change and prints
/// what it printed last.
#[inline(always)]
#[doc(hidden)]
pub fn put_number(modal: bool, w: &NumberWriter, state: &mut VarState, prefix: &[u8], n: f64, out: &mut Vec<u8>) {
    put::<false>(modal, w, state, prefix, n, out);
}

/// How an on-change variable tells that it must print again.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Modal {
    /// It always prints.
    Always,
    /// It prints when its printed text changes (CIMCO, VcPost).
    Text,
    /// It prints when its number changes, even by less than the last
    /// printed digit (Vectric: [`postc_ir::OutputOptions::on_change_by_value`]).
    Value,
}

/// The modality of a variable that prints a runtime quantity.
#[inline]
pub(crate) fn modal_of(post: &Post, var: &Variable) -> Modal {
    match (is_modal(var), post.options.on_change_by_value) {
        (false, _) => Modal::Always,
        (true, false) => Modal::Text,
        (true, true) => Modal::Value,
    }
}

/// Prints a number through a variable under a [`Modal`]: a variable that
/// compares values prints when the number differs from the one it printed
/// last (NaN, no value, is never equal), whatever text it makes. With
/// `ABSENT_PRINTS_NOTHING` (runtime quantities), a quantity with no value
/// ([`crate::machine::NO_VALUE`]) prints nothing, prefix included, and
/// leaves the modal memory as it was (the controller still holds what was
/// printed last). The check sits on the slow path, which NaN takes anyway:
/// the fast path pays nothing.
#[inline(always)]
pub(crate) fn put_modal<const ABSENT_PRINTS_NOTHING: bool>(
    modal: Modal,
    w: &NumberWriter,
    state: &mut VarState,
    prefix: &[u8],
    n: f64,
    out: &mut Vec<u8>,
) {
    match modal {
        Modal::Value => {
            if n == state.last_value || (ABSENT_PRINTS_NOTHING && n.is_nan()) {
                return;
            }
            state.last_value = n;
            put::<ABSENT_PRINTS_NOTHING>(false, w, state, prefix, n, out);
        }
        other => put::<ABSENT_PRINTS_NOTHING>(other == Modal::Text, w, state, prefix, n, out),
    }
}

#[inline(always)]
fn put<const ABSENT_PRINTS_NOTHING: bool>(
    modal: bool,
    w: &NumberWriter,
    state: &mut VarState,
    prefix: &[u8],
    n: f64,
    out: &mut Vec<u8>,
) {
    match w.round(n) {
        Some(r) => {
            if modal {
                match state.key {
                    Some(k) if k == r => return,
                    None if state.has_last => {
                        // The last print took the slow path: compare text.
                        let start = out.len();
                        out.extend_from_slice(prefix);
                        w.write_rounded(r, out);
                        if out[start..] == state.last[..] {
                            out.truncate(start);
                        } else {
                            state.has_last = false;
                            state.key = Some(r);
                        }
                        return;
                    }
                    _ => {}
                }
            }
            state.key = Some(r);
            state.has_last = false;
            w.write_rounded_after(prefix, r, out);
        }
        None => {
            if ABSENT_PRINTS_NOTHING && n.is_nan() {
                return;
            }
            if let Some(k) = state.key.take() {
                state.last.clear();
                state.last.extend_from_slice(prefix);
                w.write_rounded(k, &mut state.last);
                state.has_last = true;
            }
            let start = out.len();
            out.extend_from_slice(prefix);
            w.write(n, out);
            keep_if_changed(modal, state, start, out);
        }
    }
}

/// [`put_number`] as a text value, on the fast path only: the word, or
/// `empty` when the variable prints nothing (on-change, the same number).
/// `None`, with nothing changed, when the number takes the slow path (past
/// the fast range, a padded format, text printed last): the caller then
/// formats into a buffer.
#[inline(always)]
#[doc(hidden)]
pub fn number_word(
    modal: bool,
    w: &NumberWriter,
    state: &mut VarState,
    prefix: &[u8],
    n: f64,
    empty: &Text,
) -> Option<Text> {
    let r = w.round(n)?;
    if modal {
        match state.key {
            Some(k) if k == r => return Some(empty.clone()),
            None if state.has_last => return None,
            _ => {}
        }
    }
    let word = w.word_text(prefix, r)?;
    state.key = Some(r);
    state.has_last = false;
    Some(word)
}

/// Prints text through a variable, unless it is on-change and prints what
/// it printed last.
#[doc(hidden)]
pub fn put_text(
    modal: bool,
    state: &mut VarState,
    prefix: &[u8],
    text: &[u8],
    subs: &[Substitution],
    out: &mut Vec<u8>,
) {
    state.key = None;
    let start = out.len();
    out.extend_from_slice(prefix);
    substitute_into(text, subs, out);
    keep_if_changed(modal, state, start, out);
}

/// Applies a variable's modality to what was just written from `start`.
fn keep_if_changed(modal: bool, state: &mut VarState, start: usize, out: &mut Vec<u8>) {
    let written = &out[start..];
    if modal && state.has_last && state.last == written {
        out.truncate(start);
        return;
    }
    state.last.clear();
    state.last.extend_from_slice(written);
    state.has_last = true;
}

#[inline]
#[doc(hidden)]
pub fn is_modal(var: &Variable) -> bool {
    var.modality == Modality::OnChange
}

/// A handler statement prepared for the hot path.
pub(crate) enum Prepared<'p> {
    /// A block whose pieces are resolved to direct operations, and the
    /// line of the post that wrote it.
    Line(Vec<Op<'p>>, Option<Span>),
    /// A [`Prepared::Line`] that prints values a job may not have (a tool
    /// number, a home position, a material size) and nothing that is sure
    /// to have one: left out when none of its values is there, as `T[T] M6`
    /// is for a job with no tool; a letter printed with no value after it
    /// is reported ([`Engine::write_optional_line`]).
    OptionalLine(Vec<Op<'p>>, Option<Span>),
    /// Any other statement, interpreted, or the statements of the one a
    /// handler's share a frame in; with the steps counted before them.
    Stmts(&'p [Stmt], u64),
}

/// One piece of a prepared block.
pub(crate) enum Op<'p> {
    /// Literal bytes.
    Text(&'p [u8]),
    /// Literal bytes that fit a small window: appended as one fixed-size copy.
    ShortText(SmallBytes),
    /// A numeric quantity through a variable: no lookups left to do.
    Number { var: VarId, quantity: Quantity, format: FormatId, modal: Modal },
    /// X, Y or Z of the current position (no rotary wrap): read directly.
    Position { var: VarId, axis: u8, format: FormatId, modal: Modal },
    /// Anything else (text quantities, block numbers, assigned variables, expressions).
    Piece(&'p Piece),
}

/// Whether a handler prints a move: the position is known when it runs.
fn is_move_section(key: &HandlerKey) -> bool {
    matches!(key, HandlerKey::Section(s) if (Section::InitialRapidMove..=Section::CcwHelicalArcPlungeMove).contains(s))
}

/// Prepares a handler body: lines become flat operations. In move sections
/// X, Y and Z are read straight from the position; elsewhere (a HEADER
/// runs before the first move) they go through [`MachineState::number`], which
/// knows whether the position is known yet.
pub(crate) fn prepare_lines<'p>(post: &'p Post, body: &'p [Stmt], moves: bool) -> Vec<Prepared<'p>> {
    body.iter()
        .map(|stmt| match stmt {
            Stmt::Line { pieces, span } => line(
                post,
                pieces
                    .iter()
                    .map(|piece| match piece {
                        Piece::Text(bytes) => match SmallBytes::new(bytes) {
                            Some(small) => Op::ShortText(small),
                            None => Op::Text(bytes),
                        },
                        Piece::Var(id) => {
                            let var = &post.variables[id.index()];
                            match var.source {
                                ValueSource::Quantity(q @ (Quantity::X | Quantity::Y | Quantity::Z))
                                    if moves && post.options.rotary_wrap.is_none() =>
                                {
                                    Op::Position {
                                        var: *id,
                                        axis: [Quantity::X, Quantity::Y, Quantity::Z]
                                            .iter()
                                            .position(|a| *a == q)
                                            .unwrap_or(0) as u8,
                                        format: var.format,
                                        modal: modal_of(post, var),
                                    }
                                }
                                ValueSource::Quantity(q) if !q.is_text() && q != Quantity::BlockNumber => {
                                    Op::Number { var: *id, quantity: q, format: var.format, modal: modal_of(post, var) }
                                }
                                _ => Op::Piece(piece),
                            }
                        }
                        other => Op::Piece(other),
                    })
                    .collect(),
                *span,
            ),
            // A handler's statements made one so that they share a frame
            // (`if (true) { ... }`, see `crate::prepare`) run as the list
            // they are, the `if`'s step counted.
            Stmt::If { branches, otherwise }
                if otherwise.is_empty()
                    && let [(Expr::Bool(true), body)] = branches.as_slice() =>
            {
                Prepared::Stmts(body, 1)
            }
            other => Prepared::Stmts(std::slice::from_ref(other), 0),
        })
        .collect()
}

/// A prepared line: optional ([`Prepared::OptionalLine`]) when every value
/// it prints may be missing from a job, or when one that may be follows a
/// letter of its text; otherwise a plain line.
fn line<'p>(post: &Post, ops: Vec<Op<'p>>, span: Option<Span>) -> Prepared<'p> {
    let numbers = ops
        .iter()
        .filter(|op| matches!(op, Op::Number { .. }) || matches!(op, Op::Piece(p) if text_quantity(post, p).is_some()))
        .count();
    let positions = ops.iter().any(|op| matches!(op, Op::Position { .. }));
    let all_optional = numbers > 0 && !positions;
    let after_letter = ops.windows(2).any(|w| {
        let last = match &w[0] {
            Op::Text(bytes) => bytes.last().copied(),
            Op::ShortText(small) => small.last(),
            _ => None,
        };
        last.is_some_and(|b| b.is_ascii_alphabetic()) && matches!(w[1], Op::Number { .. })
    });
    if all_optional || after_letter { Prepared::OptionalLine(ops, span) } else { Prepared::Line(ops, span) }
}

/// The text quantity a piece prints through a variable (`[TOOLNAME]`).
fn text_quantity(post: &Post, piece: &Piece) -> Option<Quantity> {
    match piece {
        Piece::Var(id) => match post.variables.get(id.index())?.source {
            ValueSource::Quantity(q) if q.is_text() => Some(q),
            _ => None,
        },
        _ => None,
    }
}

/// Up to 16 bytes kept in a fixed array, so that appending them is one
/// fixed-size copy and a truncate rather than a `memcpy` call.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SmallBytes {
    bytes: [u8; 16],
    len: u8,
}

impl SmallBytes {
    pub(crate) fn new(bytes: &[u8]) -> Option<SmallBytes> {
        let mut small = SmallBytes { bytes: [0; 16], len: u8::try_from(bytes.len()).ok()? };
        small.bytes.get_mut(..bytes.len())?.copy_from_slice(bytes);
        Some(small)
    }

    #[inline(always)]
    pub(crate) fn append_to(&self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.bytes);
        out.truncate(out.len() - (16 - self.len as usize));
    }

    /// The last byte, if any.
    pub(crate) fn last(&self) -> Option<u8> {
        self.bytes[..self.len as usize].last().copied()
    }
}
