//! The job's outline ([`postc_ir::outline::JobOutline`]) as the text a
//! post that reads ahead receives (`JOB_OUTLINE`): a JSON array with one
//! object per section, lengths in the post's units.
//!
//! `[{"tool": 1, "diameter": 6, "name": "6 mm end mill", "notes": "",
//! "lengthOffset": 1, "speed": 18000, "jet": false, "turning": false,
//! "coolant": 1,
//! "toolpath": "Pocket", "toolpathNotes": "", "x": 10, "y": 10, "z": 5, "zMin": -3, "zMax": 5,
//! "cycle": -1, "dwell": false, "cycles": 0, "points": 0}, ...]`: `cycle`
//! is the `DRILL_KIND` number of the cycle that starts the section, -1
//! when none; `coolant` the `COOLANT_KIND` number; a length that is not a
//! finite number is `null`.

use postc_ir::outline::JobOutline;
use serde_json::json;

use crate::machine::{coolant_kind, drill_kind};

/// The outline as JSON, lengths multiplied by `factor` (toolpath units to
/// the post's).
pub fn to_json(outline: &JobOutline, factor: f64) -> String {
    let sections: Vec<serde_json::Value> = outline
        .sections
        .iter()
        .map(|s| {
            let t = &s.tool;
            json!({
                "tool": t.number,
                "diameter": t.diameter * factor,
                "name": t.name,
                "notes": t.notes,
                "lengthOffset": t.length_offset.unwrap_or(t.number),
                "speed": t.spindle_speed,
                "jet": t.jet,
                "turning": t.turning,
                "coolant": coolant_kind(s.coolant),
                "toolpath": s.toolpath,
                "toolpathNotes": s.toolpath_notes,
                "x": s.first[0] * factor,
                "y": s.first[1] * factor,
                "z": s.first[2] * factor,
                "zMin": s.z_min * factor,
                "zMax": s.z_max * factor,
                "cycle": s.starts_with_cycle.map_or(-1.0, |c| drill_kind(c.0)),
                "dwell": s.starts_with_cycle.is_some_and(|c| c.1),
                "cycles": s.cycles,
                "points": s.cycle_points,
            })
        })
        .collect();
    serde_json::Value::Array(sections).to_string()
}
