//! Records that move the tool: GOTO (a straight move, the end of an arc, or
//! a hole of a drilling cycle), RAPID (the next move only), CIRCLE (the arc
//! the next GOTO follows), FROM, GODLTA, GOHOME with a point, and CATIA's
//! `TLON,GOFWD/(CIRCLE/...),ON,(LINE/...)` after INDIRV.

use postc_ir::diagnostic::{Diagnostic, Span};
use postc_ir::event::{Command, DrillPoint, Event, FeedMove, Intent, Move, Point};
use postc_ir::units::Units;

use crate::circle::{ArcOutcome, CircleSpec, V3, build_arc, parse_circle, parse_drive_circle, unit};
use crate::cycle::drill_cycle;
use crate::diagnostics as diag;
use crate::state::{Core, Flow};
use crate::words::{Arg, Problem, Rec};

/// Chord tolerance for arcs cut into straight moves, in millimetres.
const CHORD_TOLERANCE_MM: f64 = 0.01;

/// Reads a point (x,y,z) and an optional tool axis (i,j,k).
fn point_and_axis(rec: &Rec<'_>, word: &str) -> Result<(V3, Option<V3>), Problem> {
    if let Some(i) = rec.first_non_number() {
        if let Some(Arg::Word(w)) = rec.arg(i)
            && not_a_number(w)
        {
            return Err(Problem::new(
                format!(
                    "`{}` is not a number: {word} takes finite numbers (x,y,z or x,y,z,i,j,k)",
                    String::from_utf8_lossy(w)
                ),
                Some(i),
            ));
        }
        return Err(Problem::new(format!("{word} takes numbers only: {word}/x,y,z or {word}/x,y,z,i,j,k"), Some(i)));
    }
    let mut v = [0.0; 6];
    match rec.numbers(&mut v) {
        3 => Ok(([v[0], v[1], v[2]], None)),
        6 => match unit([v[3], v[4], v[5]]) {
            Some(axis) => Ok(([v[0], v[1], v[2]], Some(axis))),
            None => Err(Problem::new("the tool axis (values 4 to 6) is a zero vector", Some(3))),
        },
        n => Err(Problem::new(format!("{word} needs 3 values (x,y,z) or 6 (x,y,z,i,j,k); this one has {n}"), None)),
    }
}

/// Whether a motion record names geometry instead of giving numbers, as an
/// APT part program does (`GOTO/PT1`, `FROM/SETPT`).
fn names_geometry(rec: &Rec<'_>) -> bool {
    matches!(rec.arg(0), Some(Arg::Word(w)) if !not_a_number(w))
}

/// A word that spells a value that is no finite number (`NaN`, `INF`,
/// `Infinity`, as programs that print floats write them): a bad value in CL
/// data, not the name of a point.
fn not_a_number(word: &[u8]) -> bool {
    let word = word.strip_prefix(b"-").or_else(|| word.strip_prefix(b"+")).unwrap_or(word);
    ["NAN", "INF", "INFINITY"].iter().any(|n| word.eq_ignore_ascii_case(n.as_bytes()))
}

impl Core {
    /// The current feed rate, per minute in the job's units.
    /// A cutting move before any FEDRAT has none (CL025, said once).
    fn feed_now(&mut self, span: Span, diags: &mut Vec<Diagnostic>) -> Option<f64> {
        let Some(feed) = self.feed else {
            if !self.warned_no_feed {
                self.warned_no_feed = true;
                diags.push(diag::no_feed(span));
            }
            return None;
        };
        let rpm = self.spindle.speed.filter(|s| *s > 0.0 && !self.spindle.css);
        if feed.per_rev && rpm.is_none() && !self.warned_per_rev {
            self.warned_per_rev = true;
            diags.push(diag::feed_per_rev(span));
        }
        Some(feed.per_minute(self.units, rpm))
    }

