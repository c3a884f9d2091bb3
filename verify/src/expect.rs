//! The toolpath side: the moves a program must make, read from the event
//! stream into a bounded window, in millimetres.

use std::collections::VecDeque;

use postc_ir::event::{ArcDir, Event, Intent, Plane};
use postc_ir::{Diagnostic, EventSource, Span, Units};

/// What kind of move the toolpath asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Rapid,
    Feed,
    Arc,
}

/// One expected move, in millimetres. `start` is NaN where the toolpath
/// does not say where the move starts (the first move).
#[derive(Clone, Copy, Debug)]
pub struct Expected {
    pub kind: Kind,
    pub start: [f64; 3],
    pub end: [f64; 3],
    pub centre: [f64; 3],
    pub dir: ArcDir,
    pub plane: Plane,
    pub intent: Intent,
    /// mm/min; NaN when the toolpath gives no feed.
    pub feed: f64,
    /// Whether the spindle (or the jet, for jet tools) runs during the move.
    pub powered: bool,
    /// Whether a jet tool (laser, plasma, waterjet) makes the move.
    pub jet: bool,
    /// Whether `feed` is per spindle revolution (mm/rev: the toolpath's
    /// `feed_per_rev`) rather than per minute.
    pub per_rev: bool,
    /// The constant surface speed the spindle runs at (m/min); NaN when
    /// it runs at a fixed rpm.
    pub surface: f64,
    /// The spindle runs only because the tool has a speed: nothing in the
    /// toolpath switches it on, and the post, an APT-word one, starts it
    /// only from the toolpath's spindle records.
    pub implied: bool,
    pub span: Span,
}

impl Expected {
    pub fn cutting(&self) -> bool {
        self.kind != Kind::Rapid
    }
}

/// What verify reads of a toolpath event: the events it reads, each with
/// only the fields it uses, in the toolpath's units. A move is a few words
/// and owns nothing, so a verification running beside the post is handed
/// records ([`Record::of`]) instead of clones of the events.
#[derive(Clone, Debug, PartialEq)]
pub enum Record {
    /// The job's units, material box (min, max) and safe Z.
    Job(Box<JobRecord>),
    Tool {
        cut_feed: f64,
        plunge_feed: f64,
        spindle_speed: f64,
        jet: bool,
        /// A lathe's turning tool: X is the radius, Z along the spindle.
        turning: bool,
    },
    /// A toolpath starts; its feeds are per revolution when `per_rev`.
    Toolpath {
        per_rev: bool,
    },
    /// The spindle starts; `surface`: at constant surface speed (metres
    /// or feet a minute, the toolpath's units), NaN at a fixed rpm.
    SpindleOn {
        surface: f64,
    },
    SpindleOff,
    JetOn,
    JetOff,
    /// A rapid; `rotary`: it has A, B or C values.
    Rapid {
        end: [f64; 3],
        rotary: bool,
    },
    Feed {
        end: [f64; 3],
        intent: Intent,
        feed: Option<f64>,
        rotary: bool,
    },
    Arc {
        end: [f64; 3],
        centre: [f64; 3],
        dir: ArcDir,
        plane: Plane,
        intent: Intent,
        feed: Option<f64>,
    },
    /// Text the toolpath asks to be written as it is.
    Insert(Box<str>),
    DrillCycle {
        retract: f64,
        reference: f64,
        depth: f64,
        feed: Option<f64>,
    },
    DrillPoint {
        x: f64,
        y: f64,
    },
    DrillEnd,
}

/// The job data of a [`Record::Job`], in the toolpath's units.
#[derive(Clone, Debug, PartialEq)]
pub struct JobRecord {
    pub units: Units,
    pub material: Option<([f64; 3], [f64; 3])>,
    pub safe_z: Option<f64>,
}

