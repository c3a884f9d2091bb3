//! Section dispatch: which section prints each event, under the Vectric
//! rules that CIMCO posts share.
//!
//! - The header prints when the first toolpath starts, with the first tool's
//!   data, after `REVISION_COMMENT`; `SPINDLE_ON` follows it and each `TOOLCHANGE` (not for jet tools,
//!   nor when the speed is negative). Each later toolpath prints
//!   `TOOLCHANGE` when the tool number changes, then `NEW_SEGMENT`. Modal
//!   memory is cleared as a toolpath starts, so its first move prints every
//!   word.
//! - `FIRST_` sections print the first move of a run of moves of their kind
//!   and again after the feed rate changes; otherwise the plain section.
//!   A post may have the feed variables forget what they printed after each
//!   rapid, so that the first feed move after a rapid prints its feed.
//!   A missing `FIRST_` section falls back to the plain one, and the other
//!   way round. Plunges without plunge sections, and retracts without
//!   `RETRACT_MOVE`, print as feed (or rapid) moves.
//! - Arcs without arc sections, arcs larger than `MAX_ARC_RADIUS`, arcs
//!   outside the XY plane and arcs of a post with ROTARY_WRAP (a G2/G3
//!   cannot turn the rotary axis) are linearized into feed moves; arcs smaller than
//!   `MIN_ARC_RADIUS` print as one straight move. A helix without helical
//!   sections prints through the arc section only when that section prints
//!   `[Z]`; otherwise it is linearized.
//! - Drilling cycles print through drilling sections when the post has
//!   them, otherwise as rapid, plunge, dwell and retract moves.
//! - Tape splitting ends a part with the footer at a retract once the part
//!   has `max - tolerance` blocks (a retract that ends at or above the
//!   job's safe Z, when it has one), or at any move once it has `max`, and
//!   starts the next part with the header. The split waits for the next
//!   block that belongs to the new part (a move, a toolpath or tool start,
//!   a dwell, jet event or insert), so a program that ends right after the
//!   retract is not split and no part is only a header and a footer. A part
//!   that starts at a toolpath boundary starts like a program: the header
//!   carries the tool and toolpath, with no TOOLCHANGE or NEW_SEGMENT.

use postc_ir::event::{ArcDir, Event, FeedMove, Intent, Move};
use postc_ir::{Diagnostic, Quantity, Section};

mod arcs;
mod drill;
mod tape;

use crate::engine::Engine;

type Result<T> = std::result::Result<T, Box<Diagnostic>>;

/// Events held for the header are at most this many, with at most this
/// much text; past either the program starts with what it knows.
const MAX_HELD: usize = 10_000;
const MAX_HELD_BYTES: usize = 1 << 20;

/// The kind of the last move printed, for `FIRST_` sections.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Family {
    None,
    Rapid,
    Feed,
    Plunge,
    Retract,
    Arc(ArcDir, Helix),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Helix {
    Flat,
    Helical,
    Plunge,
}

/// Dispatch state of one run.
pub struct SectionDispatch {
    started: bool,
    finished: bool,
    tool_changed: bool,
    last_tool: Option<u32>,
    initial_rapid: bool,
    family: Family,
    last_feed: Option<f64>,
    spindle_on: bool,
    /// Which rotary axes (A, B, C) the post reads: a move that turns one
    /// it does not read is refused ([`check_axes`]).
    rotary_read: [bool; 3],
    /// The post reads the spindle's direction (`SPINDLE_CCW`): a
    /// SpindleOn that only turns the spindle the other way starts it again.
    reads_direction: bool,
    /// A spindle stop the post had no section to write, at its event:
    /// warned of when a move follows it before a tool change, a restart
    /// or the end (which stop or start the spindle themselves).
    unwritten_stop: Option<postc_ir::Span>,
    /// Tape splitting: the current part ends before the next block.
    split_pending: bool,
    /// Inserts, comments, coolant and compensation that came before the
    /// program started, and the length of their text: run after the
    /// header, which waits for the first tool.
    held: Vec<Event>,
    held_bytes: usize,
    /// Formats of the X and Y variables, to know the printed points.
    xy_formats: [Option<postc_ir::FormatId>; 2],
    exact_arcs: bool,
    /// The variables that print the feed, forgotten after each rapid when
    /// the post says so ([`postc_ir::OutputOptions::rapid_forgets_feed`]).
    feed_vars: Vec<postc_ir::VarId>,
}

