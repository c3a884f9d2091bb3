//! Drilling cycles under the section rules: through DRILL_POINT when the
//! post has it, otherwise as moves (rapid to the clearance and reference
//! planes, plunge or pecks, dwell, retract), since Vectric posts have no
//! cycle sections.

use postc_ir::event::{DrillKind, DrillPoint, Intent};
use postc_ir::{Diagnostic, Section};

use super::{MAX_PECKS, Result, SectionDispatch};
use crate::engine::Engine;

impl SectionDispatch {
    /// One hole: through DRILL_POINT, or as moves when the post has no drilling sections.
    pub(super) fn drill_point(&mut self, eng: &mut Engine, p: DrillPoint) -> Result<()> {
        let at = [p.x, p.y, p.z];
        if eng.has(Section::DrillPoint) {
            eng.machine.pos = at;
            eng.machine.pos_known = true;
            eng.run_section(Section::DrillPoint)?;
            return Ok(());
        }
        let Some(cycle) = eng.machine.drill.clone() else {
            return Err(Box::new(
                Diagnostic::error("RT013", "a DrillPoint came outside a drilling cycle")
                    .at(eng.event_span, "this hole"),
            ));
        };
        let (clear, reference, depth) = (cycle.retract_plane, cycle.reference_plane, cycle.depth);
        let feed = cycle.feed;
        let pos = eng.machine.pos;
        if pos[2] < clear {
            self.rapid_to(eng, [pos[0], pos[1], clear])?;
        }
        self.rapid_to(eng, [at[0], at[1], clear])?;
        if reference < clear {
            self.rapid_to(eng, [at[0], at[1], reference])?;
        }
        let mut peck = cycle.peck.filter(|p| *p > 0.0 && matches!(cycle.kind, DrillKind::Deep | DrillKind::ChipBreak));
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
}
