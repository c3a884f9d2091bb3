//! Section dispatch: which section prints each event, under the Vectric
//! rules that CIMCO posts share.
//!
//! - The header prints when the first toolpath starts, with the first tool's
//!   data; `SPINDLE_ON` follows it and each `TOOLCHANGE` (not for jet tools,
//!   nor when the speed is negative). Each later toolpath prints
//!   `TOOLCHANGE` when the tool number changes, then `NEW_SEGMENT`. Modal
//!   memory is cleared as a toolpath starts, so its first move prints every
//!   word.
//! - `FIRST_` sections print the first move of a run of moves of their kind
//!   and again after the feed rate changes; otherwise the plain section.
//!   A missing `FIRST_` section falls back to the plain one, and the other
//!   way round. Plunges without plunge sections, and retracts without
//!   `RETRACT_MOVE`, print as feed (or rapid) moves.
//! - Arcs without arc sections, arcs larger than `MAX_ARC_RADIUS` and arcs
//!   outside the XY plane are linearized into feed moves; arcs smaller than
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

use postc_ir::event::{ArcDir, ArcMove, DrillCycle, DrillKind, DrillPoint, Event, FeedMove, Intent, Move, Plane};
use postc_ir::{Diagnostic, Quantity, Section};

use crate::engine::Engine;
use crate::geometry::ArcGeometry;

type Result<T> = std::result::Result<T, Box<Diagnostic>>;

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
    drill: Option<DrillCycle>,
    /// Tape splitting: the current part ends before the next block.
    split_pending: bool,
    /// Formats of the X and Y variables, to know the printed points.
    xy_formats: [Option<u16>; 2],
    exact_arcs: bool,
}

impl SectionDispatch {
    pub fn new(eng: &Engine, exact_arcs: bool) -> SectionDispatch {
        let format_of = |q| {
            eng.post
                .variables
                .iter()
                .find(|v| v.source == postc_ir::ValueSource::Quantity(q))
                .map(|v| v.format)
        };
        SectionDispatch {
            started: false,
            finished: false,
            tool_changed: false,
            last_tool: None,
            initial_rapid: true,
            family: Family::None,
            last_feed: None,
            spindle_on: false,
            drill: None,
            split_pending: false,
            xy_formats: [format_of(Quantity::X), format_of(Quantity::Y)],
            exact_arcs: exact_arcs || eng.post.options.exact_arcs,
        }
    }