impl SectionDispatch {
    pub fn new(eng: &Engine, exact_arcs: bool) -> SectionDispatch {
        let format_of =
            |q| eng.post.variables.iter().find(|v| v.source == postc_ir::ValueSource::Quantity(q)).map(|v| v.format);
        SectionDispatch {
            started: false,
            finished: false,
            tool_changed: false,
            last_tool: None,
            initial_rapid: true,
            family: Family::None,
            last_feed: None,
            spindle_on: false,
            unwritten_stop: None,
            rotary_read: rotary_read(eng.post),
            reads_direction: reads_quantity(eng.post, Quantity::SpindleCcw),
            split_pending: false,
            held: Vec::new(),
            held_bytes: 0,
            xy_formats: [format_of(Quantity::X), format_of(Quantity::Y)],
            exact_arcs: exact_arcs || eng.post.options.exact_arcs,
            feed_vars: if eng.post.options.rapid_forgets_feed {
                (0..eng.post.variables.len())
                    .filter(|&i| eng.post.variables[i].source == postc_ir::ValueSource::Quantity(Quantity::Feed))
                    .filter_map(postc_ir::VarId::from_usize)
                    .collect()
            } else {
                Vec::new()
            },
        }
    }

    /// Handles one event.
    pub fn event(&mut self, eng: &mut Engine, event: &Event) -> Result<()> {
        check_finite(eng, event)?;
        check_axes(eng, event, self.rotary_read)?;
        if let Some(at) = self.unwritten_stop {
            match event {
                Event::Rapid(_) | Event::Feed(_) | Event::Arc(_) | Event::DrillCycle(_) | Event::Dwell(_) => {
                    self.unwritten_stop = None;
                    unwritten_at(
                        eng,
                        at,
                        "the spindle to stop",
                        "the spindle runs on through the moves that follow",
                        Section::SpindleOff,
                    );
                }
                Event::Tool(_) | Event::SpindleOn(_) | Event::End => self.unwritten_stop = None,
                _ => {}
            }
        }
        match event {
            // Text, coolant and compensation before the first tool or move
            // wait for the header, which must print the first tool (an APT
            // file's INSERT and COOLNT before its LOADTL); they print after
            // it, in their order.
            Event::Insert(_) | Event::Comment(_) | Event::Coolant(_) | Event::CutterComp(_)
                if !self.started && self.held.len() < MAX_HELD && self.held_bytes < MAX_HELD_BYTES =>
            {
                if let Event::Insert(t) | Event::Comment(t) = event {
                    self.held_bytes += t.text.len();
                }
                self.held.push(event.clone());
            }
            Event::Job(job) => {
                if self.started {
                    eng.warn_once(
                        Diagnostic::warning("RT011", "a second Job event came after output began; it is ignored")
                            .at(eng.event_span, "this Job event"),
                    );
                } else {
                    if let Some(wrap) = eng.post.options.rotary_wrap
                        && !job.wrap_diameter.is_some_and(|d| d > 0.0)
                    {
                        let axis = if wrap.axis == postc_ir::post::WrappedAxis::X { 'X' } else { 'Y' };
                        eng.warn_once(
                            Diagnostic::warning(
                                "RT015",
                                format!("the post wraps {axis} around a cylinder (ROTARY_WRAP_{axis}), but the job gives no wrap diameter, so {axis} prints as a length, not as an angle"),
                            )
                            .at(eng.event_span, "this Job event")
                            .help("give the job a `wrap_diameter`"),
                        );
                    }
                    eng.machine.set_job((**job).clone());
                }
            }
            Event::Tool(tool) => {
                // A pending split ends the part before the new tool is
                // known, so its footer still sees the tool it cut with.
                self.split_if_pending(eng)?;
                self.tool_changed = self.last_tool != Some(tool.number);
                eng.machine.set_tool(tool.clone());
            }
            Event::ToolpathStart(tp) => {
                eng.machine.toolpath = tp.clone();
                self.split_if_pending(eng)?;
                self.begin_toolpath(eng)?;
            }
            Event::ToolpathEnd => {
                // The end of a toolpath belongs to the part that cut it.
                if !self.split_pending {
                    self.ensure_started(eng)?;
                }
                eng.run_section(Section::ToolpathEnd)?;
            }
            Event::Rapid(m) => {
                self.ensure_started(eng)?;
                self.rapid(eng, m)?;
            }
            Event::Feed(m) => {
                self.ensure_started(eng)?;
                self.feed(eng, m)?;
            }
            Event::Arc(a) => {
                self.ensure_started(eng)?;
                self.arc(eng, a)?;
            }
            Event::Dwell(d) => {
                self.ensure_started(eng)?;
                let rpm = eng.machine.spindle_speed;
                eng.machine.dwell = if d.revolutions && rpm > 0.0 { d.seconds * 60.0 / rpm } else { d.seconds };
                self.dwell(eng)?;
            }
            Event::SpindleOn(s) => {
                let speed = s.speed.unwrap_or(eng.machine.spindle_speed);
                let changed = speed != eng.machine.spindle_speed
                    || s.css != eng.machine.spindle_css
                    || (self.reads_direction && s.ccw != eng.machine.spindle_ccw);
                eng.machine.spindle_speed = speed;
                eng.machine.spindle_css = s.css;
                eng.machine.spindle_ccw = s.ccw;
                eng.machine.spindle_max_rpm = s.max_rpm.filter(|_| s.css);
                // SPINDLE_ON prints when the spindle starts, or runs on at a new speed.
                if self.started && (!self.spindle_on || changed) && !eng.machine.tool.jet {
                    self.spindle_on = eng.run_section(Section::SpindleOn)?;
                    if !self.spindle_on && changed {
                        unwritten(
                            eng,
                            "a new spindle speed",
                            "the spindle runs on at the speed it had",
                            Section::SpindleOn,
                        );
                    }
                }
            }
            Event::SpindleOff => {
                if self.started && !eng.run_section(Section::SpindleOff)? {
                    self.unwritten_stop = Some(eng.event_span);
                }
                self.spindle_on = false;
            }
            Event::JetOn => {
                self.ensure_started(eng)?;
                eng.run_section(Section::JetToolOn)?;
            }
            Event::JetOff => {
                self.ensure_started(eng)?;
                eng.run_section(Section::JetToolOff)?;
            }
            Event::Power(p) => {
                eng.machine.power = Some(p.value);
                self.ensure_started(eng)?;
                eng.run_section(Section::JetToolPower)?;
            }
            Event::Coolant(c) => {
                eng.machine.coolant = c.coolant;
                if self.started && !eng.run_section(Section::Coolant)? {
                    unwritten(eng, "a coolant change", "the coolant stays as it was", Section::Coolant);
                }
            }
            Event::CutterComp(c) => {
                let tool = &eng.machine.tool;
                eng.machine.comp_register = Some(f64::from(c.register.or(tool.diameter_offset).unwrap_or(tool.number)));
                eng.machine.comp_side = c.side;
                if self.started && !eng.run_section(Section::CutterComp)? {
                    unwritten(
                        eng,
                        "cutter compensation",
                        "the machine cuts on the tool's centre line, one radius off the part",
                        Section::CutterComp,
                    );
                }
            }
            Event::DrillCycle(c) => {
                self.ensure_started(eng)?;
                eng.machine.drill = Some(c.clone());
                eng.run_section(Section::DrillHeader)?;
            }
            Event::DrillPoint(p) => {
                self.ensure_started(eng)?;
                self.drill_point(eng, *p)?;
            }
            Event::DrillEnd => {
                if self.started {
                    eng.run_section(Section::DrillFooter)?;
                }
                eng.machine.drill = None;
            }
            Event::Comment(t) => {
                eng.machine.comment.clone_from(&t.text);
                if self.started {
                    eng.run_section(Section::Comment)?;
                }
            }
            Event::Insert(t) => {
                self.ensure_started(eng)?;
                self.insert(eng, &t.text)?;
            }
            Event::Command(_) => {}
            Event::End => self.finish(eng)?,
            // Never handed to posts (`run` skips it): the moves carry the feed.
            Event::FeedRate(_) => {}
        }
        Ok(())
    }

