//! APT-word dispatch: each toolpath event becomes APT records, and each
//! record calls the handler named after its major word (VcPost milling
//! posts and the `postp` controllers are written this way: `Sub GOTO`,
//! `Sub FEDRAT`, `Sub LOADTL`, ...).
//!
//! Before a handler runs, the runtime sets the registers and variables the
//! record carries, when the post has them (names are case-insensitive):
//!
//! | record | from | sets |
//! |---|---|---|
//! | every record | | `Word` (major word), `Minor` (first minor word or ""), `Text` (its text or "") |
//! | `PARTNO` | the Job, once, first | `Text` = part name, else the output file name (a CL file's own PARTNO record is this one, not a second call); `Metric` = 1 when every length the records give is in millimetres, 0 for inches |
//! | `LOADTL` | Tool | `T`, `H` (length offset, else T), `D` (diameter offset, else T), `Text` = tool name |
//! | `TOOLPATH` | ToolpathStart | `Text` = toolpath name |
//! | `RAPID` then `GOTO` | Rapid | `X Y Z`, `G` = 0; `A B C` when the move has them; `I J K` = tool axis when the move has one |
//! | `FEDRAT` | a feed that changes | `F` |
//! | `GOTO` | Feed | `X Y Z`, `G` = 1, `F`; `A B C` when given; `I J K` = tool axis when given |
//! | `CIRCLE` | Arc (one call per arc, end point included) | `X Y Z` end, `G` = 2 (clockwise) or 3, seen from the plane's positive normal; `Plane` = 17 (XY), 18 (ZX) or 19 (YZ); `I J K` centre minus start; `CX CY CZ` centre; `R` radius; `F` |
//! | `DELAY` | Dwell | `R` = seconds |
//! | `SPINDL` | SpindleOn / SpindleOff | `S`, `Minor` = `CLW`, `CCLW` or `OFF` |
//! | `COOLNT` | Coolant | `Minor` = `ON`, `FLOOD`, `MIST`, `AIR`, `OFF` |
//! | `CUTCOM` | CutterComp | `Minor` = `LEFT`, `RIGHT`, `OFF`; `D` |
//! | `CYCLE` | the first hole of a DrillCycle | `Minor` = `DRILL`, `DEEP`, `BRKCHP`, `TAP`, `BORE`, `REAM`; `X Y` of the hole, `Z` = depth, `R` = reference plane, `Q` = peck, `P` = dwell (seconds), `F` |
//! | `GOTO` | each later hole | `X Y`, `Z` = top of the hole, `G` = 1 |
//! | `CYCLE` | DrillEnd | `Minor` = `OFF` |
//! | `PPRINT` / `INSERT` | Comment / Insert | `Text` |
//! | the word | Command | `Minor`, `Text`, `Arg1`… `Arg16` (each argument, number or word), `Args` (count) |
//! | `FINI` | End, or the end of the stream | |
//!
//! Positions, centres, radii and feeds are in the post's units. Values
//! persist: a register keeps its value until a record sets it again, so
//! `Z.Previous` in `GOTO` is the Z of the move before. Jet events (`JetOn`,
//! `JetOff`, `Power`) and `ToolpathEnd` make no record.
//!
//! An arc whose post has no `CIRCLE` handler becomes `GOTO` calls along the
//! arc (RT021, once). A record whose word has no handler is skipped, with
//! one warning per word (RT020).

use std::collections::{HashMap, HashSet};

use postc_ir::event::{ArcDir, ArcMove, Arg, CompSide, Coolant, DrillCycle, DrillKind, Event, Intent, Plane};
use postc_ir::{Diagnostic, HandlerKey};

use crate::engine::Engine;
use crate::geometry::ArcGeometry;
use crate::slots::Slots;
use crate::value::Value;

type Result<T> = std::result::Result<T, Box<Diagnostic>>;

/// Dispatch state of one run.
pub struct AptDispatch {
    handlers: HashMap<String, usize>,
    slots: Slots,
    started: bool,
    finished: bool,
    /// The PARTNO record of a CL file repeats the one the start made from
    /// the job's part name; it is not called twice.
    partno_from_job: bool,
    cycle: Option<DrillCycle>,
    cycle_called: bool,
    last_feed: Option<f64>,
    warned: HashSet<String>,
}

