//! The reader's state machine: what the CL records said so far (position,
//! feed, spindle, tool, open toolpath, circle, cycle, units) and the events
//! each record becomes. Moves are in `motion.rs`; this module has the rest
//! of the record handlers, the tool bookkeeping and the flush that puts
//! held events out in contract order (see `window.rs`).

use std::collections::VecDeque;

use postc_ir::diagnostic::{Diagnostic, FileId, Span};
use postc_ir::event::{Arg as EventArg, Command, Event, Job, Point, Spindle, Tool, ToolpathStart};
use postc_ir::units::Units;

use crate::circle::{CircleSpec, V3};
use crate::cycle::CycleSpec;
use crate::diagnostics as diag;
use crate::machine_records::{self, FeedSpec, ToolLoad};
use crate::window::{LIMIT, Window};
use crate::words::{Problem, Rec};

/// Whether a toolpath is open, and who opened it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Toolpath {
    None,
    /// `TOOL PATH` or `OPFEATSTART`.
    Explicit,
    /// Opened by the reader before moves outside any toolpath.
    Synthesized,
}

/// What the file said about the job before its first moves.
#[derive(Default)]
pub(crate) struct JobDraft {
    pub units: Option<Units>,
    pub feed_units: Option<Units>,
    pub part: Option<String>,
    pub home: Option<Point>,
    pub product: Option<String>,
    pub span: Option<Span>,
}

/// A drilling cycle between `CYCLE/kind` and `CYCLE/OFF`.
pub(crate) struct ActiveCycle {
    pub spec: CycleSpec,
    pub span: Span,
    /// Height of the holes the last `DrillCycle` event was made for.
    pub header_z: Option<f64>,
    /// Where the tool stood when the cycle began.
    pub clearance_z: Option<f64>,
}

/// The state of the reader between records.
pub(crate) struct Core {
    pub file: FileId,
    pub out: VecDeque<(Event, Span)>,
    pub window: Window,
    /// `Some` until the `Job` event is out.
    pub job: Option<JobDraft>,
    pub units: Units,
    /// The job's units are settled (UNITS, or a feed unit, was read).
    pub units_known: bool,
    pub pos: Option<V3>,
    pub axis: Option<V3>,
    pub rapid: bool,
    pub feed: Option<FeedSpec>,
    pub spindle: Spindle,
    pub circle: Option<(CircleSpec, Span)>,
    pub indirv: Option<V3>,
    pub cycle: Option<ActiveCycle>,
    pub toolpath: Toolpath,
    pub tool_number: u32,
    pub tool_name: String,
    pub cutter_diameter: f64,
    pub last_tool: Option<Tool>,
    /// A tool load in the window: what, where, which record.
    pub pending_tool: Option<(ToolLoad, usize, Span)>,
    /// The cutter changed (CUTTER/TLDATA/TOOL PATH) without a load, at this window index.
    pub cutter_changed: Option<(usize, Span)>,
    /// The first spindle speed of the window, for the tool.
    pub window_speed: Option<f64>,
    pub warned_nurbs: bool,
    pub warned_per_rev: bool,
    /// CL025 was said.
    pub warned_no_feed: bool,
    /// FINI was read.
    pub ended: bool,
    /// The last record read closed a toolpath (END-OF-PATH, OPFEATEND):
    /// a file that ends there is whole without FINI (NX CLSF files).
    pub closed_at_end: bool,
}

/// How the reader goes on after a record.
pub(crate) enum Flow {
    Continue,
    /// The file is an APT part program; why, at which span.
    PartProgram(&'static str, Span),
}

pub(crate) fn text_event(word: &str, text: String) -> Event {
    Event::Command(Command { word: word.to_string(), args: vec![EventArg::Text(text)] })
}

impl Core {
    pub fn new(file: FileId) -> Core {
        Core {
            file,
            out: VecDeque::with_capacity(64),
            window: Window::default(),
            job: Some(JobDraft::default()),
            units: Units::Mm,
            units_known: false,
            pos: None,
            axis: None,
            rapid: false,
            feed: None,
            spindle: Spindle::default(),
            circle: None,
            indirv: None,
            cycle: None,
            toolpath: Toolpath::None,
            tool_number: 0,
            tool_name: String::new(),
            cutter_diameter: 0.0,
            last_tool: None,
            pending_tool: None,
            cutter_changed: None,
            window_speed: None,
            warned_nurbs: false,
            warned_per_rev: false,
            warned_no_feed: false,
            ended: false,
            closed_at_end: false,
        }
    }