    /// Writes an insert's text: through INSERT when the post has it, else as it is.
    fn insert(&mut self, eng: &mut Engine, text: &str) -> Result<()> {
        eng.machine.comment.clear();
        eng.machine.comment.push_str(text);
        if !eng.run_section(Section::Insert)? {
            let text = std::mem::take(&mut eng.machine.comment);
            eng.write_blocks(&text);
            eng.machine.comment = text;
        }
        Ok(())
    }

    /// Ends the program: the footer, once.
    pub fn finish(&mut self, eng: &mut Engine) -> Result<()> {
        if self.finished {
            return Ok(());
        }
        // A split still pending here would open a part with nothing in it.
        self.split_pending = false;
        self.ensure_started(eng)?;
        eng.run_section(Section::Footer)?;
        self.finished = true;
        Ok(())
    }

    /// Starts the program, the next tape-split part or the new tool's
    /// toolpath, whichever is due, before a block is printed.
    fn ensure_started(&mut self, eng: &mut Engine) -> Result<()> {
        self.split_if_pending(eng)?;
        if !self.started || self.tool_changed {
            self.begin_toolpath(eng)?;
        }
        Ok(())
    }

    /// Whether SPINDLE_ON prints after the header or a tool change: not
    /// for jet tools, and not before a speed is known (a negative speed is
    /// invalid, a zero one unknown: APT files give it in a later SPINDL).
    fn spindle_tool(eng: &Engine) -> bool {
        !eng.machine.tool.jet && eng.machine.spindle_speed > 0.0
    }

