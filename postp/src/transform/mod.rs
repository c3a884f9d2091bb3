//! The `postp` event transform: sits between the CL reader and the
//! runtime, and turns the reader's events into what the controller posts
//! expect.
//!
//! - It computes the motions the seed says the post processor computes and
//!   the CL file does not hold (RETRCT, CLRSRF/NOW, LETTER) as ordinary
//!   `Rapid` and `Feed` events, and applies TRANS and ROTABL's cylindrical
//!   mapping to every position on the way out (`motion.rs`).
//! - It checks every postp word's arguments and the machine it is used on
//!   (lathe-only and mill-only words), with diagnostics at the record.
//! - It gives each postp word to the post as a `Command` with fixed,
//!   normalized arguments (`words.rs`; the table is in `docs/apt.md`), also
//!   for the records the reader turns into events (SPINDL, COOLNT, CUTCOM,
//!   DELAY, LOADTL), from what the events keep of the record as written:
//!   a `Tool`'s `load` (LOADTL or only CUTTER, offsets as given), a
//!   `Coolant`'s placement (NOW, NEXT) and the reader's `FeedRate` events
//!   (the FEDRAT unit). It never reads the CL file itself.
//!
//! Nothing here formats output: the post does that.

mod motion;
mod words;

use std::collections::{HashSet, VecDeque};

use postc_ir::event::{Arg, Command, CompSide, Coolant, CoolantAt, CoolantChange, Event, FeedRate};
use postc_ir::{Diagnostic, EventSource, Span, Units};

use crate::controller::Kind;
use crate::letter::Letter;
use crate::options::RetractZ;

pub use motion::Mapping;

/// Diagnostic codes of `postp`.
pub mod codes {
    pub const NO_CL: &str = postc_ir::codes::PX001.code;
    pub const NO_MACHIN: &str = postc_ir::codes::PX002.code;
    pub const UNKNOWN_MACHIN: &str = postc_ir::codes::PX003.code;
    pub const BAD_AXIS_TYPE: &str = postc_ir::codes::PX004.code;
    pub const BAD_OPTIONS: &str = postc_ir::codes::PX005.code;
    pub const POST_FAILED: &str = postc_ir::codes::PX006.code;
    pub const LATHE_ONLY: &str = postc_ir::codes::PX010.code;
    pub const MILL_ONLY: &str = postc_ir::codes::PX011.code;
    pub const BAD_ARGS: &str = postc_ir::codes::PX012.code;
    pub const MACHIN_NOT_FIRST: &str = postc_ir::codes::PX013.code;
    pub const IGNORED: &str = postc_ir::codes::PX014.code;
    pub const POSITION_UNKNOWN: &str = postc_ir::codes::PX015.code;
    pub const BAD_PLANE: &str = postc_ir::codes::PX016.code;
    pub const DWELL_REVS: &str = postc_ir::codes::PX017.code;
    pub const LETTER: &str = postc_ir::codes::PX018.code;
    pub const AXIS_IGNORED: &str = postc_ir::codes::PX019.code;
    pub const NO_SUCH_AXIS: &str = postc_ir::codes::PX020.code;
    pub const COOLANT: &str = postc_ir::codes::PX021.code;
    pub const CYCLE_MODE: &str = postc_ir::codes::PX022.code;
}

/// What the transform needs to know about the machine.
#[derive(Clone, Debug)]
pub struct Machine {
    pub kind: Kind,
    pub name: &'static str,
    /// Rotary axes from MACHIN's axis type.
    pub axes: &'static [char],
    pub retractz: RetractZ,
}

/// The transform: an [`EventSource`] over the CL reader's events.
pub struct Transform<S> {
    inner: S,
    machine: Machine,
    queue: VecDeque<(Event, Span)>,
    /// The span of the event being handled.
    span: Span,
    /// The tool tip in the CL file's coordinates, when known.
    pos: Option<[f64; 3]>,
    trans: [f64; 3],
    clearp: Option<f64>,
    /// CLRSRF plane: unit normal and distance.
    clrsrf: Option<([f64; 3], f64)>,
    mapping: Option<Mapping>,
    /// Absolute A, B, C angles.
    angles: [f64; 3],
    letter: Option<(Letter, Span)>,
    incremental: bool,
    /// Spindle speed in rpm when known (not under constant surface speed).
    rpm: Option<f64>,
    /// The last FEDRAT as written (the reader's `FeedRate` events).
    fedrat: Option<FeedRate>,
    /// The feed mode last given to the post: per revolution or not.
    per_rev: Option<bool>,
    units: Units,
    warned: HashSet<String>,
    ended: bool,
}

