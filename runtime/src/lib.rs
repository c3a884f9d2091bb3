//! # postc runtime
//!
//! Executes a post IR over a toolpath event stream and writes the NC
//! program. The runtime reads only IR types: it never sees a dialect's
//! syntax tree.
//!
//! - [`number`]: the exact, allocation-free number formatter;
//! - [`machine`]: machine and job state in output units, and the quantities
//!   posts print;
//! - [`geometry`]: arcs, helices, linearization, radius-exact centres;
//! - [`engine`]: runs handler bodies (the hot path: literal bytes and
//!   formatted variables straight into the output buffer) and keeps modal
//!   memory, block numbers and warnings; `interp` runs the rest of the
//!   statement language;
//! - [`prepare`]: a post's IR made into the runtime's [`exec::Code`]:
//!   constants folded, and the fast path that builds a function's text
//!   straight in the output (the output-buffer operations are the
//!   runtime's, not the IR's);
//! - [`sections`]: which section prints each event (Vectric rules, CIMCO);
//! - [`apt_words`]: events as APT records calling the handler of each
//!   major word (VcPost posts, the `postp` controllers);
//! - [`calls`]: runs a post over Sub calls instead of events (VcPost
//!   probe-cycle tables and composites event files), with [`call_tables`]
//!   the functions whose values a call's lists give;
//! - [`script_host`]: the trait through which functions kept as scripts
//!   run; the host itself comes from the caller ([`RunOptions::script_host`]);
//! - [`units`]: every event's lengths and feeds in the post's output units,
//!   before it is dispatched;
//! - [`lathe`]: the `lathe` option, turning events into the runtime's plane;
//! - [`js`]: JavaScript's conversions, which the IR's builtins name;
//! - [`regex`]: JavaScript's regular expressions (translated onto the
//!   `regex` crate, linear in the text) and the text methods that take
//!   them, for the interpreter and the CIMCO script host alike;
//! - [`output`]: the [`output::Sink`] trait the caller's sinks implement
//!   (files, standard output: the command line), the memory and discard
//!   sinks, and the names of tape-split parts;
//! - [`clock`]: dates and times as posts print them, from the Unix time the
//!   caller passes as [`RunOptions::now`].
//!
//! The runtime touches neither the file system, the clock nor the terminal:
//! output goes to a sink, and "now" is an input.
//!
//! [`run`] pulls events one at a time from an [`EventSource`], so memory
//! stays flat whatever the toolpath's length.

pub mod apt_words;
mod blocks;
pub mod call_tables;
pub mod calls;
pub mod clock;
pub mod engine;
pub mod exec;
pub mod geometry;
mod interp;
pub use postc_ir::js;
pub mod lathe;
pub mod machine;
pub mod number;
pub mod outline;
pub mod output;
pub mod prepare;
pub mod profile;
pub mod regex;
pub mod script_host;
pub mod sections;
mod slots;
pub mod trace;
pub mod units;
pub mod value;

use postc_ir::event::FileInfo;
use postc_ir::{Diagnostic, Dispatch, EventSource, Post};

pub use engine::Engine;
pub use output::{Finished, Output};

/// Options of one run that do not come from the post.
#[derive(Default)]
pub struct RunOptions {
    /// Arc words from the printed start and end points (`--exact-arcs`).
    pub exact_arcs: bool,
    /// `[DATE]` and `[TIME]`, overriding the job's.
    pub date: Option<String>,
    pub time: Option<String>,
    /// Now, as a Unix time in seconds: what `[DATE]` and `[TIME]` print (in
    /// UTC) when neither the job nor `date`/`time` give them. The runtime
    /// never reads the clock; the caller does (the command line: the system
    /// clock, or `SOURCE_DATE_EPOCH`). `None` prints Thursday, January 1,
    /// 1970, 00:00.
    pub now: Option<i64>,
    /// The output file, overriding the job's (`-o`).
    pub file: Option<FileInfo>,
    /// Chord tolerance in mm for linearized arcs, overriding the post's.
    pub arc_tolerance: Option<f64>,
    /// Called with the number of events handled, every 65536 events.
    pub progress: Option<Box<dyn FnMut(u64)>>,
    /// Builds the host that runs the post's scripts, if it has any
    /// (`postc_driver::script_host` picks it by the scripts' language).
    pub script_host: Option<script_host::ScriptHostFactory>,
    /// Called with the provenance of every block written (`--trace`).
    pub trace: Option<trace::TraceSink>,
    /// Told of every handler run and function call (`bench --profile`).
    pub profile: Option<Box<dyn profile::CallObserver>>,
    /// Post properties the user sets (`--set property.NAME=VALUE`), by
    /// name, in order: a Fusion post's `properties`, as Fusion's post
    /// dialog and `post --property` set them (`POST_PROPERTIES`).
    pub properties: Vec<(String, String)>,
    /// Run the post's code as its IR says it, with none of
    /// [`prepare`]'s passes (folding, inlining, fused words, ...): what the
    /// differential tests compare the prepared run with.
    pub unprepared: bool,
}