    /// A straight move to `p`.
    fn linear(&mut self, p: V3, axis: Option<V3>, rapid: bool, span: Span, diags: &mut Vec<Diagnostic>) {
        if axis.is_some() {
            self.axis = axis;
        }
        let rapid = std::mem::take(&mut self.rapid) || rapid;
        let event = if rapid {
            Event::Rapid(Move { x: p[0], y: p[1], z: p[2], a: None, b: None, c: None, tool_axis: self.axis })
        } else {
            let intent = match self.pos {
                Some(s) if (p[0] - s[0]).abs() < 1e-9 && (p[1] - s[1]).abs() < 1e-9 && p[2] < s[2] => Intent::Plunge,
                _ => Intent::Cut,
            };
            let feed = self.feed_now(span, diags);
            Event::Feed(FeedMove {
                x: p[0],
                y: p[1],
                z: p[2],
                intent,
                feed,
                a: None,
                b: None,
                c: None,
                tool_axis: self.axis,
            })
        };
        self.pos = Some(p);
        self.emit_motion(event, span);
    }

    pub fn goto(&mut self, rec: &Rec<'_>, diags: &mut Vec<Diagnostic>) -> Flow {
        if names_geometry(rec) {
            return Flow::PartProgram("GOTO names a point instead of giving its coordinates", rec.span());
        }
        let span = rec.span();
        let (p, axis) = match point_and_axis(rec, "GOTO") {
            Ok(v) => v,
            Err(problem) => {
                self.report(rec, "GOTO", problem, diags);
                return Flow::Continue;
            }
        };
        if self.cycle.is_some() {
            self.drill_point(p, axis, span, diags);
        } else if let Some((spec, _)) = self.circle.take() {
            self.arc(&spec, p, axis, span, diags);
        } else {
            self.linear(p, axis, false, span, diags);
        }
        Flow::Continue
    }

    fn report(&self, rec: &Rec<'_>, word: &str, problem: Problem, diags: &mut Vec<Diagnostic>) {
        let at = problem.arg.map_or(rec.span(), |i| rec.arg_span(i));
        diags.push(diag::bad_args(at, format!("{word}: {}", problem.message), "see the record's forms in docs/apt.md"));
    }

    fn arc(&mut self, spec: &CircleSpec, p: V3, axis: Option<V3>, span: Span, diags: &mut Vec<Diagnostic>) {
        if axis.is_some() {
            self.axis = axis;
        }
        self.rapid = false;
        let feed = self.feed_now(span, diags);
        let tolerance = CHORD_TOLERANCE_MM * Units::Mm.factor_to(self.units);
        match build_arc(spec, self.pos, p, feed, tolerance) {
            ArcOutcome::Arc { arc, off_circle } => {
                if let Some((start, end)) = off_circle {
                    diags.push(diag::arc_off_circle(span, start, end));
                }
                self.pos = Some(p);
                self.emit_motion(Event::Arc(arc), span);
            }
            ArcOutcome::Linear(points) => {
                diags.push(diag::tilted_arc(span, points.len()));
                for q in points {
                    let event = Event::Feed(FeedMove {
                        x: q[0],
                        y: q[1],
                        z: q[2],
                        intent: Intent::Cut,
                        feed,
                        a: None,
                        b: None,
                        c: None,
                        tool_axis: self.axis,
                    });
                    self.emit_motion(event, span);
                }
                self.pos = Some(p);
            }
        }
    }

    fn drill_point(&mut self, p: V3, axis: Option<V3>, span: Span, diags: &mut Vec<Diagnostic>) {
        if axis.is_some() {
            self.axis = axis;
        }
        self.rapid = false;
        let Some(cycle) = self.cycle.as_ref() else { return };
        let units = self.units;
        let rpm = self.spindle.speed.filter(|s| *s > 0.0);
        let feed = match cycle.spec.feed {
            Some(f) => Some(f.per_minute(units, rpm)),
            None => self.feed_now(span, diags),
        };
        let Some(cycle) = self.cycle.as_mut() else { return };
        let header = drill_cycle(&cycle.spec, p[2], cycle.clearance_z, feed);
        let retract = header.retract_plane;
        if cycle.header_z != Some(p[2]) {
            let first = cycle.header_z.is_none();
            cycle.header_z = Some(p[2]);
            if !first {
                self.emit(Event::DrillEnd, span);
            }
            self.emit_motion(Event::DrillCycle(header), span);
        }
        self.pos = Some([p[0], p[1], retract]);
        self.emit_motion(Event::DrillPoint(DrillPoint { x: p[0], y: p[1], z: p[2] }), span);
    }