impl<S: EventSource> Transform<S> {
    pub fn new(inner: S, machine: Machine) -> Transform<S> {
        let lathe = machine.kind == Kind::Lathe;
        Transform {
            inner,
            machine,
            queue: VecDeque::new(),
            span: Span::default(),
            pos: None,
            trans: [0.0; 3],
            clearp: None,
            clrsrf: None,
            mapping: None,
            angles: [0.0; 3],
            letter: None,
            incremental: false,
            rpm: None,
            fedrat: None,
            // The default startup strings put mills in feed per minute and
            // lathes in feed per revolution.
            per_rev: Some(lathe),
            units: Units::Mm,
            warned: HashSet::new(),
            ended: false,
        }
    }

    fn push(&mut self, event: Event) {
        self.queue.push_back((event, self.span));
    }

    /// Gives the post a normalized word.
    fn command(&mut self, word: &str, args: Vec<Arg>) {
        self.push(Event::Command(Command { word: word.into(), args }));
    }

    fn error(&self, diags: &mut Vec<Diagnostic>, code: &'static str, message: String, label: &str) {
        diags.push(Diagnostic::error(code, message).at(self.span, label.to_string()));
    }

    fn warn_once(&mut self, diags: &mut Vec<Diagnostic>, key: &str, d: Diagnostic) {
        if self.warned.insert(key.to_string()) {
            diags.push(d.at(self.span, "here"));
        }
    }

    /// A lathe-only or mill-only word on the wrong machine: an error.
    fn needs(&self, kind: Kind, word: &str, diags: &mut Vec<Diagnostic>) -> bool {
        if self.machine.kind == kind {
            return true;
        }
        let (code, what, other) = match kind {
            Kind::Lathe => (codes::LATHE_ONLY, "lathe", "mill"),
            Kind::Mill => (codes::MILL_ONLY, "mill", "lathe"),
        };
        self.error(
            diags,
            code,
            format!("{word} is a {what} word, and MACHIN/{} is a {other}", self.machine.name),
            "not on this machine",
        );
        false
    }

    /// Handles one event of the reader.
    fn event(&mut self, event: Event, diags: &mut Vec<Diagnostic>) {
        match event {
            Event::Job(mut job) => {
                self.units = job.units;
                job.part = None;
                job.file = Default::default();
                self.push(Event::Job(job));
            }
            Event::Tool(tool) => {
                // A tool only described (CUTTER, TLDATA) is no tool change.
                let Some(load) = tool.load.as_deref().copied() else {
                    return;
                };
                if self.needs(Kind::Mill, "LOADTL", diags) {
                    // The event leaves out offsets equal to the tool number;
                    // the load as written says whether they were given.
                    let (h, d) = (load.length_offset, load.diameter_offset);
                    let reg = |v: Option<u32>, e: Option<u32>| Arg::Number(v.or(e).map_or(-1.0, f64::from));
                    let args = vec![
                        Arg::Number(f64::from(tool.number)),
                        reg(h, tool.length_offset),
                        reg(d, tool.diameter_offset),
                    ];
                    self.command("LOADTL", args);
                }
            }
            Event::ToolpathStart(_) | Event::ToolpathEnd | Event::JetOn | Event::JetOff | Event::Power(_) => {}
            Event::Rapid(m) => {
                self.tool_axis(m.tool_axis, diags);
                self.move_to(true, [m.x, m.y, m.z], None, diags);
            }
            Event::Feed(m) => {
                self.tool_axis(m.tool_axis, diags);
                self.move_to(false, [m.x, m.y, m.z], m.feed, diags);
            }
            Event::Arc(a) => self.arc(a, diags),
            Event::Dwell(d) => {
                let seconds = if d.revolutions {
                    match self.rpm {
                        Some(rpm) if rpm > 0.0 => d.seconds * 60.0 / rpm,
                        _ => {
                            diags.push(
                                Diagnostic::warning(codes::DWELL_REVS, "a dwell in revolutions needs the spindle speed in RPM")
                                    .at(self.span, "no RPM known here")
                                    .note("the dwell is written as that many seconds, which is at least as long at 60 RPM or more"),
                            );
                            d.seconds
                        }
                    }
                } else {
                    d.seconds
                };
                self.command("DELAY", vec![Arg::Number(seconds)]);
            }
            Event::SpindleOn(s) => self.spindle(s, diags),
            Event::SpindleOff => {
                let args = vec![word("OFF"), Arg::Number(0.0), word("RPM"), word("CLW"), Arg::Number(0.0)];
                self.command("SPINDL", args);
            }
            Event::Coolant(c) => self.coolant(c, diags),
            Event::CutterComp(c) => {
                let side = match c.side {
                    CompSide::Left => "LEFT",
                    CompSide::Right => "RIGHT",
                    CompSide::Off => "OFF",
                };
                self.command("CUTCOM", vec![word(side), Arg::Number(c.register.map_or(-1.0, f64::from))]);
            }
            Event::DrillCycle(c) => self.cycle(c, diags),
            Event::DrillPoint(p) => self.hole(p),
            Event::DrillEnd => self.push(Event::DrillEnd),
            Event::Comment(t) => {
                let text = t.text.clone();
                self.push(Event::Comment(t));
                if let Some((letter, _)) = self.letter.take() {
                    self.engrave(letter, &text, diags);
                }
            }
            Event::Insert(t) => self.push(Event::Insert(t)),
            Event::Command(c) => self.word(c, diags),
            Event::End => self.end(diags),
            Event::FeedRate(f) => self.fedrat = Some(f),
        }
    }

