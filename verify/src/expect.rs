//! The toolpath side: the moves a program must make, read from the event
//! stream into a bounded window, in millimetres.

use std::collections::VecDeque;

use postc_ir::event::{ArcDir, DrillCycle, Event, Intent, Plane};
use postc_ir::{Diagnostic, EventSource, Span};

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
    source: &'a mut dyn EventSource,
    window: VecDeque<Expected>,
    done: bool,
    factor: f64,
    pos: [f64; 3],
    cut_feed: f64,
    plunge_feed: f64,
    jet_tool: bool,
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
    cycle: Option<DrillCycle>,
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
    pub fn new(source: &'a mut dyn EventSource) -> ExpectedPath<'a> {
        ExpectedPath {
            source,
            window: VecDeque::with_capacity(WINDOW),
            done: false,
            factor: 1.0,
            pos: [f64::NAN; 3],
            cut_feed: f64::NAN,
            plunge_feed: f64::NAN,
            jet_tool: false,
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
    pub fn fill(&mut self, n: usize) {
        let n = n.min(WINDOW);
        while self.window.len() < n && !self.done {
            self.scratch.clear();
            let next = self.source.next_event(&mut self.scratch);
            for d in self.scratch.drain(..) {
                if self.diagnostics.len() < 100 {
                    self.diagnostics.push(d);
                }
            }
            match next {
                Some((event, span)) => self.event(event, span),
                None => self.done = true,
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

    fn event(&mut self, event: Event, span: Span) {
        let f = self.factor;
        let nan = [f64::NAN; 3];
        match event {
            Event::Job(job) => {
                self.factor = job.units.mm_per_unit();
                let f = self.factor;
                self.job.material = job
                    .material
                    .map(|m| ([m.min.x * f, m.min.y * f, m.min.z * f], [m.max.x * f, m.max.y * f, m.max.z * f]));
                self.job.safe_z = job.safe_z.map(|z| z * f);
            }
            Event::Tool(tool) => {
                self.cut_feed = tool.cut_feed * f;
                self.plunge_feed = tool.plunge_feed * f;
                self.jet_tool = tool.jet;
                // The runtime starts a spindle tool's spindle after the header and
                // each tool change, when the toolpath gives it a speed (section
                // posts; an APT-word post is told by the toolpath's own records).
                let speed = !tool.jet && tool.spindle_speed > 0.0;
                self.spindle = speed && !self.apt_words;
                self.implied = speed && self.apt_words;
                self.jet = false;
            }
            Event::SpindleOn(_) => self.spindle = true,
            Event::SpindleOff => {
                self.spindle = false;
                self.implied = false;
            }
            Event::JetOn => self.jet = true,
            Event::JetOff => self.jet = false,
            Event::Rapid(m) => {
                self.job.rotary |= m.a.is_some() || m.b.is_some() || m.c.is_some();
                self.push(
                    Kind::Rapid,
                    [m.x * f, m.y * f, m.z * f],
                    nan,
                    ArcDir::Cw,
                    Plane::Xy,
                    Intent::Cut,
                    f64::NAN,
                    span,
                )
            }
            Event::Feed(m) => {
                self.job.rotary |= m.a.is_some() || m.b.is_some() || m.c.is_some();
                let mut intent = m.intent;
                let end = [m.x * f, m.y * f, m.z * f];
                if intent == Intent::Cut
                    && !self.apt_words
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
                let feed = self.feed_for(intent, m.feed);
                self.push(Kind::Feed, end, nan, ArcDir::Cw, Plane::Xy, intent, feed, span)
            }
            Event::Arc(a) => {
                let feed = self.feed_for(a.intent, a.feed);
                let end = [a.x * f, a.y * f, a.z * f];
                let centre = [a.cx * f, a.cy * f, a.cz * f];
                self.push(Kind::Arc, end, centre, a.dir, a.plane, a.intent, feed, span)
            }
            Event::Insert(t) => {
                for line in t.text.lines().map(str::trim).filter(|l| !l.is_empty()) {
                    if self.inserts.len() == INSERTS {
                        self.inserts.pop_front();
                    }
                    self.inserts.push_back(line.to_string());
                }
            }
            Event::DrillCycle(c) => self.cycle = Some(c),
            Event::DrillEnd => self.cycle = None,
            Event::DrillPoint(p) => {
                let Some(c) = self.cycle.clone() else { return };
                let (x, y) = (p.x * f, p.y * f);
                let (clear, reference, depth) = (c.retract_plane * f, c.reference_plane * f, c.depth * f);
                let feed = c.feed.map_or(self.plunge_feed, |v| v * f);
                self.push(Kind::Rapid, [x, y, clear], nan, ArcDir::Cw, Plane::Xy, Intent::Cut, f64::NAN, span);
                self.push(Kind::Rapid, [x, y, reference], nan, ArcDir::Cw, Plane::Xy, Intent::Cut, f64::NAN, span);
                self.push(Kind::Feed, [x, y, depth], nan, ArcDir::Cw, Plane::Xy, Intent::Plunge, feed, span);
                self.push(Kind::Rapid, [x, y, clear], nan, ArcDir::Cw, Plane::Xy, Intent::Cut, f64::NAN, span);
            }
            _ => {}
        }
    }
}