impl AptDispatch {
    pub fn new(eng: &Engine) -> AptDispatch {
        let post = eng.post;
        let handlers = post
            .handlers
            .iter()
            .enumerate()
            .filter_map(|(i, h)| match &h.key {
                HandlerKey::Word(w) => Some((w.to_ascii_uppercase(), i)),
                HandlerKey::Section(_) => None,
            })
            .collect();
        let slots = Slots::new(post);
        AptDispatch {
            handlers,
            slots,
            started: false,
            finished: false,
            partno_from_job: false,
            cycle: None,
            cycle_called: false,
            last_feed: None,
            warned: HashSet::new(),
        }
    }

    /// Sets a register or variable the post has; names it lacks are ignored.
    fn set(&self, eng: &mut Engine, name: &str, value: Value) {
        self.slots.set(eng, name, value);
    }

    fn num(&self, eng: &mut Engine, name: &str, v: f64) {
        self.set(eng, name, Value::Num(v));
    }

    fn text(&self, eng: &mut Engine, name: &str, t: &str) {
        self.set(eng, name, Value::text(t));
    }

    /// Calls the handler of a word, after setting `Word`, `Minor` and `Text`.
    fn call(&mut self, eng: &mut Engine, word: &str, minor: &str, text: &str) -> Result<()> {
        self.text(eng, "WORD", word);
        self.text(eng, "MINOR", minor);
        self.text(eng, "TEXT", text);
        match self.handlers.get(word) {
            Some(&i) => eng.run_handler(i),
            None => {
                if self.warned.insert(word.to_string()) {
                    let mut d = Diagnostic::warning(
                        "RT020",
                        format!("the post has no Sub for {word}; those records are skipped"),
                    );
                    if eng.event_span.end > eng.event_span.start {
                        d = d.at(eng.event_span, "the first one");
                    }
                    eng.warn_once(d.help(format!("add `Sub {word}` ... `End Sub` to the post to handle them")));
                }
                Ok(())
            }
        }
    }

    fn set_xyz(&self, eng: &mut Engine, p: [f64; 3]) {
        self.num(eng, "X", p[0]);
        self.num(eng, "Y", p[1]);
        self.num(eng, "Z", p[2]);
    }

    fn set_axis(&self, eng: &mut Engine, axis: Option<[f64; 3]>) {
        if let Some([i, j, k]) = axis {
            self.num(eng, "I", i);
            self.num(eng, "J", j);
            self.num(eng, "K", k);
        }
    }

    /// Rotary axis positions (degrees), when the move has them.
    fn set_rotary(&self, eng: &mut Engine, abc: [Option<f64>; 3]) {
        for (name, v) in ["A", "B", "C"].into_iter().zip(abc) {
            if let Some(v) = v {
                self.num(eng, name, v);
            }
        }
    }

    /// The program starts: PARTNO with the part's (or the file's) name.
    fn start(&mut self, eng: &mut Engine) -> Result<()> {
        if self.started {
            return Ok(());
        }
        self.started = true;
        self.partno_from_job = eng.machine.job.part.is_some();
        let name = eng.machine.job.part.clone().unwrap_or_else(|| eng.machine.file_name.clone());
        let metric = eng.machine.output_units == postc_ir::Units::Mm;
        self.num(eng, "METRIC", if metric { 1.0 } else { 0.0 });
        self.call(eng, "PARTNO", "", &name)
    }

    /// FEDRAT when the feed changes; the feed in `F` either way.
    fn feed(&mut self, eng: &mut Engine, feed: f64) -> Result<()> {
        eng.machine.feed = feed;
        self.num(eng, "F", feed);
        if self.last_feed != Some(feed) {
            self.last_feed = Some(feed);
            self.call(eng, "FEDRAT", "", "")?;
        }
        Ok(())
    }

    fn feed_for(eng: &Engine, intent: Intent, feed: Option<f64>) -> f64 {
        feed.unwrap_or(match intent {
            Intent::Plunge | Intent::Retract => eng.machine.tool.plunge_feed,
            _ => eng.machine.tool.cut_feed,
        })
    }

    fn goto(&mut self, eng: &mut Engine, p: [f64; 3], g: f64, axis: Option<[f64; 3]>) -> Result<()> {
        eng.machine.move_from = eng.machine.pos;
        eng.machine.move_length = None;
        eng.machine.pos = p;
        eng.machine.pos_known = true;
        self.set_xyz(eng, p);
        self.num(eng, "G", g);
        self.set_axis(eng, axis);
        self.call(eng, "GOTO", "", "")
    }