/// What a successful run produced.
pub struct RunReport {
    pub warnings: Vec<Diagnostic>,
    pub events: u64,
    pub blocks: u64,
    pub bytes: u64,
    pub output: Finished,
}

/// Runs `post` over the events of `source` into `out`. On any error the
/// output is dropped (files are never created) and every diagnostic so far
/// is returned.
pub fn run<S: EventSource + ?Sized>(
    post: &Post,
    source: &mut S,
    out: Output,
    mut options: RunOptions,
) -> Result<RunReport, Vec<Diagnostic>> {
    let mut post_storage;
    let mut post = post;
    if let Some(tol) = options.arc_tolerance {
        post_storage = post.clone();
        post_storage.options.arc_tolerance = tol;
        post = &post_storage;
    }
    let output_units = post.output_units();
    let mut conversion = units::Conversion::new(output_units);
    let mut machine =
        machine::MachineState::new(output_units, post.options.spindle_speed_range, post.options.rotary_wrap);
    machine.date = options.date.take().unwrap_or_default();
    machine.time = options.time.take().unwrap_or_default();
    (machine.default_date, machine.default_time) = clock::format_utc(options.now.unwrap_or(0));
    if let Some(f) = options.file.take() {
        machine.file_name = f.name;
        machine.file_dir = f.dir;
        machine.file_ext = f.extension;
    }
    machine.properties = serde_json::Value::Object(
        options.properties.iter().map(|(k, v)| (k.clone(), serde_json::Value::String(v.clone()))).collect(),
    )
    .to_string();
    if post.options.reads_ahead
        && let Some(outline) = source.outline()
    {
        let factor = output_units.map_or(1.0, |u| outline.units.factor_to(u));
        machine.outline = outline::to_json(&outline, factor);
    }
    let mut diagnostics = Vec::new();
    // A post that reads ahead holds the next event in hand, the first one
    // before its one-time code runs: its job's units are known there, as
    // Fusion's engine knows the document's before a post's top level
    // (`createFormat({decimals: (unit == MM ? 3 : 4)})`) runs.
    let reads_ahead = post.options.reads_ahead;
    let mut ahead: Option<(postc_ir::Event, postc_ir::diagnostic::Span)> = None;
    if reads_ahead {
        ahead = next_posted(source, &mut diagnostics);
        if let Some((postc_ir::Event::Job(job), _)) = &ahead {
            machine.output_units = conversion.units_for(job);
        }
    }
    let code = if options.unprepared { prepare::unprepared(post) } else { prepare::prepare(post) };
    let mut out = out;
    if post.options.windows_1252_output {
        out.write_windows_1252();
    }
    let mut engine = Engine::new(post, &code, machine, out);
    engine.trace = options.trace.take().map(|sink| Box::new(trace::Tracer::new(sink, post.info.host_file)));
    engine.profile = options.profile.take();
    let mut dispatch: Box<dyn Dispatcher> = match post.info.dispatch {
        Dispatch::Sections => Box::new(sections::SectionDispatch::new(&engine, options.exact_arcs)),
        Dispatch::AptWords => Box::new(apt_words::AptDispatch::new(&engine)),
    };
    let mut events = 0u64;
    let fail = |mut diagnostics: Vec<Diagnostic>, engine: Engine| {
        diagnostics.extend(engine.warnings);
        Err(diagnostics)
    };
    // The caller hands a host when the post needs one: for its scripts, or
    // for the functions of its dialect's API its code calls.
    if let Some(make) = options.script_host {
        match make(&engine) {
            Ok(host) => engine.script_host = Some(host),
            Err(d) => {
                diagnostics.push(d);
                return fail(diagnostics, engine);
            }
        }
    }
    let lathe = post.options.lathe;
    if let Err(d) = engine.init() {
        diagnostics.push(*d);
        return fail(diagnostics, engine);
    }
    let observe = engine.script_host.is_some();
    // A post that reads ahead knows the event after the one it posts
    // (`NEXT_RECORD_MOTION`): the loop holds one event in hand.
    loop {
        // Posts that do not read ahead take each event as it is read.
        let read = if reads_ahead {
            ahead.take().or_else(|| next_posted(source, &mut diagnostics))
        } else {
            source.next_event(&mut diagnostics)
        };
        let Some((mut event, span)) = read else { break };
        if reads_ahead {
            ahead = next_posted(source, &mut diagnostics);
            engine.machine.record_id = events as f64;
            engine.machine.next_record_motion = ahead.as_ref().is_some_and(|(e, _)| e.is_move());
        }
        if postc_ir::diagnostic::has_errors(&diagnostics) {
            return fail(diagnostics, engine);
        }
        // Posts never see FeedRate records ([`next_posted`] skips them for
        // posts that read ahead). Skipped here, in the loop, a Vectric move
        // costs 48 instructions fewer than through `next_posted` (callgrind,
        // `postc bench gcode_mm.pp`: 1,425 against 1,473).
        if matches!(event, postc_ir::Event::FeedRate(_)) {
            continue;
        }
        engine.event_span = span;
        if let Some(t) = engine.trace.as_deref_mut() {
            t.event = Some(events);
            t.event_span = Some(span);
        }
        conversion.convert(&mut event);
        if lathe {
            event = lathe::turn_event(event);
        }
        if observe && let Some(host) = engine.script_host.as_mut() {
            host.observe(&event);
        }
        if let Err(d) = dispatch.event(&mut engine, &event) {
            diagnostics.push(at_event(*d, span));
            return fail(diagnostics, engine);
        }
        events += 1;
        if events & 0xFFFF == 0
            && let Some(p) = options.progress.as_mut()
        {
            p(events);
        }
    }
    if postc_ir::diagnostic::has_errors(&diagnostics) {
        return fail(diagnostics, engine);
    }
    if let Some(t) = engine.trace.as_deref_mut() {
        (t.event, t.event_span) = (None, None);
    }
    if let Err(d) = dispatch.finish(&mut engine) {
        diagnostics.push(*d);
        return fail(diagnostics, engine);
    }
    diagnostics.append(&mut engine.warnings);
    let blocks = engine.out.blocks();
    let bytes = engine.out.bytes();
    let tape = post.options.tape_splitting.as_ref();
    match engine.out.finish(tape) {
        Ok(output) => Ok(RunReport { warnings: diagnostics, events, blocks, bytes, output }),
        Err(e) => {
            diagnostics.push(Diagnostic::error("IO003", format!("could not write the program: {e}")));
            Err(diagnostics)
        }
    }
}