    /// A toolpath starts: header or tool change, new segment, fresh modal state.
    fn begin_toolpath(&mut self, eng: &mut Engine) -> Result<()> {
        if !self.started {
            self.started = true;
            self.start_program(eng)?;
        } else {
            if self.tool_changed {
                eng.run_section(Section::ToolChange)?;
                self.spindle_on = Self::spindle_tool(eng) && eng.run_section(Section::SpindleOn)?;
                self.initial_rapid = true;
            }
            eng.run_section(Section::NewSegment)?;
        }
        self.tool_changed = false;
        self.last_tool = Some(eng.machine.tool.number);
        self.fresh_modal_state(eng);
        Ok(())
    }

    fn start_program(&mut self, eng: &mut Engine) -> Result<()> {
        // A stock Vectric post's revision lines come first (docs/vectric.md).
        eng.run_section(Section::RevisionComment)?;
        eng.run_section(Section::Header)?;
        self.spindle_on = Self::spindle_tool(eng) && eng.run_section(Section::SpindleOn)?;
        self.initial_rapid = true;
        self.held_bytes = 0;
        for held in std::mem::take(&mut self.held) {
            self.event(eng, &held)?;
        }
        Ok(())
    }

    fn fresh_modal_state(&mut self, eng: &mut Engine) {
        if eng.post.options.forget_modal_at_toolpath_start {
            eng.clear_modal();
        }
        self.family = Family::None;
        self.last_feed = None;
    }

    fn set_rotary(eng: &mut Engine, a: Option<f64>, b: Option<f64>, c: Option<f64>) {
        for (slot, v) in [a, b, c].into_iter().enumerate() {
            if let Some(v) = v {
                eng.machine.rotary[slot] = Some(v);
            }
        }
    }

