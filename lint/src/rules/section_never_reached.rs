//! LN014: a section the runtime never runs for this post. Under
//! `ROTARY_WRAP_X`/`_Y` every arc is cut into feed moves (a G2/G3 cannot
//! turn the rotary axis, docs/vectric.md), so the arc sections are dead;
//! with `MAX_ARC_RADIUS = 0` every arc is larger than the limit, and the
//! same holds. A reader of the post expects arcs from them.

use postc_ir::{Diagnostic, HandlerKey};

use crate::product::is_arc_section;
use postc_ir::codes;

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN014.code, name: "section-never-reached", check };

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    let o = &cx.post.options;
    let why = if o.rotary_wrap.is_some() {
        "the post wraps an axis (ROTARY_WRAP), so every arc is cut into feed moves"
    } else if o.max_arc_radius == Some(0.0) {
        "MAX_ARC_RADIUS is 0, so every arc is cut into feed moves"
    } else {
        return;
    };
    for h in &cx.post.handlers {
        let HandlerKey::Section(s) = h.key else { continue };
        if !is_arc_section(s) {
            continue;
        }
        let mut d = Diagnostic::warning(RULE.code, format!("{} is never run: {why}", s.name()))
            .help("remove the section, or unwrap the axis to print true arcs");
        if let Some(span) = h.span {
            d = d.at(span, "never run");
        }
        out.push(d);
    }
}