    /// Drops a CIRCLE that no GOTO followed.
    pub fn drop_circle(&mut self, next: Option<Span>, diags: &mut Vec<Diagnostic>) {
        if let Some((_, span)) = self.circle.take() {
            diags.push(diag::circle_without_goto(span, next));
        }
    }

    pub fn circle_record(&mut self, rec: &Rec<'_>, diags: &mut Vec<Diagnostic>) -> Result<(), Problem> {
        self.drop_circle(Some(rec.span()), diags);
        let (spec, ignored) = parse_circle(rec)?;
        if let Some(i) = ignored {
            diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "CIRCLE"));
        }
        self.circle = Some((spec, rec.span()));
        Ok(())
    }

    pub fn from(&mut self, rec: &Rec<'_>) -> Result<(), Problem> {
        let (p, axis) = point_and_axis(rec, "FROM")?;
        self.pos = Some(p);
        if axis.is_some() {
            self.axis = axis;
        }
        if let Some(job) = &mut self.job {
            job.home.get_or_insert(Point { x: p[0], y: p[1], z: p[2] });
        }
        self.emit(Event::Command(Command { word: "FROM".to_string(), args: rec.command_args() }), rec.span());
        Ok(())
    }

    pub fn godlta(&mut self, rec: &Rec<'_>, diags: &mut Vec<Diagnostic>) -> Result<(), Problem> {
        self.drop_circle(Some(rec.span()), diags);
        if let Some(i) = rec.first_non_number() {
            return Err(Problem::new("GODLTA takes numbers only: GODLTA/dx,dy,dz or GODLTA/d", Some(i)));
        }
        let mut v = [0.0; 3];
        let delta = match rec.numbers(&mut v) {
            1 => {
                let a = self.axis.unwrap_or([0.0, 0.0, 1.0]);
                [a[0] * v[0], a[1] * v[0], a[2] * v[0]]
            }
            3 => v,
            n => {
                return Err(Problem::new(
                    format!("GODLTA needs 1 value (along the tool axis) or 3 (dx,dy,dz); this one has {n}"),
                    None,
                ));
            }
        };
        let Some(s) = self.pos else {
            return Err(Problem::new("GODLTA moves from the current position, and no position is known yet", None));
        };
        self.linear([s[0] + delta[0], s[1] + delta[1], s[2] + delta[2]], None, false, rec.span(), diags);
        Ok(())
    }

    pub fn gohome(&mut self, rec: &Rec<'_>, diags: &mut Vec<Diagnostic>) -> Result<(), Problem> {
        if rec.len() == 0 {
            self.emit(Event::Command(Command { word: "GOHOME".to_string(), args: Vec::new() }), rec.span());
            return Ok(());
        }
        self.drop_circle(Some(rec.span()), diags);
        let (p, axis) = point_and_axis(rec, "GOHOME")?;
        self.linear(p, axis, true, rec.span(), diags);
        Ok(())
    }

    pub fn drive_motion(&mut self, rec: &Rec<'_>, diags: &mut Vec<Diagnostic>) -> Flow {
        if names_geometry(rec) {
            return Flow::PartProgram("a drive statement along named geometry", rec.span());
        }
        self.drop_circle(Some(rec.span()), diags);
        let indirv = self.indirv.take();
        match parse_drive_circle(rec, self.pos, indirv) {
            Ok((spec, end)) => {
                if indirv.is_none() {
                    diags.push(diag::no_indirv(rec.span()));
                }
                self.arc(&spec, end, None, rec.span(), diags);
            }
            Err(problem) => self.report(rec, &rec.word(), problem, diags),
        }
        Flow::Continue
    }
}