    fn rapid(&mut self, eng: &mut Engine, m: &Move) -> Result<()> {
        Self::set_rotary(eng, m.a, m.b, m.c);
        self.rapid_to(eng, [m.x, m.y, m.z])
    }

    fn rapid_to(&mut self, eng: &mut Engine, target: [f64; 3]) -> Result<()> {
        self.ensure_started(eng)?;
        let pos = eng.machine.pos;
        let retract = same_xy(pos, target) && target[2] > pos[2];
        eng.machine.pos = target;
        eng.machine.pos_known = true;
        let section = if self.initial_rapid && eng.has(Section::InitialRapidMove) {
            Section::InitialRapidMove
        } else if retract && eng.has(Section::RetractMove) {
            Section::RetractMove
        } else {
            Section::RapidMove
        };
        self.initial_rapid = false;
        self.family = Family::Rapid;
        eng.run_section(section)?;
        // Vectric prints the feed again on the first feed move after a
        // rapid, changed or not (docs/vectric.md).
        for &v in &self.feed_vars {
            eng.forget_var(v);
        }
        self.after_move(eng, retract)
    }

    fn feed(&mut self, eng: &mut Engine, m: &FeedMove) -> Result<()> {
        Self::set_rotary(eng, m.a, m.b, m.c);
        self.feed_to(eng, [m.x, m.y, m.z], m.intent, m.feed)
    }

    /// The feed for a move: its own, or the tool's by intent.
    fn feed_for(eng: &Engine, intent: Intent, feed: Option<f64>) -> f64 {
        feed.unwrap_or(match intent {
            Intent::Plunge | Intent::Retract => eng.machine.tool.plunge_feed,
            _ => eng.machine.tool.cut_feed,
        })
    }

    fn feed_to(&mut self, eng: &mut Engine, target: [f64; 3], intent: Intent, feed: Option<f64>) -> Result<()> {
        self.ensure_started(eng)?;
        let pos = eng.machine.pos;
        // A move straight along Z is a plunge or retract of a milling tool;
        // a turning tool's Z runs along the spindle, where it cuts.
        let along_z = !eng.machine.tool.turning && same_xy(pos, target);
        let intent = match intent {
            Intent::Cut if along_z && target[2] < pos[2] => Intent::Plunge,
            Intent::Cut if along_z && target[2] > pos[2] => Intent::Retract,
            other => other,
        };
        let feed = Self::feed_for(eng, intent, feed);
        eng.machine.move_from = pos;
        eng.machine.move_length = None;
        eng.machine.pos = target;
        eng.machine.pos_known = true;
        let first_run = |fam: Family, s: &Self| s.family != fam || s.last_feed != Some(feed);
        let (family, section) = match intent {
            Intent::Plunge if first_run(Family::Plunge, self) && eng.has(Section::FirstPlungeMove) => {
                (Family::Plunge, Some(Section::FirstPlungeMove))
            }
            Intent::Plunge if eng.has(Section::PlungeMove) => (Family::Plunge, Some(Section::PlungeMove)),
            Intent::Retract if eng.has(Section::RetractMove) => (Family::Retract, Some(Section::RetractMove)),
            _ => {
                let first = first_run(Family::Feed, self);
                (Family::Feed, pick(eng, Section::FirstFeedMove, Section::FeedMove, first))
            }
        };
        self.print_feed_section(eng, family, section, feed)?;
        self.after_move(eng, intent == Intent::Retract)
    }

    /// Prints a feed-rate section, with FEED_RATE_CHANGE first when the feed changed.
    fn print_feed_section(
        &mut self,
        eng: &mut Engine,
        family: Family,
        section: Option<Section>,
        feed: f64,
    ) -> Result<()> {
        eng.machine.feed = feed;
        if self.last_feed != Some(feed) {
            eng.run_section(Section::FeedRateChange)?;
        }
        self.family = family;
        self.last_feed = Some(feed);
        match section {
            Some(s) => {
                eng.run_section(s)?;
            }
            None => eng.warn_once(
                Diagnostic::warning("RT012", "the post has no FEED_MOVE section, so feed moves print nothing")
                    .help("add `begin FEED_MOVE` with a line such as \"G1[X][Y][Z][F]\""),
            ),
        }
        Ok(())
    }