    /// Handles one event.
    pub fn event(&mut self, eng: &mut Engine, event: &Event) -> Result<()> {
        check_finite(eng, event)?;
        match event {
            Event::Job(job) => {
                if self.started {
                    eng.warn_once(Diagnostic::warning("RT011", "a second Job event came after output began; it is ignored")
                        .at(eng.event_span, "this Job event"));
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
                    let units = eng.post.info.units;
                    eng.machine.set_job((**job).clone(), units);
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
                let changed = speed != eng.machine.spindle_speed;
                eng.machine.spindle_speed = speed;
                // SPINDLE_ON prints when the spindle starts, or runs on at a new speed.
                if self.started && (!self.spindle_on || changed) && !eng.machine.tool.jet {
                    self.spindle_on = eng.run_section(Section::SpindleOn)?;
                }
            }
            Event::SpindleOff => {
                if self.started {
                    eng.run_section(Section::SpindleOff)?;
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
                eng.machine.power = p.value;
                self.ensure_started(eng)?;
                eng.run_section(Section::JetToolPower)?;
            }
            Event::Coolant(_) => {
                if self.started {
                    eng.run_section(Section::Coolant)?;
                }
            }
            Event::CutterComp(c) => {
                eng.machine.comp_register = f64::from(c.register.unwrap_or(eng.machine.tool.number));
                if self.started {
                    eng.run_section(Section::CutterComp)?;
                }
            }
            Event::DrillCycle(c) => {
                self.ensure_started(eng)?;
                eng.run_section(Section::DrillHeader)?;
                self.drill = Some(c.clone());
            }
            Event::DrillPoint(p) => {
                self.ensure_started(eng)?;
                self.drill_point(eng, *p)?;
            }
            Event::DrillEnd => {
                if self.started {
                    eng.run_section(Section::DrillFooter)?;
                }
                self.drill = None;
            }
            Event::Comment(t) => {
                eng.machine.comment.clone_from(&t.text);
                if self.started {
                    eng.run_section(Section::Comment)?;
                }
            }
            Event::Insert(t) => {
                self.ensure_started(eng)?;
                eng.machine.comment.clone_from(&t.text);
                if !eng.run_section(Section::Insert)? {
                    let text = std::mem::take(&mut eng.machine.comment);
                    eng.write_blocks(&text);
                    eng.machine.comment = text;
                }
            }
            Event::Command(_) => {}
            Event::End => self.finish(eng)?,
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

    /// Ends the current tape-split part with the footer when a split is
    /// due; the next part starts (with the header) at its first block.
    fn split_if_pending(&mut self, eng: &mut Engine) -> Result<()> {
        if !self.split_pending {
            return Ok(());
        }
        self.split_pending = false;
        eng.run_section(Section::Footer)?;
        eng.out.new_part();
        self.started = false;
        Ok(())
    }

    fn start_program(&mut self, eng: &mut Engine) -> Result<()> {
        eng.run_section(Section::Header)?;
        self.spindle_on = Self::spindle_tool(eng) && eng.run_section(Section::SpindleOn)?;
        self.initial_rapid = true;
        Ok(())
    }

    fn fresh_modal_state(&mut self, eng: &mut Engine) {
        eng.clear_modal();
        self.family = Family::None;
        self.last_feed = None;
    }

    fn point(eng: &Engine, x: f64, y: f64, z: f64) -> [f64; 3] {
        [eng.machine.len(x), eng.machine.len(y), eng.machine.len(z)]
    }

    fn set_rotary(eng: &mut Engine, a: Option<f64>, b: Option<f64>, c: Option<f64>) {
        for (slot, v) in [a, b, c].into_iter().enumerate() {
            if let Some(v) = v {
                eng.machine.rotary[slot] = v;
            }
        }
    }

    fn rapid(&mut self, eng: &mut Engine, m: &Move) -> Result<()> {
        let target = Self::point(eng, m.x, m.y, m.z);
        Self::set_rotary(eng, m.a, m.b, m.c);
        self.rapid_to(eng, target)
    }

    fn rapid_to(&mut self, eng: &mut Engine, target: [f64; 3]) -> Result<()> {
        self.ensure_started(eng)?;
        let pos = eng.machine.pos;
        let retract = same_xy(pos, target) && target[2] > pos[2];
        eng.machine.pos = target;
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
        self.after_move(eng, retract)
    }

    fn feed(&mut self, eng: &mut Engine, m: &FeedMove) -> Result<()> {
        let target = Self::point(eng, m.x, m.y, m.z);
        Self::set_rotary(eng, m.a, m.b, m.c);
        let feed = m.feed.map(|f| eng.machine.len(f));
        self.feed_to(eng, target, m.intent, feed)
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
        let intent = match intent {
            Intent::Cut if same_xy(pos, target) && target[2] < pos[2] => Intent::Plunge,
            Intent::Cut if same_xy(pos, target) && target[2] > pos[2] => Intent::Retract,
            other => other,
        };
        let feed = Self::feed_for(eng, intent, feed);
        eng.machine.move_from = pos;
        eng.machine.move_length = None;
        eng.machine.pos = target;
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
    fn print_feed_section(&mut self, eng: &mut Engine, family: Family, section: Option<Section>, feed: f64) -> Result<()> {
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

    fn arc(&mut self, eng: &mut Engine, a: &ArcMove) -> Result<()> {
        let start = eng.machine.pos;
        let end = Self::point(eng, a.x, a.y, a.z);
        let centre = Self::point(eng, a.cx, a.cy, a.cz);
        let geometry = ArcGeometry::new(start, end, centre, a.dir, a.plane);
        let feed = a.feed.map(|f| eng.machine.len(f));
        let options = &eng.post.options;
        let unit = eng.machine.output_units.factor_to(postc_ir::Units::Mm).recip();
        if options.min_arc_radius.is_some_and(|min| geometry.radius < min) {
            return self.feed_to(eng, end, a.intent, feed);
        }
        let too_big = options.max_arc_radius.is_some_and(|max| geometry.radius > max);
        let tolerance = options.arc_tolerance * unit;
        if too_big || a.plane != Plane::Xy || !geometry.radius.is_finite() || geometry.radius <= 0.0 {
            return self.linearize(eng, &geometry, a.intent, feed, tolerance);
        }
        let Some((family, section)) = self.arc_section(eng, &geometry, a) else {
            return self.linearize(eng, &geometry, a.intent, feed, tolerance);
        };
        let feed = Self::feed_for(eng, a.intent, feed);
        eng.machine.arc = if self.exact_arcs { self.exact(eng, &geometry, a.dir) } else { geometry };
        eng.machine.move_from = start;
        eng.machine.move_length = Some(geometry.length());
        eng.machine.pos = end;
        self.print_feed_section(eng, family, Some(section), feed)?;
        self.after_move(eng, false)
    }

    /// The section an arc prints through, or `None` to linearize it.
    fn arc_section(&self, eng: &Engine, g: &ArcGeometry, a: &ArcMove) -> Option<(Family, Section)> {
        let feed = Self::feed_for(eng, a.intent, a.feed.map(|f| eng.machine.len(f)));
        let first = |fam: Family| self.family != fam || self.last_feed != Some(feed);
        let cw = a.dir == ArcDir::Cw;
        let flat = if cw { (Section::FirstCwArcMove, Section::CwArcMove) } else { (Section::FirstCcwArcMove, Section::CcwArcMove) };
        if g.is_helical() {
            if a.intent == Intent::Plunge {
                let (f, p) = if cw {
                    (Section::FirstCwHelicalArcPlungeMove, Section::CwHelicalArcPlungeMove)
                } else {
                    (Section::FirstCcwHelicalArcPlungeMove, Section::CcwHelicalArcPlungeMove)
                };
                let fam = Family::Arc(a.dir, Helix::Plunge);
                if let Some(s) = pick(eng, f, p, first(fam)) {
                    return Some((fam, s));
                }
            }
            let (f, p) = if cw {
                (Section::FirstCwHelicalArcMove, Section::CwHelicalArcMove)
            } else {
                (Section::FirstCcwHelicalArcMove, Section::CcwHelicalArcMove)
            };
            let fam = Family::Arc(a.dir, Helix::Helical);
            if let Some(s) = pick(eng, f, p, first(fam)) {
                return Some((fam, s));
            }
            let fam = Family::Arc(a.dir, Helix::Flat);
            let s = pick(eng, flat.0, flat.1, first(fam))?;
            return eng.section_prints(s, Quantity::Z).then_some((fam, s));
        }
        let fam = Family::Arc(a.dir, Helix::Flat);
        pick(eng, flat.0, flat.1, first(fam)).map(|s| (fam, s))
    }

    /// The arc as the controller reads it: printed start and end points and
    /// a centre equidistant from both.
    fn exact(&self, eng: &Engine, g: &ArcGeometry, dir: ArcDir) -> ArcGeometry {
        let printed = |p: [f64; 3]| {
            let mut q = p;
            for (axis, format) in self.xy_formats.iter().enumerate() {
                if let Some(f) = format {
                    q[axis] = eng.writers[*f as usize].printed_value(p[axis]);
                }
            }
            q
        };
        g.exact(printed(g.start), printed(g.end), dir)
    }

    fn linearize(&mut self, eng: &mut Engine, g: &ArcGeometry, intent: Intent, feed: Option<f64>, tol: f64) -> Result<()> {
        let mut n = g.segments(tol);
        if n > MAX_CHORDS {
            eng.warn_once(
                Diagnostic::warning(
                    "RT017",
                    format!("an arc of radius {:.3} needs more than {MAX_CHORDS} chords to stay within the tolerance; it is cut into {MAX_CHORDS}", g.radius),
                )
                .at(eng.event_span, "this arc"),
            );
            n = MAX_CHORDS;
        }
        for i in 1..=n {
            let p = g.point_at(f64::from(i) / f64::from(n));
            self.feed_to(eng, p, intent, feed)?;
        }
        Ok(())
    }

    fn dwell(&mut self, eng: &mut Engine) -> Result<()> {
        if !eng.run_section(Section::DwellMove)? {
            eng.warn_once(Diagnostic::warning("RT010", "the post has no DWELL_MOVE section, so dwells are skipped"));
        }
        Ok(())
    }

    /// One hole: through DRILL_POINT, or as moves when the post has no drilling sections.
    fn drill_point(&mut self, eng: &mut Engine, p: DrillPoint) -> Result<()> {
        let at = Self::point(eng, p.x, p.y, p.z);
        if eng.has(Section::DrillPoint) {
            eng.machine.pos = at;
            eng.run_section(Section::DrillPoint)?;
            return Ok(());
        }
        let Some(cycle) = self.drill.clone() else {
            return Err(Box::new(
                Diagnostic::error("RT013", "a DrillPoint came outside a drilling cycle").at(eng.event_span, "this hole"),
            ));
        };
        let factor = eng.machine.factor;
        let len = |v: f64| v * factor;
        let (clear, reference, depth) = (len(cycle.retract_plane), len(cycle.reference_plane), len(cycle.depth));
        let feed = cycle.feed.map(len);
        let pos = eng.machine.pos;
        if pos[2] < clear {
            self.rapid_to(eng, [pos[0], pos[1], clear])?;
        }
        self.rapid_to(eng, [at[0], at[1], clear])?;
        if reference < clear {
            self.rapid_to(eng, [at[0], at[1], reference])?;
        }
        let mut peck = cycle.peck.map(len).filter(|p| *p > 0.0 && matches!(cycle.kind, DrillKind::Deep | DrillKind::ChipBreak));
        if let Some(p) = peck
            && (reference - depth) / p > f64::from(MAX_PECKS)
        {
            eng.warn_once(
                Diagnostic::warning(
                    "RT018",
                    format!("a peck of {p} would need more than {MAX_PECKS} pecks for this hole; it is drilled in {MAX_PECKS}"),
                )
                .at(eng.event_span, "this hole"),
            );
            peck = Some((reference - depth) / f64::from(MAX_PECKS));
        }
        let mut z = reference;
        while let Some(step) = peck.filter(|_| z - depth > 1e-9) {
            z = (z - step).max(depth);
            self.feed_to(eng, [at[0], at[1], z], Intent::Plunge, feed)?;
            if z > depth {
                let back = if cycle.kind == DrillKind::Deep { reference } else { z + 0.5 * step };
                self.rapid_to(eng, [at[0], at[1], back])?;
                self.rapid_to(eng, [at[0], at[1], z])?;
            }
        }
        if peck.is_none() {
            self.feed_to(eng, [at[0], at[1], depth], Intent::Plunge, feed)?;
        }
        if let Some(d) = cycle.dwell.filter(|d| *d > 0.0) {
            eng.machine.dwell = d;
            self.dwell(eng)?;
        }
        self.rapid_to(eng, [at[0], at[1], clear])
    }

    /// Tape splitting after a move.
    fn after_move(&mut self, eng: &mut Engine, retract: bool) -> Result<()> {
        let Some(tape) = &eng.post.options.tape_splitting else { return Ok(()) };
        let blocks = eng.out.blocks_in_part();
        // A retract that stops below safe Z (a peck back to the R plane, a
        // feed retract before the rapid up) is no place to end a part: the
        // next part would start from the header's position with a move
        // down into the cut.
        let clear = eng.machine.job.safe_z.is_none_or(|z| eng.machine.pos[2] >= z - 1e-9 * z.abs().max(1.0));
        let soft = retract && clear && blocks + tape.tolerance >= tape.max_lines;
        let hard = blocks >= tape.max_lines;
        if !(soft || hard) {
            return Ok(());
        }
        if self.split_pending {
            return Ok(());
        }
        if hard && !soft {
            eng.warn_once(Diagnostic::warning(
                "RT014",
                format!(
                    "a part reached {} lines with no retract in its last {}; it was split inside a cut",
                    tape.max_lines, tape.tolerance
                ),
            ).help("raise the TAPE_SPLITTING tolerance so that a retract falls inside it"));
        }
        self.split_pending = true;
        Ok(())
    }
}

/// A longhand peck cycle drills a hole in at most this many pecks.
const MAX_PECKS: u32 = 1_000;

/// Linearized arcs are cut into at most this many chords.
const MAX_CHORDS: u32 = 10_000;

/// Refuses events whose numbers are not finite: a NaN or infinite
/// coordinate would otherwise print as 0.
fn check_finite(eng: &Engine, event: &Event) -> Result<()> {
    let numbers: &[f64] = match event {
        Event::Rapid(m) => &[m.x, m.y, m.z],
        Event::Feed(m) => &[m.x, m.y, m.z, m.feed.unwrap_or(0.0)],
        Event::Arc(a) => &[a.x, a.y, a.z, a.cx, a.cy, a.cz, a.feed.unwrap_or(0.0)],
        Event::DrillPoint(p) => &[p.x, p.y, p.z],
        Event::DrillCycle(c) => &[c.retract_plane, c.reference_plane, c.depth, c.peck.unwrap_or(0.0), c.dwell.unwrap_or(0.0)],
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

#[cfg(test)]
mod tests {
    use postc_ir::event::{Job, Tool, ToolpathStart, VecSource};
    use postc_ir::post::TapeSplitting;
    use postc_ir::{FileId, Handler, HandlerKey, NumberFormat, Piece, Post, Stmt, ValueSource, Variable};

    use super::*;
    use crate::{Finished, Output, RunOptions};

    /// A post that prints each section's name and, for moves, Z; split
    /// into parts of at most `max` blocks, at a retract once a part has
    /// `max - tolerance`.
    fn tape_post(max_lines: u64, tolerance: u64) -> Post {
        let mut post = Post::default();
        post.formats.push(NumberFormat { decimals: 0, ..NumberFormat::default() });
        post.variables.push(Variable {
            name: "Z".into(),
            source: ValueSource::Quantity(Quantity::Z),
            prefix: b"Z".to_vec(),
            format: 0,
            modality: postc_ir::Modality::Always,
        });
        post.variables.push(Variable {
            name: "T".into(),
            source: ValueSource::Quantity(Quantity::Tool),
            prefix: b"T".to_vec(),
            format: 0,
            modality: postc_ir::Modality::Always,
        });
        let line = |text: &str, var: Option<u16>| {
            let mut pieces = vec![Piece::Text(text.as_bytes().to_vec())];
            pieces.extend(var.map(Piece::Var));
            Stmt::Line(pieces)
        };
        for (section, text, var) in [
            (Section::Header, "HEADER ", Some(1)),
            (Section::Footer, "FOOTER ", Some(1)),
            (Section::ToolChange, "TOOLCHANGE ", Some(1)),
            (Section::NewSegment, "NEW_SEGMENT", None),
            (Section::RapidMove, "RAPID ", Some(0)),
            (Section::FeedMove, "FEED ", Some(0)),
        ] {
            post.handlers.push(Handler { key: HandlerKey::Section(section), body: vec![line(text, var)], span: None });
        }
        post.options.tape_splitting = Some(TapeSplitting {
            max_lines,
            tolerance,
            name_format: "%s_%d.nc".into(),
            start_index: 1,
            index_on_first_file: true,
        });
        post
    }

    fn parts(post: &Post, events: Vec<Event>) -> Vec<String> {
        let mut source = VecSource::new(events, FileId(0));
        let report = crate::run(post, &mut source, Output::memory(), RunOptions::default()).unwrap_or_else(|d| panic!("{d:?}"));
        match report.output {
            Finished::Memory(parts) => parts.into_iter().map(|p| String::from_utf8(p).unwrap()).collect(),
            _ => unreachable!(),
        }
    }

    /// A pass away from home (so its first rapid is no retract) that ends
    /// with a retract.
    fn pass(x: f64) -> Vec<Event> {
        vec![
            Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
            Event::Feed(FeedMove { x, y: 0.0, z: -1.0, ..FeedMove::default() }),
            Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
        ]
    }

    fn tool(number: u32) -> Event {
        Event::Tool(Tool { number, ..Tool::default() })
    }

    #[test]
    fn a_split_due_at_the_last_retract_makes_no_empty_part() {
        let mut events = vec![Event::Job(Box::default()), tool(1), Event::ToolpathStart(ToolpathStart::default())];
        events.extend(pass(1.0));
        events.push(Event::ToolpathEnd);
        events.push(Event::End);
        assert_eq!(parts(&tape_post(4, 2), events), ["HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n"]);
    }

    #[test]
    fn a_split_waits_for_the_next_move_and_restarts_with_the_header() {
        let mut events = vec![Event::Job(Box::default()), tool(1), Event::ToolpathStart(ToolpathStart::default())];
        events.extend(pass(1.0));
        events.extend(pass(2.0));
        events.push(Event::End);
        assert_eq!(
            parts(&tape_post(4, 2), events),
            [
                "HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n",
                "HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n",
            ]
        );
    }

    #[test]
    fn a_split_at_a_tool_change_starts_the_part_like_a_program() {
        let mut events = vec![Event::Job(Box::default()), tool(1), Event::ToolpathStart(ToolpathStart::default())];
        events.extend(pass(1.0));
        events.push(Event::ToolpathEnd);
        events.push(tool(2));
        events.push(Event::ToolpathStart(ToolpathStart::default()));
        events.extend(pass(1.0));
        events.push(Event::End);
        // The old part's footer still has tool 1; the new part's header
        // loads tool 2, with no TOOLCHANGE or NEW_SEGMENT.
        assert_eq!(
            parts(&tape_post(4, 2), events),
            [
                "HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n",
                "HEADER T2\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T2\n",
            ]
        );
    }

    #[test]
    fn a_part_ends_only_at_a_retract_that_reaches_safe_z() {
        let job = Job { safe_z: Some(5.0), ..Job::default() };
        let mut events = vec![Event::Job(Box::new(job)), tool(1), Event::ToolpathStart(ToolpathStart::default())];
        for x in [1.0, 2.0] {
            events.extend([
                Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
                Event::Feed(FeedMove { x, y: 0.0, z: -1.0, ..FeedMove::default() }),
                // A feed retract to just above the surface: no split here,
                // or the next part would start with the rapid up alone.
                Event::Feed(FeedMove { x, y: 0.0, z: 0.0, intent: Intent::Retract, ..FeedMove::default() }),
                Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
            ]);
        }
        events.push(Event::End);
        let pass = "RAPID Z5\nFEED Z-1\nFEED Z0\nRAPID Z5\n";
        assert_eq!(
            parts(&tape_post(6, 3), events),
            [format!("HEADER T1\n{pass}FOOTER T1\n"), format!("HEADER T1\n{pass}FOOTER T1\n")]
        );
    }

    #[test]
    fn a_wrapped_post_warns_when_the_job_has_no_wrap_diameter() {
        let mut post = tape_post(100, 10);
        post.options.rotary_wrap =
            Some(postc_ir::post::RotaryWrap { axis: postc_ir::post::WrappedAxis::Y, letter: Some('A'), reversed: false });
        let run = |job: Job| {
            let events = vec![Event::Job(Box::new(job)), tool(1), Event::ToolpathStart(ToolpathStart::default()), Event::End];
            let mut source = VecSource::new(events, FileId(0));
            let report = crate::run(&post, &mut source, Output::memory(), RunOptions::default()).unwrap_or_else(|d| panic!("{d:?}"));
            report.warnings.iter().map(|w| w.code.to_string()).collect::<Vec<_>>()
        };
        assert_eq!(run(Job::default()), ["RT015"]);
        assert!(run(Job { wrap_diameter: Some(40.0), ..Job::default() }).is_empty());
    }
}