    fn end(&mut self, diags: &mut Vec<Diagnostic>) {
        if self.ended {
            return;
        }
        self.ended = true;
        if let Some((_, span)) = self.letter.take() {
            diags.push(
                Diagnostic::warning(codes::LETTER, "LETTER engraves the next PPRINT, and none followed")
                    .at(span, "nothing was engraved"),
            );
        }
        self.push(Event::End);
    }

    fn spindle(&mut self, s: postc_ir::event::Spindle, diags: &mut Vec<Diagnostic>) {
        let speed = s.speed.unwrap_or(0.0);
        if s.css && !self.needs(Kind::Lathe, "SPINDL/..,SFM (constant surface speed)", diags) {
            return;
        }
        let mut max = s.max_rpm.unwrap_or(0.0);
        if max > 0.0 && self.machine.kind == Kind::Mill {
            self.warn_once(
                diags,
                "MAXRPM",
                Diagnostic::warning(codes::IGNORED, "MAXRPM applies to lathes only; ignored on a mill"),
            );
            max = 0.0;
        }
        self.rpm = if s.css { None } else { Some(speed) };
        let args = vec![
            word("ON"),
            Arg::Number(speed),
            word(if s.css { "SFM" } else { "RPM" }),
            word(if s.ccw { "CCLW" } else { "CLW" }),
            Arg::Number(max),
        ];
        self.command("SPINDL", args);
    }

    fn coolant(&mut self, change: CoolantChange, diags: &mut Vec<Diagnostic>) {
        let c = change.coolant;
        let kind = match c {
            Coolant::Off => "OFF",
            Coolant::Mist => "MIST",
            Coolant::Flood => "FLOOD",
            Coolant::Through | Coolant::Air => {
                let what = if c == Coolant::Air { "AIR" } else { "THRU" };
                self.warn_once(
                    diags,
                    what,
                    Diagnostic::warning(
                        codes::COOLANT,
                        format!("postp knows COOLNT MIST, FLOOD, ON and OFF; {what} is taken as FLOOD"),
                    ),
                );
                "FLOOD"
            }
        };
        let place = if change.at == Some(CoolantAt::Now) {
            "NOW"
        } else if change.at == Some(CoolantAt::Next) || c == Coolant::Off {
            "NEXT"
        } else {
            "Z"
        };
        self.command("COOLNT", vec![word(kind), word(place)]);
    }

    /// Multi-axis tool axes are not turned into rotary positions.
    fn tool_axis(&mut self, axis: Option<[f64; 3]>, diags: &mut Vec<Diagnostic>) {
        if let Some([i, j, k]) = axis
            && (i.abs() > 1e-6 || j.abs() > 1e-6 || (k - 1.0).abs() > 1e-6)
        {
            self.warn_once(
                diags,
                "TOOLAXIS",
                Diagnostic::warning(
                    codes::AXIS_IGNORED,
                    "postp writes 3-axis positions; the tool axis of multi-axis GOTOs is ignored",
                )
                .note("ROTABL positions rotary axes; 5-axis tool-axis output is not implemented"),
            );
        }
    }
}

fn word(w: &str) -> Arg {
    Arg::Word(w.into())
}

impl<S: EventSource> EventSource for Transform<S> {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        loop {
            if let Some(e) = self.queue.pop_front() {
                return Some(e);
            }
            if self.ended {
                return None;
            }
            let before = diagnostics.len();
            let next = self.inner.next_event(diagnostics);
            // The reader warns that a feed per revolution with no spindle
            // speed passes as a feed per minute; postp writes it per
            // revolution (see `feed_of`), so the warning does not apply.
            let new = diagnostics.split_off(before);
            diagnostics.extend(new.into_iter().filter(|d| d.code != "CL019"));
            match next {
                Some((event, span)) => {
                    self.span = span;
                    self.event(event, diagnostics);
                }
                None => self.end(diagnostics),
            }
        }
    }
}