impl Record {
    /// The record of an event; `None` for the events verify does not read.
    #[inline]
    pub fn of(event: &Event) -> Option<Record> {
        Some(match event {
            Event::Rapid(m) => {
                Record::Rapid { end: [m.x, m.y, m.z], rotary: m.a.is_some() || m.b.is_some() || m.c.is_some() }
            }
            Event::Feed(m) => Record::Feed {
                end: [m.x, m.y, m.z],
                intent: m.intent,
                feed: m.feed,
                rotary: m.a.is_some() || m.b.is_some() || m.c.is_some(),
            },
            Event::Arc(a) => Record::Arc {
                end: [a.x, a.y, a.z],
                centre: [a.cx, a.cy, a.cz],
                dir: a.dir,
                plane: a.plane,
                intent: a.intent,
                feed: a.feed,
            },
            Event::Job(job) => Record::Job(Box::new(JobRecord {
                units: job.units,
                material: job.material.as_ref().map(|m| ([m.min.x, m.min.y, m.min.z], [m.max.x, m.max.y, m.max.z])),
                safe_z: job.safe_z,
            })),
            Event::Tool(t) => Record::Tool {
                cut_feed: t.cut_feed,
                plunge_feed: t.plunge_feed,
                spindle_speed: t.spindle_speed,
                jet: t.jet,
                turning: t.turning,
            },
            Event::ToolpathStart(t) => Record::Toolpath { per_rev: t.feed_per_rev },
            Event::SpindleOn(s) => {
                Record::SpindleOn { surface: if s.css { s.speed.unwrap_or(f64::NAN) } else { f64::NAN } }
            }
            Event::SpindleOff => Record::SpindleOff,
            Event::JetOn => Record::JetOn,
            Event::JetOff => Record::JetOff,
            Event::Insert(t) => Record::Insert(t.text.as_str().into()),
            Event::DrillCycle(c) => Record::DrillCycle {
                retract: c.retract_plane,
                reference: c.reference_plane,
                depth: c.depth,
                feed: c.feed,
            },
            Event::DrillPoint(p) => Record::DrillPoint { x: p.x, y: p.y },
            Event::DrillEnd => Record::DrillEnd,
            _ => return None,
        })
    }
}

/// A toolpath as records, a batch at a time: [`Record::of`] each event of
/// an [`EventSource`] ([`Records`]), or batches made where the events were
/// read.
pub trait RecordSource {
    /// Replaces `batch` with the next records, each with the span of its
    /// event, at least one; false at the end. Diagnostics of the
    /// toolpath's reader go to `diagnostics`.
    fn next_batch(&mut self, batch: &mut Vec<(Record, Span)>, diagnostics: &mut Vec<Diagnostic>) -> bool;
}

/// The records of an event source's events, read one at a time.
pub struct Records<'a>(pub &'a mut dyn EventSource);

impl RecordSource for Records<'_> {
    fn next_batch(&mut self, batch: &mut Vec<(Record, Span)>, diagnostics: &mut Vec<Diagnostic>) -> bool {
        batch.clear();
        while let Some((event, span)) = self.0.next_event(diagnostics) {
            if let Some(record) = Record::of(&event) {
                batch.push((record, span));
                return true;
            }
        }
        false
    }
}

/// The job data verify uses.
#[derive(Clone, Copy, Debug, Default)]
pub struct JobData {
    /// Material box in mm (min, max).
    pub material: Option<([f64; 3], [f64; 3])>,
    pub safe_z: Option<f64>,
    /// Whether any toolpath move has A/B/C values.
    pub rotary: bool,
}

/// The expected path: a window over the toolpath's moves.
pub struct ExpectedPath<'a> {
    source: &'a mut dyn RecordSource,
    /// The source's latest batch, read up to `at`.
    batch: Vec<(Record, Span)>,
    at: usize,
    window: VecDeque<Expected>,
    done: bool,
    factor: f64,
    pos: [f64; 3],
    cut_feed: f64,
    plunge_feed: f64,
    jet_tool: bool,
    turning_tool: bool,
    /// The current toolpath's feeds are per revolution.
    per_rev: bool,
    /// The constant surface speed, m/min; NaN at a fixed rpm.
    surface: f64,
    /// Whether the toolpath's first tool is a lathe's turning tool, once
    /// its Tool record is read: the program is then a lathe program
    /// (docs/verify.md, "Lathe programs").
    pub lathe: Option<bool>,
    spindle: bool,
    /// The tool has a speed, but the toolpath has not switched the spindle
    /// on (APT-word posts only, [`ExpectedPath::apt_words`]).
    implied: bool,
    jet: bool,
    /// The post is an APT-word one (VcPost milling, postp): the runtime
    /// hands it the toolpath's records as they are, so a tool change does
    /// not start the spindle and a straight move down is fed as its intent
    /// says, not as a plunge.
    pub apt_words: bool,
    /// The current drilling cycle: clearance, reference plane, depth and feed.
    cycle: Option<(f64, f64, f64, Option<f64>)>,
    /// The lines of the toolpath's latest inserts (text it asks to be
    /// written as it is), not yet found in the program; at most [`INSERTS`].
    inserts: VecDeque<String>,
    pub job: JobData,
    /// The lowest Z a toolpath rapid has ended at so far (mm).
    pub min_rapid_z: f64,
    /// The highest Z a toolpath rapid has ended at so far (mm).
    pub max_rapid_z: f64,
    /// Moves read so far.
    pub count: u64,
    /// The reader's diagnostics (bad toolpath lines).
    pub diagnostics: Vec<Diagnostic>,
    scratch: Vec<Diagnostic>,
}