    fn dwell(&mut self, eng: &mut Engine) -> Result<()> {
        if !eng.run_section(Section::DwellMove)? {
            eng.warn_once(
                Diagnostic::warning("RT010", "the post has no DWELL_MOVE section, so dwells are skipped")
                    .at(eng.event_span, "this dwell (the first of them) is skipped")
                    .help("add a `begin DWELL_MOVE` section (`onDwell()` in a JavaScript post)"),
            );
        }
        Ok(())
    }
}

/// Warns, once for each kind, that an event which changes how the tool
/// cuts reached a post with no handler (`section`) to write it.
fn unwritten(eng: &mut Engine, what: &str, consequence: &str, section: Section) {
    unwritten_at(eng, eng.event_span, what, consequence, section);
}

/// [`unwritten`] of the event at `at`.
fn unwritten_at(eng: &mut Engine, at: postc_ir::Span, what: &str, consequence: &str, section: Section) {
    eng.warn_once(
        Diagnostic::warning(
            "RT035",
            format!("the toolpath asks for {what} here, and the post has no way to write it: {consequence}"),
        )
        .at(at, "this event (the first of its kind) is not written")
        .note(format!("the post has no {} handler", section.name()))
        .help("post with a post that writes it, or set it at the machine by hand"),
    );
}

/// A longhand peck cycle drills a hole in at most this many pecks.
const MAX_PECKS: u32 = 1_000;

/// Linearized arcs are cut into at most this many chords.
const MAX_CHORDS: u32 = 10_000;

/// How far a move's tool axis may lean from +Z and still be upright: the
/// noise of a CL file's unit vector (1e-6 of k is 0.08 degrees).
const UPRIGHT: f64 = 1e-6;

/// Refuses a move the post cannot write as it is: one whose tool axis
/// leans away from +Z (a CL file's `GOTO/x,y,z,i,j,k` of a multi-axis
/// operation; a post driven by the kind of each move writes X, Y and Z
/// only, so the machine would hold the tool upright at the tilted tool's
/// tip point), and one that turns a rotary axis (A, B or C away from 0)
/// the post never reads (the program would cut with the part where it
/// was).
fn check_axes(eng: &Engine, event: &Event, read: [bool; 3]) -> Result<()> {
    let (tool_axis, turns) = match event {
        Event::Rapid(m) => (m.tool_axis, [m.a, m.b, m.c]),
        Event::Feed(m) => (m.tool_axis, [m.a, m.b, m.c]),
        _ => return Ok(()),
    };
    if let Some([i, j, k]) = tool_axis
        && 1.0 - k > UPRIGHT
    {
        let degrees = k.clamp(-1.0, 1.0).acos().to_degrees();
        return Err(Box::new(
            Diagnostic::error(
                "RT040",
                format!(
                    "this move tilts the tool {degrees:.1} degrees from Z (tool axis {i:.4}, {j:.4}, {k:.4}), and the post is handed X, Y and Z only: the machine would hold the tool upright and cut another shape"
                ),
            )
            .at(eng.event_span, "a multi-axis move")
            .help("post a multi-axis toolpath with a post driven by APT words, which is handed the tool axis as I J K, or have the CAM system write this operation for three axes"),
        ));
    }
    for (i, (value, read)) in turns.into_iter().zip(read).enumerate() {
        let Some(degrees) = value.filter(|v| v.abs() > 1e-9) else { continue };
        if read {
            continue;
        }
        let axis = ['A', 'B', 'C'][i];
        return Err(Box::new(
            Diagnostic::error(
                "RT041",
                format!(
                    "this move turns the {axis} axis to {degrees} degrees, and the post writes no {axis} axis: the program would cut with the part where it was"
                ),
            )
            .at(eng.event_span, "a move of a rotary axis")
            .help(format!("post the toolpath with a post that writes the {axis} axis, or have the CAM system write it for three axes")),
        ));
    }
    Ok(())
}