    /// Holds a non-move event in the window.
    pub fn emit(&mut self, event: Event, span: Span) {
        if let Some(job) = &mut self.job {
            job.span.get_or_insert(span);
        }
        self.window.push(event, span);
        if self.window.len() - self.window.notes >= LIMIT {
            self.flush();
        }
    }

    /// Emits a move (or a drill cycle event), opening a toolpath if none is
    /// open, and flushes the window when the header is settled.
    /// Holds an event that records what the file said without changing
    /// what the others mean (`FeedRate`): it neither dates the `Job` nor
    /// counts toward a forced flush, so every other event comes out as it
    /// would without it.
    pub fn note(&mut self, event: Event, span: Span) {
        self.window.push(event, span);
        self.window.notes += 1;
    }

    pub fn emit_motion(&mut self, event: Event, span: Span) {
        if self.toolpath == Toolpath::None {
            self.toolpath = Toolpath::Synthesized;
            self.window.synth_before = Some(self.window.len());
        }
        if self.job.is_none()
            && self.window.is_empty()
            && self.window.synth_before.is_none()
            && self.pending_tool.is_none()
            && self.cutter_changed.is_none()
        {
            self.out.push_back((event, span));
            return;
        }
        self.emit(event, span);
        if self.units_known || self.job.is_none() {
            self.flush();
        }
    }

    /// Puts every held event out, in contract order.
    pub fn flush(&mut self) {
        self.place_tool();
        if self.window.synth_before.is_some() {
            let span = self
                .window
                .synth_before
                .and_then(|i| self.window.events.get(i))
                .map_or(Span::new(self.file, 0, 0), |e| e.1);
            self.window.place_synth(Event::ToolpathStart(ToolpathStart::default()), span);
        }
        if let Some(job) = self.job.take() {
            self.units = job.units.or(job.feed_units).unwrap_or(Units::Mm);
            let span = job.span.unwrap_or(Span::new(self.file, 0, 0));
            let event =
                Job { units: self.units, part: job.part, home: job.home, product: job.product, ..Job::default() };
            self.out.push_back((Event::Job(Box::new(event)), Span::new(self.file, span.start, span.start)));
        }
        self.window.drain_into(&mut self.out);
    }

    /// Inserts the `Tool` event for a load or a cutter change in the window.
    fn place_tool(&mut self) {
        let (load, at, span, forced) = match (self.pending_tool.take(), self.cutter_changed.take()) {
            (Some((load, at, span)), _) => (load, at, span, true),
            (None, Some((at, span))) => (ToolLoad { number: self.tool_number, ..ToolLoad::default() }, at, span, false),
            (None, None) => return,
        };
        let speed = self.window_speed.take().or(self.last_tool.as_ref().map(|t| t.spindle_speed)).unwrap_or(0.0);
        let tool = Tool {
            number: load.number,
            name: self.tool_name.clone(),
            diameter: self.cutter_diameter,
            spindle_speed: speed,
            length_offset: load.length_offset.filter(|&h| h != load.number),
            diameter_offset: load.diameter_offset.filter(|&d| d != load.number),
            load: forced.then(|| {
                Box::new(postc_ir::event::ToolLoad {
                    length_offset: load.length_offset,
                    diameter_offset: load.diameter_offset,
                })
            }),
            ..Tool::default()
        };
        let same = self
            .last_tool
            .as_ref()
            .is_some_and(|t| t.number == tool.number && t.name == tool.name && t.diameter == tool.diameter);
        if forced || !same {
            let at = self.window.tool_position(at);
            self.window.insert(at, Event::Tool(tool.clone()), span);
            self.last_tool = Some(tool);
        }
    }

    /// Ends the toolpath the reader opened, before a tool change.
    fn end_synthesized_toolpath(&mut self, span: Span) {
        if self.toolpath == Toolpath::Synthesized {
            if self.window.synth_before.is_some() {
                self.place_tool();
                let at = self.window.synth_before.and_then(|i| self.window.events.get(i)).map_or(span, |e| e.1);
                self.window.place_synth(Event::ToolpathStart(ToolpathStart::default()), at);
            }
            self.window.push(Event::ToolpathEnd, span);
            self.toolpath = Toolpath::None;
        }
    }

    pub(crate) fn note_units(&mut self, units: Option<Units>, from_feed: bool) {
        if let (Some(job), Some(u)) = (&mut self.job, units) {
            if from_feed {
                job.feed_units.get_or_insert(u);
            } else {
                job.units = Some(u);
            }
            self.units = job.units.or(job.feed_units).unwrap_or(Units::Mm);
            self.units_known = true;
        }
    }