    fn arc(&mut self, eng: &mut Engine, a: ArcMove) -> Result<()> {
        let start = eng.machine.pos;
        let (end, centre) = ([a.x, a.y, a.z], [a.cx, a.cy, a.cz]);
        let g = ArcGeometry::new(start, end, centre, a.dir, a.plane);
        let feed = Self::feed_for(eng, a.intent, a.feed);
        self.feed(eng, feed)?;
        if !self.handlers.contains_key("CIRCLE") {
            if self.warned.insert("CIRCLE".into()) {
                eng.warn_once(Diagnostic::warning(
                    "RT021",
                    "the post has no Sub for CIRCLE; arcs are cut into GOTO moves",
                ));
            }
            let tolerance =
                eng.post.options.arc_tolerance * eng.machine.output_units.factor_to(postc_ir::Units::Mm).recip();
            let n = g.segments(tolerance).min(10_000);
            for i in 1..=n {
                self.goto(eng, g.point_at(f64::from(i) / f64::from(n)), 1.0, None)?;
            }
            return Ok(());
        }
        eng.machine.arc = g;
        eng.machine.move_from = start;
        eng.machine.move_length = Some(g.length());
        eng.machine.pos = end;
        eng.machine.pos_known = true;
        self.set_xyz(eng, end);
        self.num(eng, "G", if a.dir == ArcDir::Cw { 2.0 } else { 3.0 });
        let plane = match a.plane {
            Plane::Xy => 17.0,
            Plane::Zx => 18.0,
            Plane::Yz => 19.0,
        };
        self.num(eng, "PLANE", plane);
        self.num(eng, "I", centre[0] - start[0]);
        self.num(eng, "J", centre[1] - start[1]);
        self.num(eng, "K", centre[2] - start[2]);
        self.num(eng, "CX", centre[0]);
        self.num(eng, "CY", centre[1]);
        self.num(eng, "CZ", centre[2]);
        self.num(eng, "R", g.radius);
        self.call(eng, "CIRCLE", "", "")
    }

    fn hole(&mut self, eng: &mut Engine, x: f64, y: f64, z: f64) -> Result<()> {
        let Some(cycle) = self.cycle.clone() else {
            return Err(Box::new(
                Diagnostic::error("RT013", "a DrillPoint came outside a drilling cycle")
                    .at(eng.event_span, "this hole"),
            ));
        };
        let top = [x, y, z];
        if self.cycle_called {
            return self.goto(eng, top, 1.0, None);
        }
        self.cycle_called = true;
        let (depth, reference) = (cycle.depth, cycle.reference_plane);
        let peck = cycle.peck.unwrap_or(0.0);
        let feed = cycle.feed.unwrap_or(eng.machine.tool.plunge_feed);
        eng.machine.pos = top;
        eng.machine.pos_known = true;
        self.set_xyz(eng, [top[0], top[1], depth]);
        self.num(eng, "R", reference);
        self.num(eng, "Q", peck);
        self.num(eng, "P", cycle.dwell.unwrap_or(0.0));
        self.num(eng, "F", feed);
        let kind = match cycle.kind {
            DrillKind::Drill => "DRILL",
            DrillKind::Deep => "DEEP",
            DrillKind::ChipBreak => "BRKCHP",
            DrillKind::Tap => "TAP",
            DrillKind::Bore => "BORE",
            DrillKind::Ream => "REAM",
        };
        self.call(eng, "CYCLE", kind, "")
    }