/// An error of the post while it handles an event, with the event's
/// record in the toolpath when it names no place there: which record the
/// post stopped at (a Fusion post's "Spindle speed out of range." at the
/// CL file's tool change that gave no SPINDL).
#[cold]
fn at_event(d: Diagnostic, span: postc_ir::diagnostic::Span) -> Diagnostic {
    if crate::interp::is_setting_error(&d) {
        return d;
    }
    if span.end > span.start && !d.labels.iter().any(|l| l.span.file == span.file) {
        d.also(span, "while posting this toolpath record")
    } else {
        d
    }
}

/// The next event a post sees: what a FEDRAT record said is for toolpath
/// readers (postp's transform); posts see the feed on the moves.
fn next_posted<S: EventSource + ?Sized>(
    source: &mut S,
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<(postc_ir::Event, postc_ir::diagnostic::Span)> {
    loop {
        match source.next_event(diagnostics)? {
            (postc_ir::Event::FeedRate(_), _) => continue,
            read => return Some(read),
        }
    }
}

/// How events reach a post's handlers.
trait Dispatcher {
    fn event(&mut self, engine: &mut Engine, event: &postc_ir::Event) -> Result<(), Box<Diagnostic>>;
    fn finish(&mut self, engine: &mut Engine) -> Result<(), Box<Diagnostic>>;
}

impl Dispatcher for sections::SectionDispatch {
    #[inline]
    fn event(&mut self, engine: &mut Engine, event: &postc_ir::Event) -> Result<(), Box<Diagnostic>> {
        sections::SectionDispatch::event(self, engine, event)
    }

    fn finish(&mut self, engine: &mut Engine) -> Result<(), Box<Diagnostic>> {
        sections::SectionDispatch::finish(self, engine)
    }
}

impl Dispatcher for apt_words::AptDispatch {
    fn event(&mut self, engine: &mut Engine, event: &postc_ir::Event) -> Result<(), Box<Diagnostic>> {
        apt_words::AptDispatch::event(self, engine, event.clone())
    }

    fn finish(&mut self, engine: &mut Engine) -> Result<(), Box<Diagnostic>> {
        apt_words::AptDispatch::finish(self, engine)
    }
}

/// What the tests of this crate's modules (`tests/modules/`) reach that is
/// not its interface: nothing else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod engine {
        pub use crate::engine::{KeptWord, is_modal, number_word, put_number, put_text};
    }
    pub mod interp {
        pub use crate::interp::{Flow, move_back, texts_empty};
    }
    pub mod interp_ops {
        pub use crate::interp::ops::{binary, builtin, compare, format_picture};
    }
    pub mod js {
        pub use crate::js::parse_short_decimal;
    }
    pub mod number {
        pub use crate::number::push_integer;
    }
    pub mod output {
        pub use crate::output::c_format;
    }
    pub mod prepare_emit_marks {
        pub use crate::prepare::emit::marks::drop_truncates;
    }
    pub mod prepare_fresh {
        pub use crate::prepare::fresh::start_nulls;
    }
    pub mod prepare_fuse {
        pub use crate::prepare::fuse::{expressions, runs, stmts};
    }
    pub mod prepare_locals {
        pub use crate::prepare::locals::tidy;
    }
    pub mod prepare_splice {
        pub use crate::prepare::splice::small_functions;
    }
    pub mod prepare_unshift {
        pub use crate::prepare::unshift::{block_numbers, count_is_positive, count_is_zero};
    }
    pub mod value {
        pub use crate::value::Repr;
    }
}
