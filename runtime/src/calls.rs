//! Runs a post over Sub calls instead of toolpath events: VcPost's
//! probe-cycle tables and composites event files (see
//! [`postc_ir::calls`]).
//!
//! [`run_calls`] runs the post's one-time code (statements outside any Sub),
//! then, for each [`SubCall`] in order:
//!
//! 1. sets each variable the call carries that the post has (a register or
//!    a global, names compared without case; other names are skipped), and
//!    fills the globals of each [`postc_ir::CallList`] from the call's list
//!    of that name (see [`crate::call_tables`]);
//! 2. calls the Sub of that name (without case). A Sub the post lacks is
//!    skipped: silently when the call says so ([`MissingSub::Skip`], a
//!    routine a post may leave out by design), else with one warning per
//!    name (RT030).
//!
//! Each call has the post's whole step budget; a runaway loop stops with
//! RT002 at the loop's line, and the diagnostic also points at the record
//! that called the Sub. After the first error no more Subs run, but the
//! source is read to its end so that every problem of the file is
//! reported (at most [`MAX_DIAGNOSTICS`]). Output is written whole or not
//! at all, as for toolpaths.

use std::collections::HashMap;

use postc_ir::{CallSource, CallValue, Diagnostic, MissingSub, Post, SubCall};

use crate::call_tables::Tables;
use crate::engine::Engine;
use crate::slots::Slots;
use crate::value::Value;
use crate::{Output, RunOptions, RunReport};

/// Most diagnostics collected from a source after its first error.
pub const MAX_DIAGNOSTICS: usize = 200;

/// Runs `post` over the calls of `source` into `out`.
pub fn run_calls<S: CallSource + ?Sized>(
    post: &Post,
    source: &mut S,
    out: Output,
    mut options: RunOptions,
) -> Result<RunReport, Vec<Diagnostic>> {
    let mut machine = crate::machine::MachineState::new(
        post.output_units(),
        post.options.spindle_speed_range,
        post.options.rotary_wrap,
    );
    machine.date = options.date.take().unwrap_or_default();
    machine.time = options.time.take().unwrap_or_default();
    (machine.default_date, machine.default_time) = crate::clock::format_utc(options.now.unwrap_or(0));
    if let Some(f) = options.file.take() {
        machine.file_name = f.name;
        machine.file_dir = f.dir;
        machine.file_ext = f.extension;
    }
    let code = crate::prepare::prepare(post);
    let mut eng = Engine::new(post, &code, machine, out);
    let mut diagnostics = Vec::new();
    if let Err(d) = eng.init() {
        diagnostics.push(*d);
        diagnostics.append(&mut eng.warnings);
        return Err(diagnostics);
    }
    let mut runner = Runner::new(post, Tables::new(post));
    let mut failed = false;
    let mut calls = 0u64;
    while let Some(call) = source.next_call(&mut diagnostics) {
        if postc_ir::diagnostic::has_errors(&diagnostics) {
            failed = true;
        }
        if failed {
            if diagnostics.len() >= MAX_DIAGNOSTICS {
                break;
            }
            continue;
        }
        if let Err(d) = runner.call(&mut eng, &call) {
            diagnostics.push(*d);
            failed = true;
        }
        calls += 1;
        if calls & 0xFFFF == 0
            && let Some(p) = options.progress.as_mut()
        {
            p(calls);
        }
    }
    if failed || postc_ir::diagnostic::has_errors(&diagnostics) {
        diagnostics.append(&mut eng.warnings);
        return Err(diagnostics);
    }
    diagnostics.append(&mut eng.warnings);
    let (blocks, bytes) = (eng.out.blocks(), eng.out.bytes());
    match eng.out.finish(post.options.tape_splitting.as_ref()) {
        Ok(output) => Ok(RunReport { warnings: diagnostics, events: calls, blocks, bytes, output }),
        Err(e) => {
            diagnostics.push(Diagnostic::error("IO003", format!("could not write the program: {e}")));
            Err(diagnostics)
        }
    }
}

/// Calls Subs by name.
struct Runner {
    slots: Slots,
    /// Upper-case Sub name to function index.
    subs: HashMap<String, postc_ir::FunctionId>,
    tables: Tables,
    warned: Vec<String>,
}

impl Runner {
    fn new(post: &Post, tables: Tables) -> Runner {
        let mut subs = HashMap::new();
        for (i, f) in post.functions.iter().enumerate() {
            if let Some(i) = postc_ir::FunctionId::from_usize(i) {
                subs.entry(f.name.to_ascii_uppercase()).or_insert(i);
            }
        }
        Runner { slots: Slots::new(post), subs, tables, warned: Vec::new() }
    }

    fn call(&mut self, eng: &mut Engine, call: &SubCall) -> Result<(), Box<Diagnostic>> {
        eng.event_span = call.span;
        let mut filled = Vec::new();
        for (name, value) in &call.vars {
            let upper = name.to_ascii_uppercase();
            match value {
                CallValue::Number(n) => self.slots.set(eng, &upper, Value::Num(*n)),
                CallValue::Text(t) => self.slots.set(eng, &upper, Value::text(t)),
                CallValue::List(values) if self.tables.has(&upper) => {
                    self.tables.fill(eng, &upper, values);
                    filled.push(upper);
                }
                CallValue::List(_) => {}
            }
        }
        self.tables.clear_except(eng, &filled);
        let upper = call.sub.to_ascii_uppercase();
        let Some(&f) = self.subs.get(&upper) else {
            if call.missing == MissingSub::Warn && !self.warned.contains(&upper) {
                self.warned.push(upper);
                eng.warn_once(
                    Diagnostic::warning(
                        "RT030",
                        format!("the post has no Sub `{}`; those calls are skipped", call.sub),
                    )
                    .at(call.span, "first call"),
                );
            }
            return Ok(());
        };
        eng.steps = 0;
        eng.call(f, Vec::new())
            .map(|_| ())
            .map_err(|d| Box::new(d.also(call.span, format!("while running `{}` for this record", call.sub))))
    }
}