/// Which of the rotary axes A, B and C a post reads anywhere: a variable
/// of the quantity, or the quantity in its code.
fn rotary_read(post: &postc_ir::Post) -> [bool; 3] {
    const ROTARY: [Quantity; 3] = [Quantity::A, Quantity::B, Quantity::C];
    struct Reads([bool; 3]);
    impl postc_ir::visit::Visit for Reads {
        fn visit_expr(&mut self, expr: &postc_ir::Expr) {
            if let postc_ir::Expr::Quantity(q) = expr
                && let Some(i) = ROTARY.iter().position(|r| r == q)
            {
                self.0[i] = true;
            }
            postc_ir::visit::walk_expr(self, expr);
        }
    }
    let mut reads = Reads([false; 3]);
    postc_ir::visit::walk_post(&mut reads, post);
    for v in &post.variables {
        if let postc_ir::ValueSource::Quantity(q) = v.source
            && let Some(i) = ROTARY.iter().position(|r| *r == q)
        {
            reads.0[i] = true;
        }
    }
    reads.0
}

/// Whether any code of the post reads quantity `q`.
fn reads_quantity(post: &postc_ir::Post, q: Quantity) -> bool {
    struct Reads(Quantity, bool);
    impl postc_ir::visit::Visit for Reads {
        fn visit_expr(&mut self, expr: &postc_ir::Expr) {
            self.1 |= matches!(expr, postc_ir::Expr::Quantity(q) if *q == self.0);
            postc_ir::visit::walk_expr(self, expr);
        }
    }
    let mut reads = Reads(q, false);
    postc_ir::visit::walk_post(&mut reads, post);
    reads.1 || post.variables.iter().any(|v| v.source == postc_ir::ValueSource::Quantity(q))
}

/// Refuses events whose numbers are not finite: a NaN or infinite
/// coordinate would otherwise print as 0.
fn check_finite(eng: &Engine, event: &Event) -> Result<()> {
    let numbers: &[f64] = match event {
        Event::Rapid(m) => &[m.x, m.y, m.z],
        Event::Feed(m) => &[m.x, m.y, m.z, m.feed.unwrap_or(0.0)],
        Event::Arc(a) => &[a.x, a.y, a.z, a.cx, a.cy, a.cz, a.feed.unwrap_or(0.0)],
        Event::DrillPoint(p) => &[p.x, p.y, p.z],
        Event::DrillCycle(c) => {
            &[c.retract_plane, c.reference_plane, c.depth, c.peck.unwrap_or(0.0), c.dwell.unwrap_or(0.0)]
        }
        Event::Dwell(d) => &[d.seconds],
        Event::Power(p) => &[p.value],
        _ => return Ok(()),
    };
    if numbers.iter().all(|n| n.is_finite()) {
        return Ok(());
    }
    Err(Box::new(
        Diagnostic::error("RT016", format!("this {} event has a value that is not a finite number", event.name()))
            .at(eng.event_span, "here")
            .help("every coordinate, feed and time must be an ordinary number"),
    ))
}

/// The `FIRST_` section when it applies and exists, else the plain one,
/// else the `FIRST_` one.
fn pick(eng: &Engine, first_section: Section, plain: Section, first: bool) -> Option<Section> {
    if first && eng.has(first_section) {
        Some(first_section)
    } else if eng.has(plain) {
        Some(plain)
    } else if eng.has(first_section) {
        Some(first_section)
    } else {
        None
    }
}

fn same_xy(a: [f64; 3], b: [f64; 3]) -> bool {
    (a[0] - b[0]).abs() <= 1e-9 && (a[1] - b[1]).abs() <= 1e-9
}
