//! Synthetic toolpaths: event sources that make toolpaths of any length
//! without reading a file, for `postc toolpath gen` and `postc bench`.
//!
//! Patterns:
//! - `zigzag`: a 3D raster (every move changes X, Y and Z a little), with a
//!   retract, rapid and plunge every 200 moves;
//! - `arcs`: rows of half circles turning both ways, in the same frame;
//! - `mixed`: the raster with an arc every fourth move;
//! - `standard`: a small job that touches every kind of event: two tools,
//!   three toolpaths, rapids, plunges, cuts, arcs both ways, a helical ramp,
//!   a dwell and a jet toolpath (the size is fixed; `--moves` is ignored).

use postc_ir::event::*;
use postc_ir::{Diagnostic, EventSource, FileId, Span, Units};

/// The toolpath patterns `gen` knows, each with what it makes.
pub const PATTERNS: &[(&str, &str)] = &[
    ("zigzag", "a 3D raster, with a retract, rapid and plunge every 200 moves"),
    ("arcs", "rows of half circles turning both ways"),
    ("mixed", "the raster with an arc every fourth move"),
    ("standard", "a small job with every kind of event, two tools and a jet toolpath (--moves is ignored)"),
];

/// A generated toolpath.
pub struct Synthetic {
    pattern: Pattern,
    moves: u64,
    done_moves: u64,
    stage: Stage,
    /// Queue of events for the `standard` job and for fixed sequences.
    queue: std::collections::VecDeque<Event>,
    pos: [f64; 3],
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Pattern {
    Zigzag,
    Arcs,
    Mixed,
    Standard,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Stage {
    Preamble,
    Body,
    Finished,
}

const ROW: u64 = 200;
const STEP: f64 = 0.5;
const DEPTH: f64 = -1.0;
const SAFE: f64 = 5.0;

impl Synthetic {
    /// A generator for a named pattern and number of moves.
    pub fn new(pattern: &str, moves: u64) -> Option<Synthetic> {
        let pattern = match pattern {
            "zigzag" => Pattern::Zigzag,
            "arcs" => Pattern::Arcs,
            "mixed" => Pattern::Mixed,
            "standard" => Pattern::Standard,
            _ => return None,
        };
        Some(Synthetic {
            pattern,
            moves,
            done_moves: 0,
            stage: Stage::Preamble,
            queue: Default::default(),
            pos: [0.0; 3],
        })
    }

    /// The moves made so far (for a progress bar).
    pub fn moves_made(&self) -> u64 {
        self.done_moves
    }

    fn preamble(&mut self) {
        let q = &mut self.queue;
        q.push_back(Event::Job(Box::new(Job {
            units: Units::Mm,
            material: Some(Material {
                min: Point { x: 0.0, y: 0.0, z: -20.0 },
                max: Point { x: 300.0, y: 200.0, z: 0.0 },
            }),
            origin: Some(Origin { x: 0.0, y: 0.0, z: ZOrigin::MaterialSurface, xy: "Bottom Left".into() }),
            home: Some(Point { x: 0.0, y: 0.0, z: 20.0 }),
            safe_z: Some(SAFE),
            wrap_diameter: None,
            file: FileInfo { name: "synthetic".into(), dir: String::new(), extension: "nc".into() },
            notes: "Synthetic toolpath made by postc".into(),
            date: Some("2026-01-01".into()),
            time: Some("12:00:00".into()),
            tools: vec!["6 mm end mill".into()],
            toolpaths: vec!["Synthetic".into()],
            product: Some("postc".into()),
            part: None,
        })));
        q.push_back(Event::Tool(Tool {
            number: 1,
            name: "6 mm end mill".into(),
            diameter: 6.0,
            spindle_speed: 18000.0,
            cut_feed: 1500.0,
            plunge_feed: 500.0,
            ..Tool::default()
        }));
        q.push_back(Event::ToolpathStart(ToolpathStart {
            name: "Synthetic".into(),
            notes: String::new(),
            ..ToolpathStart::default()
        }));
        q.push_back(Event::Rapid(Move { x: 0.0, y: 0.0, z: SAFE, ..Move::default() }));
        q.push_back(Event::Feed(FeedMove { x: 0.0, y: 0.0, z: DEPTH, intent: Intent::Plunge, ..FeedMove::default() }));
        self.pos = [0.0, 0.0, DEPTH];
    }

    /// The next body move; between rows, the retract and re-entry go to
    /// the queue and the first of them is returned.
    fn body_move(&mut self) -> Event {
        let n = self.done_moves;
        let row = n / ROW;
        let col = n % ROW;
        if col == 0 && n > 0 {
            // Retract, move over, plunge: three moves of the budget.
            let [x, y, _] = self.pos;
            self.queue.push_back(Event::Rapid(Move { x, y: y + STEP, z: SAFE, ..Move::default() }));
            self.queue.push_back(Event::Feed(FeedMove {
                x,
                y: y + STEP,
                z: DEPTH,
                intent: Intent::Plunge,
                ..FeedMove::default()
            }));
            self.pos = [x, y + STEP, DEPTH];
            self.done_moves += 3;
            return Event::Rapid(Move { x, y, z: SAFE, ..Move::default() });
        }
        let dir = if row.is_multiple_of(2) { 1.0 } else { -1.0 };
        let [x, y, _] = self.pos;
        // A triangle wave in Z: every move changes all three axes, cheaply.
        let z = DEPTH - 0.25 * ((n % 40) as f64 / 20.0 - 1.0).abs();
        let arc = match self.pattern {
            Pattern::Arcs => true,
            Pattern::Mixed => n % 4 == 3,
            _ => false,
        };
        self.done_moves += 1;
        if arc {
            let ex = x + dir * 2.0 * STEP;
            let ccw = (n / 2).is_multiple_of(2);
            let z = self.pos[2];
            self.pos = [ex, y, z];
            Event::Arc(ArcMove {
                dir: if ccw { ArcDir::Ccw } else { ArcDir::Cw },
                x: ex,
                y,
                z,
                cx: x + dir * STEP,
                cy: y,
                cz: z,
                ..ArcMove::default()
            })
        } else {
            let nx = x + dir * STEP * 0.987;
            let ny = y + 0.0013;
            self.pos = [nx, ny, z];
            Event::Feed(FeedMove { x: nx, y: ny, z, ..FeedMove::default() })
        }
    }

    fn postamble(&mut self) {
        let [x, y, _] = self.pos;
        self.queue.push_back(Event::Rapid(Move { x, y, z: SAFE, ..Move::default() }));
        self.queue.push_back(Event::ToolpathEnd);
        self.queue.push_back(Event::End);
    }
}

impl EventSource for Synthetic {
    fn next_event(&mut self, _: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        loop {
            if let Some(e) = self.queue.pop_front() {
                return Some((e, Span::new(FileId(0), 0, 0)));
            }
            match self.stage {
                Stage::Preamble => {
                    if self.pattern == Pattern::Standard {
                        self.queue.extend(standard_job());
                        self.stage = Stage::Finished;
                    } else {
                        self.preamble();
                        self.stage = Stage::Body;
                    }
                }
                Stage::Body if self.done_moves < self.moves => {
                    return Some((self.body_move(), Span::new(FileId(0), 0, 0)));
                }
                Stage::Body => {
                    self.postamble();
                    self.stage = Stage::Finished;
                }
                Stage::Finished => return None,
            }
        }
    }
}

/// The standard job: every kind of move and event, two tools, three
/// toolpaths and a jet toolpath, in millimetres.
pub fn standard_job() -> Vec<Event> {
    let rapid = |x, y, z| Event::Rapid(Move { x, y, z, ..Move::default() });
    let feed = |x, y, z, intent| Event::Feed(FeedMove { x, y, z, intent, ..FeedMove::default() });
    let arc = |dir, x, y, z, cx, cy, intent| {
        Event::Arc(ArcMove { dir, x, y, z, cx, cy, cz: z, intent, ..ArcMove::default() })
    };
    let tool = |number, name: &str, diameter, jet| Tool {
        number,
        name: name.into(),
        notes: format!("{name} (standard job)"),
        diameter,
        spindle_speed: if jet { 0.0 } else { 16000.0 },
        cut_feed: 1200.0,
        plunge_feed: 400.0,
        jet,
        power: jet.then_some(80.0),
        ..Tool::default()
    };
    vec![
        Event::Job(Box::new(Job {
            units: Units::Mm,
            material: Some(Material {
                min: Point { x: 0.0, y: 0.0, z: -18.0 },
                max: Point { x: 200.0, y: 150.0, z: 0.0 },
            }),
            origin: Some(Origin { x: 0.0, y: 0.0, z: ZOrigin::MaterialSurface, xy: "Bottom Left".into() }),
            home: Some(Point { x: 0.0, y: 0.0, z: 25.0 }),
            safe_z: Some(5.0),
            wrap_diameter: Some(50.0),
            file: FileInfo { name: "standard".into(), dir: "/jobs".into(), extension: "nc".into() },
            notes: "Standard test job (postc)".into(),
            date: Some("2026-01-01".into()),
            time: Some("12:00:00".into()),
            tools: vec!["6 mm End Mill".into(), "3 mm Ball Nose".into(), "Laser".into()],
            toolpaths: vec!["Pocket".into(), "Profile".into(), "Ball finish".into(), "Laser engrave".into()],
            product: Some("postc".into()),
            part: None,
        })),
        Event::Tool(tool(1, "6 mm End Mill", 6.0, false)),
        Event::ToolpathStart(ToolpathStart {
            name: "Pocket".into(),
            notes: "helical entry, arcs both ways".into(),
            ..ToolpathStart::default()
        }),
        rapid(50.0, 40.0, 5.0),
        feed(50.0, 40.0, 0.5, Intent::Plunge),
        arc(ArcDir::Ccw, 50.0, 40.0, -1.5, 45.0, 40.0, Intent::Plunge),
        arc(ArcDir::Ccw, 50.0, 40.0, -3.0, 45.0, 40.0, Intent::Cut),
        feed(70.0, 40.0, -3.0, Intent::Cut),
        arc(ArcDir::Ccw, 80.0, 50.0, -3.0, 70.0, 50.0, Intent::Cut),
        arc(ArcDir::Cw, 90.0, 60.0, -3.0, 90.0, 50.0, Intent::Cut),
        Event::Feed(FeedMove { x: 90.0, y: 80.0, z: -3.0, feed: Some(900.0), ..FeedMove::default() }),
        Event::Dwell(Dwell { seconds: 1.5, revolutions: false }),
        feed(90.0, 80.0, 0.0, Intent::Retract),
        rapid(90.0, 80.0, 5.0),
        Event::ToolpathEnd,
        Event::ToolpathStart(ToolpathStart {
            name: "Profile".into(),
            notes: "same tool".into(),
            ..ToolpathStart::default()
        }),
        rapid(10.0, 10.0, 5.0),
        feed(10.0, 10.0, -2.0, Intent::Plunge),
        feed(10.0, 20.0, -2.0, Intent::LeadIn),
        feed(60.0, 20.0, -2.0, Intent::Cut),
        arc(ArcDir::Cw, 70.0, 10.0, -2.0, 60.0, 10.0, Intent::Cut),
        feed(70.0, 0.0, -2.0, Intent::LeadOut),
        rapid(70.0, 0.0, 5.0),
        Event::ToolpathEnd,
        Event::Tool(tool(2, "3 mm Ball Nose", 3.0, false)),
        Event::ToolpathStart(ToolpathStart {
            name: "Ball finish".into(),
            notes: String::new(),
            ..ToolpathStart::default()
        }),
        rapid(20.0, 100.0, 5.0),
        feed(20.0, 100.0, -0.5, Intent::Plunge),
        feed(40.0, 102.0, -0.8, Intent::Cut),
        feed(60.0, 100.0, -0.6, Intent::Cut),
        arc(ArcDir::Ccw, 60.0, 110.0, -0.6, 60.0, 105.0, Intent::Cut),
        feed(20.0, 110.0, -0.6, Intent::Cut),
        rapid(20.0, 110.0, 5.0),
        Event::ToolpathEnd,
        Event::Tool(tool(3, "Laser", 0.2, true)),
        Event::ToolpathStart(ToolpathStart {
            name: "Laser engrave".into(),
            notes: "jet tool".into(),
            ..ToolpathStart::default()
        }),
        rapid(100.0, 100.0, 0.0),
        Event::Power(Power { value: 80.0 }),
        Event::JetOn,
        feed(120.0, 100.0, 0.0, Intent::Cut),
        arc(ArcDir::Cw, 130.0, 90.0, 0.0, 120.0, 90.0, Intent::Cut),
        Event::Power(Power { value: 40.0 }),
        feed(130.0, 70.0, 0.0, Intent::Cut),
        Event::JetOff,
        rapid(130.0, 70.0, 5.0),
        Event::ToolpathEnd,
        Event::End,
    ]
}
