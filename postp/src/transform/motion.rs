//! Positions on their way to the post: TRANS (a translation that replaces
//! the previous one), ROTABL's cylindrical mapping (a linear axis turned
//! into degrees of A or B), the feed of each move, and the motions the post
//! processor computes: RETRCT, CLRSRF/NOW and LETTER.
//!
//! Every computed motion is made in the CL file's coordinates and goes
//! through the same path as the file's own moves, so TRANS and the mapping
//! apply to it too.

use postc_ir::event::{ArcMove, DrillCycle, DrillPoint, Event, FeedMove, Move};
use postc_ir::{Diagnostic, EventSource, Units};
use postc_runtime::geometry::ArcGeometry;

use super::{Transform, codes, word};
use crate::letter::{Letter, Motion};

/// Chord tolerance of arcs cut into moves under cylindrical mapping, mm.
const CHORD_MM: f64 = 0.01;

/// ROTABL/LINEAR: one linear axis turned into rotation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mapping {
    /// 0: X into A; 1: Y into B.
    pub axis: usize,
    pub radius: f64,
    /// The linear coordinate (translated) where the mapping began; the
    /// axis stays there while it lasts.
    pub origin: f64,
    /// The rotary angle where the mapping began.
    pub angle: f64,
}

impl<S: EventSource> Transform<S> {
    fn translated(&self, p: [f64; 3]) -> [f64; 3] {
        [p[0] + self.trans[0], p[1] + self.trans[1], p[2] + self.trans[2]]
    }

    /// The feed of a move: per revolution as written when the last FEDRAT
    /// named a per-revolution unit (the post is told with `FEDRAT/PERREV`),
    /// else the reader's feed per minute.
    fn feed_of(&mut self, feed: Option<f64>) -> Option<f64> {
        let f = self.fedrat;
        let per_rev = f.and_then(|f| f.unit).map(|u| u.per_rev());
        if let Some(p) = per_rev
            && self.per_rev != Some(p)
        {
            self.per_rev = Some(p);
            self.command("FEDRAT", vec![word(if p { "PERREV" } else { "PERMIN" })]);
        }
        match f {
            Some(f) if per_rev == Some(true) => {
                let factor = match (f.unit.and_then(|u| u.units()), self.units) {
                    (Some(Units::Mm), Units::Inch) => 1.0 / 25.4,
                    (Some(Units::Inch), Units::Mm) => 25.4,
                    _ => 1.0,
                };
                Some(f.value * factor)
            }
            _ => feed,
        }
    }

    /// A move to a point in CL coordinates.
    pub(super) fn move_to(&mut self, rapid: bool, p: [f64; 3], feed: Option<f64>, diags: &mut Vec<Diagnostic>) {
        if self.incremental && self.pos.is_none() {
            self.error(
                diags,
                codes::POSITION_UNKNOWN,
                "MODE/91 writes moves as distances, and where the tool is here is not known".into(),
                "after GOHOME, RETRCT to home or before any move",
            );
        }
        if self.machine.kind == super::Kind::Lathe && p[1].abs() > 1e-9 {
            self.warn_once(
                diags,
                "LATHE_Y",
                Diagnostic::warning(codes::AXIS_IGNORED, "a lathe has no Y axis; Y is ignored")
                    .note("lathe CL files give X as the radius and Z along the spindle"),
            );
        }
        self.pos = Some(p);
        let feed = if rapid { None } else { self.feed_of(feed) };
        self.emit(rapid, p, feed);
    }

    /// Writes a move after translation and mapping.
    fn emit(&mut self, rapid: bool, p: [f64; 3], feed: Option<f64>) {
        let q = self.translated(p);
        let (mut x, mut y, z) = (q[0], q[1], q[2]);
        let (mut a, mut b) = (None, None);
        if let Some(m) = self.mapping {
            let angle = m.angle + (q[m.axis] - m.origin).to_degrees() / m.radius;
            if m.axis == 0 {
                x = m.origin;
                a = Some(angle);
                self.angles[0] = angle;
            } else {
                y = m.origin;
                b = Some(angle);
                self.angles[1] = angle;
            }
        }
        let event = if rapid {
            Event::Rapid(Move { x, y, z, a, b, c: None, tool_axis: None })
        } else {
            Event::Feed(FeedMove { x, y, z, feed, a, b, ..FeedMove::default() })
        };
        self.push(event);
    }

    pub(super) fn arc(&mut self, a: ArcMove, diags: &mut Vec<Diagnostic>) {
        let end = [a.x, a.y, a.z];
        let Some(start) = self.pos.filter(|_| self.mapping.is_some()) else {
            let feed = self.feed_of(a.feed);
            self.pos = Some(end);
            let e = self.translated(end);
            let c = self.translated([a.cx, a.cy, a.cz]);
            let arc = ArcMove { x: e[0], y: e[1], z: e[2], cx: c[0], cy: c[1], cz: c[2], feed, ..a };
            self.push(Event::Arc(arc));
            return;
        };
        // Under cylindrical mapping an arc is cut into feed moves.
        let g = ArcGeometry::new(start, end, [a.cx, a.cy, a.cz], a.dir, a.plane);
        let tol = if self.units == Units::Inch { CHORD_MM / 25.4 } else { CHORD_MM };
        let n = g.segments(tol).clamp(1, 10_000);
        for i in 1..=n {
            let p = if i == n { end } else { g.point_at(f64::from(i) / f64::from(n)) };
            self.move_to(false, p, a.feed, diags);
        }
    }

