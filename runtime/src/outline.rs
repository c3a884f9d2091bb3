//! The job's outline ([`postc_ir::outline::JobOutline`]) as the text a
//! post that reads ahead receives (`JOB_OUTLINE`): a JSON array with one
//! object per section, lengths in the post's units.
//!
//! `[{"tool": 1, "diameter": 6, "name": "6 mm end mill", "notes": "",
//! "lengthOffset": 1, "speed": 18000, "jet": false, "coolant": 1,
//! "toolpath": "Pocket", "x": 10, "y": 10, "z": 5, "zMin": -3, "zMax": 5,
//! "cycle": -1, "dwell": false, "cycles": 0, "points": 0}, ...]`: `cycle`
//! is the `DRILL_KIND` number of the cycle that starts the section, -1
//! when none; `coolant` the `COOLANT_KIND` number.

use std::fmt::Write;

use postc_ir::outline::JobOutline;

use crate::machine::{coolant_kind, drill_kind};

/// The outline as JSON, lengths multiplied by `factor` (toolpath units to
/// the post's).
pub fn to_json(outline: &JobOutline, factor: f64) -> String {
    let mut out = String::from("[");
    for (i, s) in outline.sections.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        let t = &s.tool;
        let coolant = coolant_kind(s.coolant);
        let cycle = s.starts_with_cycle.map_or(-1.0, |c| drill_kind(c.0));
        let _ = write!(
            out,
            "{{\"tool\":{},\"diameter\":{},\"name\":{},\"notes\":{},\"lengthOffset\":{},\"speed\":{},\"jet\":{},\
             \"coolant\":{},\"toolpath\":{},\"x\":{},\"y\":{},\"z\":{},\"zMin\":{},\"zMax\":{},\"cycle\":{},\
             \"dwell\":{},\"cycles\":{},\"points\":{}}}",
            t.number,
            number(t.diameter * factor),
            text(&t.name),
            text(&t.notes),
            t.length_offset.unwrap_or(t.number),
            number(t.spindle_speed),
            t.jet,
            coolant,
            text(&s.toolpath),
            number(s.first[0] * factor),
            number(s.first[1] * factor),
            number(s.first[2] * factor),
            number(s.z_min * factor),
            number(s.z_max * factor),
            cycle,
            s.starts_with_cycle.is_some_and(|c| c.1),
            s.cycles,
            s.cycle_points,
        );
    }
    out.push(']');
    out
}

/// A number as JSON writes it (JavaScript's shortest form; no NaN).
fn number(v: f64) -> String {
    if v.is_finite() { crate::js::number_to_string(v) } else { "null".into() }
}

/// A text as a JSON string.
fn text(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
