//! Arcs under the section rules: which arc section prints an arc, the
//! helix fallbacks, radius-exact arc words, and linearization into feed
//! moves (for posts without arc sections, arcs past MAX_ARC_RADIUS, arcs
//! outside the XY plane, arcs of a post that wraps an axis around a
//! cylinder).

use postc_ir::event::{ArcDir, ArcMove, Intent, Plane};
use postc_ir::{Diagnostic, Quantity, Section};

use super::{Family, Helix, MAX_CHORDS, Result, SectionDispatch, pick};
use crate::engine::Engine;
use crate::geometry::ArcGeometry;

impl SectionDispatch {
    pub(super) fn arc(&mut self, eng: &mut Engine, a: &ArcMove) -> Result<()> {
        let start = eng.machine.pos;
        let end = [a.x, a.y, a.z];
        let centre = [a.cx, a.cy, a.cz];
        let geometry = ArcGeometry::new(start, end, centre, a.dir, a.plane);
        let feed = a.feed;
        let options = &eng.post.options;
        let unit = eng.machine.output_units.factor_to(postc_ir::Units::Mm).recip();
        if options.min_arc_radius.is_some_and(|min| geometry.radius < min) {
            return self.feed_to(eng, end, a.intent, feed);
        }
        let too_big = options.max_arc_radius.is_some_and(|max| geometry.radius > max);
        let tolerance = options.arc_tolerance * unit;
        // Under ROTARY_WRAP one of X and Y turns a rotary axis: a G2/G3
        // cannot move it, so wrapped arcs are cut into feed moves, as for
        // posts without arc sections.
        let wrapped = options.rotary_wrap.is_some();
        let plane_written = a.plane == Plane::Xy || options.arcs_in_every_plane;
        if too_big || wrapped || !plane_written || !geometry.radius.is_finite() || geometry.radius <= 0.0 {
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
        eng.machine.pos_known = true;
        self.print_feed_section(eng, family, Some(section), feed)?;
        self.after_move(eng, false)
    }

    /// The section an arc prints through, or `None` to linearize it.
    fn arc_section(&self, eng: &Engine, g: &ArcGeometry, a: &ArcMove) -> Option<(Family, Section)> {
        let feed = Self::feed_for(eng, a.intent, a.feed);
        let first = |fam: Family| self.family != fam || self.last_feed != Some(feed);
        let cw = a.dir == ArcDir::Cw;
        let flat = if cw {
            (Section::FirstCwArcMove, Section::CwArcMove)
        } else {
            (Section::FirstCcwArcMove, Section::CcwArcMove)
        };
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
                    q[axis] = eng.writers[f.index()].printed_value(p[axis]);
                }
            }
            q
        };
        g.exact(printed(g.start), printed(g.end), dir)
    }

    fn linearize(
        &mut self,
        eng: &mut Engine,
        g: &ArcGeometry,
        intent: Intent,
        feed: Option<f64>,
        tol: f64,
    ) -> Result<()> {
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
}