    pub(super) fn cycle(&mut self, mut c: DrillCycle, diags: &mut Vec<Diagnostic>) {
        if !self.needs(super::Kind::Mill, "CYCLE", diags) {
            return;
        }
        if self.incremental || self.mapping.is_some() {
            self.error(
                diags,
                codes::CYCLE_MODE,
                "drilling cycles are written in absolute mode without cylindrical mapping".into(),
                "MODE/91 or ROTABL/LINEAR is in force",
            );
            return;
        }
        let dz = self.trans[2];
        c.retract_plane += dz;
        c.reference_plane += dz;
        if let Some(s) = &mut c.surface {
            *s += dz;
        }
        c.depth += dz;
        self.push(Event::DrillCycle(c));
    }

    pub(super) fn hole(&mut self, p: DrillPoint) {
        let z = self.pos.map_or(p.z, |q| q[2]);
        self.pos = Some([p.x, p.y, z]);
        let q = self.translated([p.x, p.y, p.z]);
        self.push(Event::DrillPoint(DrillPoint { x: q[0], y: q[1], z: q[2] }));
    }

    /// RETRCT: Z to the clearance plane, to `retractz`, or home.
    pub(super) fn retract(&mut self, diags: &mut Vec<Diagnostic>) {
        // A clearance plane is in the CL file's coordinates (TRANS moves it
        // with the part); `retractz` is where the machine goes, untranslated.
        let z = match (self.clearp, self.machine.retractz) {
            (Some(z), _) => z,
            (None, crate::options::RetractZ::At(z)) => z - self.trans[2],
            (None, crate::options::RetractZ::Home) => {
                self.command("RETRCT", Vec::new());
                self.pos = None;
                return;
            }
        };
        let Some(p) = self.pos else {
            self.error(
                diags,
                codes::POSITION_UNKNOWN,
                "RETRCT needs to know where the tool is".into(),
                "no position yet",
            );
            return;
        };
        self.move_to(true, [p[0], p[1], z], None, diags);
    }

    /// CLRSRF/NOW: the tool tip to the plane, along its normal.
    pub(super) fn clear_surface(&mut self, diags: &mut Vec<Diagnostic>) {
        let Some((n, d)) = self.clrsrf else {
            self.error(
                diags,
                codes::BAD_PLANE,
                "CLRSRF/NOW needs a plane: CLRSRF/XYPLAN,d first".into(),
                "no plane defined",
            );
            return;
        };
        let Some(p) = self.pos else {
            self.error(
                diags,
                codes::POSITION_UNKNOWN,
                "CLRSRF/NOW needs to know where the tool is".into(),
                "no position yet",
            );
            return;
        };
        let s = n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - d;
        let target = [p[0] - s * n[0], p[1] - s * n[1], p[2] - s * n[2]];
        self.move_to(true, target, None, diags);
    }

    /// LETTER's moves for the PPRINT text that followed it.
    pub(super) fn engrave(&mut self, letter: Letter, text: &str, diags: &mut Vec<Diagnostic>) {
        let inch = if self.units == Units::Inch { 1.0 } else { 25.4 };
        let (motions, missing) = letter.motions(text, self.pos, inch);
        if !missing.is_empty() {
            let list: String = missing.iter().collect();
            diags.push(
                Diagnostic::warning(codes::LETTER, format!("the engraving font has no `{list}`; engraved as `?`"))
                    .at(self.span, "in this text")
                    .note("the font has the printable ASCII characters"),
            );
        }
        if self.per_rev == Some(true) {
            self.per_rev = Some(false);
            self.command("FEDRAT", vec![word("PERMIN")]);
        }
        for m in motions {
            match m {
                Motion::Rapid(p) => {
                    self.pos = Some(p);
                    self.emit(true, p, None);
                }
                Motion::Feed(p, f) => {
                    self.pos = Some(p);
                    self.emit(false, p, Some(f));
                }
            }
        }
    }

    /// ROTABL/LINEAR,AAXIS|BAXIS[,RADIUS,r] starts cylindrical mapping.
    pub(super) fn start_mapping(&mut self, axis: usize, radius: Option<f64>, diags: &mut Vec<Diagnostic>) -> bool {
        let Some(p) = self.pos else {
            self.error(
                diags,
                codes::POSITION_UNKNOWN,
                "ROTABL/LINEAR needs to know where the tool is".into(),
                "no position yet",
            );
            return false;
        };
        let q = self.translated(p);
        let r = radius.unwrap_or(q[2]).abs();
        if !(r > 1e-9 && r.is_finite()) {
            self.error(
                diags,
                codes::BAD_ARGS,
                "cylindrical mapping needs a radius: the tool is at Z 0 (the rotary centreline)".into(),
                "give ROTABL/LINEAR,..,RADIUS,r",
            );
            return false;
        }
        self.mapping = Some(Mapping { axis, radius: r, origin: q[axis], angle: self.angles[axis] });
        true
    }
}