/// How many moves the window holds at most before the program side must consume some.
pub const WINDOW: usize = 512;

/// Insert lines kept at most while they wait to be found in the program.
const INSERTS: usize = 64;

impl<'a> ExpectedPath<'a> {
    pub fn new(source: &'a mut dyn RecordSource) -> ExpectedPath<'a> {
        ExpectedPath {
            source,
            batch: Vec::new(),
            at: 0,
            window: VecDeque::with_capacity(WINDOW),
            done: false,
            factor: 1.0,
            pos: [f64::NAN; 3],
            cut_feed: f64::NAN,
            plunge_feed: f64::NAN,
            jet_tool: false,
            turning_tool: false,
            per_rev: false,
            surface: f64::NAN,
            lathe: None,
            spindle: false,
            implied: false,
            jet: false,
            apt_words: false,
            cycle: None,
            inserts: VecDeque::new(),
            job: JobData::default(),
            min_rapid_z: f64::INFINITY,
            max_rapid_z: f64::NEG_INFINITY,
            count: 0,
            diagnostics: Vec::new(),
            scratch: Vec::new(),
        }
    }

    /// Reads events until the window holds `n` moves or the toolpath ends.
    #[inline]
    pub fn fill(&mut self, n: usize) {
        let n = n.min(WINDOW);
        if self.window.len() < n && !self.done {
            self.read(n);
        }
    }

    fn read(&mut self, n: usize) {
        while self.window.len() < n && !self.done {
            if let Some((record, span)) = self.batch.get_mut(self.at) {
                // Taken out of the batch, which is read once.
                let record = std::mem::replace(record, Record::DrillEnd);
                let span = *span;
                self.at += 1;
                self.record(&record, span);
                continue;
            }
            self.at = 0;
            self.done = !self.source.next_batch(&mut self.batch, &mut self.scratch);
            for d in self.scratch.drain(..) {
                if self.diagnostics.len() < 100 {
                    self.diagnostics.push(d);
                }
            }
        }
    }

    /// Reads until the job data is known (the first move, or the end).
    pub fn start(&mut self) {
        self.fill(1);
    }

    pub fn get(&mut self, k: usize) -> Option<&Expected> {
        if k >= self.window.len() {
            self.fill(k + 1);
        }
        self.window.get(k)
    }

    pub fn pop(&mut self) -> Option<Expected> {
        self.fill(1);
        self.window.pop_front()
    }

    pub fn is_done(&mut self) -> bool {
        self.fill(1);
        self.window.is_empty()
    }

    /// Whether `line` (a block that does not read as G-code) holds a line of
    /// text the toolpath asked to be inserted as it is: the toolpath's text,
    /// not the post's. Reads ahead to the next move for an insert not yet
    /// read; a line found is forgotten.
    pub fn inserted(&mut self, line: &[u8]) -> bool {
        self.fill(self.window.len() + 1);
        let line = String::from_utf8_lossy(line);
        match self.inserts.iter().position(|t| line.contains(t.as_str())) {
            Some(i) => {
                self.inserts.remove(i);
                true
            }
            None => false,
        }
    }

    fn powered(&self) -> bool {
        if self.jet_tool { self.jet } else { self.spindle || self.implied }
    }

    #[allow(clippy::too_many_arguments)] // one expected move's fields, filled from five event kinds
    fn push(
        &mut self,
        kind: Kind,
        end: [f64; 3],
        centre: [f64; 3],
        dir: ArcDir,
        plane: Plane,
        intent: Intent,
        feed: f64,
        span: Span,
    ) {
        if kind == Kind::Rapid {
            self.min_rapid_z = self.min_rapid_z.min(end[2]);
            self.max_rapid_z = self.max_rapid_z.max(end[2]);
        }
        let start = self.pos;
        let zero_length = start.iter().zip(end).all(|(a, b)| (a - b).abs() < 1e-9);
        self.pos = end;
        if zero_length && kind != Kind::Arc {
            return;
        }
        self.count += 1;
        let (powered, jet, implied) = (self.powered(), self.jet_tool, self.implied && !self.spindle && !self.jet_tool);
        let (per_rev, surface) = (self.per_rev, self.surface);
        self.window.push_back(Expected {
            kind,
            start,
            end,
            centre,
            dir,
            plane,
            intent,
            feed,
            powered,
            jet,
            per_rev,
            surface,
            implied,
            span,
        });
    }

    fn feed_for(&self, intent: Intent, feed: Option<f64>) -> f64 {
        feed.map(|f| f * self.factor).unwrap_or(match intent {
            Intent::Plunge | Intent::Retract => self.plunge_feed,
            _ => self.cut_feed,
        })
    }

    fn record(&mut self, record: &Record, span: Span) {
        let f = self.factor;
        let nan = [f64::NAN; 3];
        match record {
            Record::Job(job) => {
                self.factor = job.units.mm_per_unit();
                let f = self.factor;
                self.job.material = job.material.map(|(min, max)| (min.map(|v| v * f), max.map(|v| v * f)));
                self.job.safe_z = job.safe_z.map(|z| z * f);
            }
            &Record::Tool { cut_feed, plunge_feed, spindle_speed, jet, turning } => {
                self.cut_feed = cut_feed * f;
                self.plunge_feed = plunge_feed * f;
                self.jet_tool = jet;
                self.turning_tool = turning;
                self.lathe.get_or_insert(turning);
                self.surface = f64::NAN;
                // The runtime starts a spindle tool's spindle after the header and
                // each tool change, when the toolpath gives it a speed (section
                // posts; an APT-word post is told by the toolpath's own records).
                let speed = !jet && spindle_speed > 0.0;
                self.spindle = speed && !self.apt_words;
                self.implied = speed && self.apt_words;
                self.jet = false;
            }
            &Record::Toolpath { per_rev } => self.per_rev = per_rev,
            &Record::SpindleOn { surface } => {
                self.spindle = true;
                // Feet a minute in an inch job.
                self.surface = if f > 1.0 { surface * 0.3048 } else { surface };
            }
            Record::SpindleOff => {
                self.spindle = false;
                self.implied = false;
            }
            Record::JetOn => self.jet = true,
            Record::JetOff => self.jet = false,
            &Record::Rapid { end, rotary } => {
                self.job.rotary |= rotary;
                self.push(Kind::Rapid, end.map(|v| v * f), nan, ArcDir::Cw, Plane::Xy, Intent::Cut, f64::NAN, span)
            }
            &Record::Feed { end, intent, feed, rotary } => {
                self.job.rotary |= rotary;
                let mut intent = intent;
                let end = end.map(|v| v * f);
                // A turning tool's Z runs along the spindle, where it cuts.
                if intent == Intent::Cut
                    && !self.apt_words
                    && !self.turning_tool
                    && (self.pos[0] - end[0]).abs() < 1e-9
                    && (self.pos[1] - end[1]).abs() < 1e-9
                {
                    // The section runtime's rule: a straight move down is a plunge, up a retract.
                    if end[2] < self.pos[2] {
                        intent = Intent::Plunge;
                    } else if end[2] > self.pos[2] {
                        intent = Intent::Retract;
                    }
                }
                let feed = self.feed_for(intent, feed);
                self.push(Kind::Feed, end, nan, ArcDir::Cw, Plane::Xy, intent, feed, span)
            }
            &Record::Arc { end, centre, dir, plane, intent, feed } => {
                let feed = self.feed_for(intent, feed);
                self.push(Kind::Arc, end.map(|v| v * f), centre.map(|v| v * f), dir, plane, intent, feed, span)
            }
            Record::Insert(text) => {
                for line in text.lines().map(str::trim).filter(|l| !l.is_empty()) {
                    if self.inserts.len() == INSERTS {
                        self.inserts.pop_front();
                    }
                    self.inserts.push_back(line.to_string());
                }
            }
            &Record::DrillCycle { retract, reference, depth, feed } => {
                self.cycle = Some((retract, reference, depth, feed))
            }
            Record::DrillEnd => self.cycle = None,
            &Record::DrillPoint { x, y } => {
                let Some((retract, reference, depth, feed)) = self.cycle else { return };
                let (x, y) = (x * f, y * f);
                let (clear, reference, depth) = (retract * f, reference * f, depth * f);
                let feed = feed.map_or(self.plunge_feed, |v| v * f);
                self.push(Kind::Rapid, [x, y, clear], nan, ArcDir::Cw, Plane::Xy, Intent::Cut, f64::NAN, span);
                self.push(Kind::Rapid, [x, y, reference], nan, ArcDir::Cw, Plane::Xy, Intent::Cut, f64::NAN, span);
                self.push(Kind::Feed, [x, y, depth], nan, ArcDir::Cw, Plane::Xy, Intent::Plunge, feed, span);
                self.push(Kind::Rapid, [x, y, clear], nan, ArcDir::Cw, Plane::Xy, Intent::Cut, f64::NAN, span);
            }
        }
    }
}
