//! LN011: the post splits long programs into files (`TAPE_SPLITTING`) and
//! only its tool change starts the spindle. Every part starts with the
//! header (followed by `SPINDLE_ON` when the post has one, as the first
//! part does); the tool change is not repeated at a split, so a part run
//! on its own cuts with the spindle stopped.

use postc_ir::codes;
use postc_ir::{Diagnostic, Quantity, Section};

use super::spindle_never_printed::has_word;
use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN011.code, name: "tape-split-spindle", check };

fn starts_spindle(cx: &Context, s: Section) -> bool {
    cx.lines(s).any(|(p, _)| {
        let t = crate::literal_text(p).to_ascii_uppercase();
        ["M3", "M03", "M4", "M04"].iter().any(|m| has_word(&t, m))
    })
}

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if cx.post.options.tape_splitting.is_none() || !cx.straight_lines() {
        return;
    }
    let only_toolchange = starts_spindle(cx, Section::ToolChange) && !cx.has(Section::SpindleOn);
    if !only_toolchange || starts_spindle(cx, Section::Header) || cx.prints(Section::Header, &[Quantity::SpindleSpeed])
    {
        return;
    }
    let mut d = Diagnostic::warning(
        RULE.code,
        "the post splits programs into parts, but only the tool change starts the spindle: a part begins with the header, which does not",
    )
    .help("start the spindle in a SPINDLE_ON section (it follows the header of every part) or in the HEADER");
    if let Some(span) = cx.section_span(Section::Header) {
        d = d.at(span, "each part starts here");
    }
    out.push(d);
}