    pub(crate) fn units_record(&mut self, units: Units, span: Span, diags: &mut Vec<Diagnostic>) {
        if self.job.is_some() {
            self.note_units(Some(units), false);
        } else if units != self.units {
            diags.push(diag::late_units(span));
        }
    }

    pub(crate) fn set_cutter(&mut self, diameter: f64, span: Span) {
        if diameter != self.cutter_diameter || self.last_tool.is_none() {
            self.cutter_diameter = diameter;
            if self.pending_tool.is_none() {
                self.cutter_changed.get_or_insert((self.window.len(), span));
            }
        }
    }

    pub(crate) fn tool_load(&mut self, rec: &Rec<'_>, skip: usize, diags: &mut Vec<Diagnostic>) -> Result<(), Problem> {
        let span = rec.span();
        let mut ignored = |i| diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "tool load"));
        let load = machine_records::parse_tool_load(rec, skip, &mut ignored)?;
        self.end_synthesized_toolpath(span);
        if self.pending_tool.is_some() {
            self.place_tool();
        }
        self.cutter_changed = None;
        self.tool_number = load.number;
        self.axis = None;
        self.pending_tool = Some((load, self.window.len(), span));
        Ok(())
    }

    /// A `$$->` comment that Creo writes for a record it did not output:
    /// the cutter diameter is taken from `CUTTER`.
    pub fn echoed_cutter(&mut self, rec: &Rec<'_>) {
        if let Some(d) = machine_records::cutter_diameter(rec) {
            self.set_cutter(d, rec.span());
        }
    }

    pub fn start_toolpath(&mut self, name: String, span: Span, diags: &mut Vec<Diagnostic>) {
        self.drop_circle(Some(span), diags);
        self.close_cycle(Some(span), diags);
        if self.toolpath != Toolpath::None {
            if self.toolpath == Toolpath::Synthesized && self.window.synth_before.is_some() {
                self.end_synthesized_toolpath(span);
            } else {
                self.emit(Event::ToolpathEnd, span);
            }
        }
        self.toolpath = Toolpath::Explicit;
        self.emit(Event::ToolpathStart(ToolpathStart { name, notes: String::new(), ..ToolpathStart::default() }), span);
    }

    pub fn end_toolpath(&mut self, span: Span, diags: &mut Vec<Diagnostic>) {
        self.closed_at_end = true;
        if self.toolpath != Toolpath::Explicit {
            diags.push(diag::stray_end_of_path(span));
        }
        if self.toolpath == Toolpath::None {
            return;
        }
        self.drop_circle(Some(span), diags);
        self.close_cycle(Some(span), diags);
        if self.toolpath == Toolpath::Synthesized {
            self.end_synthesized_toolpath(span);
        } else {
            self.emit(Event::ToolpathEnd, span);
            self.toolpath = Toolpath::None;
        }
    }

    /// Closes what is open at FINI (`at`) or at the end of the file (`None`,
    /// with `end` the empty span at the end of the file).
    pub fn finish(&mut self, at: Option<Span>, end: Span, diags: &mut Vec<Diagnostic>) {
        self.drop_circle(at, diags);
        if let Some(cycle) = self.cycle.take() {
            diags.push(diag::open_cycle(cycle.span, at));
            if cycle.header_z.is_some() {
                self.emit(Event::DrillEnd, at.unwrap_or(end));
            }
        }
        if self.toolpath != Toolpath::None {
            let span = at.unwrap_or(end);
            if self.toolpath == Toolpath::Synthesized {
                self.end_synthesized_toolpath(span);
            } else {
                self.emit(Event::ToolpathEnd, span);
            }
            self.toolpath = Toolpath::None;
        }
    }

    /// Ends an open cycle that no CYCLE/OFF ended.
    pub fn close_cycle(&mut self, at: Option<Span>, diags: &mut Vec<Diagnostic>) {
        if let Some(cycle) = self.cycle.take() {
            diags.push(diag::open_cycle(cycle.span, at));
            if cycle.header_z.is_some() {
                self.emit(Event::DrillEnd, at.unwrap_or(cycle.span));
            }
        }
    }

    /// Product line of a Creo `$$*` header comment.
    pub fn product(&mut self, text: &str) {
        if let Some(job) = &mut self.job {
            job.product.get_or_insert_with(|| text.trim().to_string());
        }
    }
}