    /// Handles one event.
    pub fn event(&mut self, eng: &mut Engine, event: Event) -> Result<()> {
        if let Event::Job(job) = event {
            if !self.started {
                eng.machine.set_job(*job);
            }
            return self.start(eng);
        }
        self.start(eng)?;
        match event {
            Event::Job(_) => {}
            Event::Tool(tool) => {
                let (number, name) = (tool.number, tool.name.clone());
                let h = tool.length_offset.unwrap_or(number);
                let d = tool.diameter_offset.unwrap_or(number);
                eng.machine.set_tool(tool);
                self.num(eng, "T", f64::from(number));
                self.num(eng, "H", f64::from(h));
                self.num(eng, "D", f64::from(d));
                self.call(eng, "LOADTL", "", &name)?;
            }
            Event::ToolpathStart(tp) => {
                let name = tp.name.clone();
                eng.machine.toolpath = tp;
                self.call(eng, "TOOLPATH", "", &name)?;
            }
            Event::ToolpathEnd => {}
            Event::Rapid(m) => {
                let p = [m.x, m.y, m.z];
                self.set_rotary(eng, [m.a, m.b, m.c]);
                self.num(eng, "G", 0.0);
                self.call(eng, "RAPID", "", "")?;
                self.goto(eng, p, 0.0, m.tool_axis)?;
            }
            Event::Feed(m) => {
                let p = [m.x, m.y, m.z];
                self.set_rotary(eng, [m.a, m.b, m.c]);
                let feed = Self::feed_for(eng, m.intent, m.feed);
                self.feed(eng, feed)?;
                self.goto(eng, p, 1.0, m.tool_axis)?;
            }
            Event::Arc(a) => self.arc(eng, a)?,
            Event::Dwell(d) => {
                let rpm = eng.machine.spindle_speed;
                let seconds = if d.revolutions && rpm > 0.0 { d.seconds * 60.0 / rpm } else { d.seconds };
                eng.machine.dwell = seconds;
                self.num(eng, "R", seconds);
                self.call(eng, "DELAY", "", "")?;
            }
            Event::SpindleOn(s) => {
                if let Some(speed) = s.speed {
                    eng.machine.spindle_speed = speed;
                }
                eng.machine.spindle_ccw = s.ccw;
                let speed = eng.machine.spindle_speed;
                self.num(eng, "S", speed);
                self.call(eng, "SPINDL", if s.ccw { "CCLW" } else { "CLW" }, "")?;
            }
            Event::SpindleOff => self.call(eng, "SPINDL", "OFF", "")?,
            Event::Coolant(c) => {
                let minor = match c.coolant {
                    Coolant::Off => "OFF",
                    Coolant::Flood => "FLOOD",
                    Coolant::Mist => "MIST",
                    Coolant::Through => "ON",
                    Coolant::Air => "AIR",
                };
                self.call(eng, "COOLNT", minor, "")?;
            }
            Event::CutterComp(c) => {
                let register = c.register.unwrap_or(eng.machine.tool.number);
                eng.machine.comp_register = Some(f64::from(register));
                self.num(eng, "D", f64::from(register));
                let minor = match c.side {
                    CompSide::Off => "OFF",
                    CompSide::Left => "LEFT",
                    CompSide::Right => "RIGHT",
                };
                self.call(eng, "CUTCOM", minor, "")?;
            }
            Event::DrillCycle(c) => {
                self.cycle = Some(c);
                self.cycle_called = false;
            }
            Event::DrillPoint(p) => self.hole(eng, p.x, p.y, p.z)?,
            Event::DrillEnd => {
                if self.cycle_called {
                    self.call(eng, "CYCLE", "OFF", "")?;
                }
                self.cycle = None;
                self.cycle_called = false;
            }
            Event::Comment(t) => self.call(eng, "PPRINT", "", &t.text)?,
            Event::Insert(t) => self.call(eng, "INSERT", "", &t.text)?,
            Event::Command(c) if c.word.eq_ignore_ascii_case("PARTNO") && self.partno_from_job => {
                self.partno_from_job = false;
            }
            Event::Command(c) => {
                let word = c.word.to_ascii_uppercase();
                let minor = c
                    .args
                    .iter()
                    .find_map(|a| if let Arg::Word(w) = a { Some(w.as_str()) } else { None })
                    .unwrap_or("");
                let text = c
                    .args
                    .iter()
                    .find_map(|a| if let Arg::Text(t) = a { Some(t.as_str()) } else { None })
                    .unwrap_or("");
                self.num(eng, "ARGS", c.args.len() as f64);
                for (i, a) in c.args.iter().enumerate().take(16) {
                    let value = match a {
                        Arg::Number(n) => Value::Num(*n),
                        Arg::Word(w) | Arg::Text(w) => Value::text(w),
                    };
                    self.set(eng, &format!("ARG{}", i + 1), value);
                }
                let (minor, text) = (minor.to_string(), text.to_string());
                self.call(eng, &word, &minor, &text)?;
            }
            Event::JetOn | Event::JetOff | Event::Power(_) => {}
            Event::End => self.finish(eng)?,
            // Never handed to posts (`run` skips it): the moves carry the feed.
            Event::FeedRate(_) => {}
        }
        Ok(())
    }

    /// Ends the program: FINI, once.
    pub fn finish(&mut self, eng: &mut Engine) -> Result<()> {
        if self.finished {
            return Ok(());
        }
        self.start(eng)?;
        self.finished = true;
        self.call(eng, "FINI", "", "")
    }
}
