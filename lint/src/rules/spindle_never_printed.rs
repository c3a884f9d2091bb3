//! LN002: the post changes tools but never prints a spindle speed, so
//! every tool runs at the speed the spindle was left at. Posts for
//! machines whose spindle speed is set by hand (a trim router) do this on
//! purpose; the warning says so.

use postc_ir::codes;
use postc_ir::{Diagnostic, Quantity, Section};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN002.code, name: "spindle-speed-never-printed", check };

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if !cx.straight_lines() || cx.post.info.laser_support {
        return;
    }
    // Only a post that controls the spindle (a SPINDLE_ON section, or M3/M4
    // in the header or tool change) is expected to say how fast.
    let starts = cx.has(Section::SpindleOn)
        || [Section::Header, Section::ToolChange].iter().any(|s| {
            cx.lines(*s).any(|(p, _)| {
                let t = crate::literal_text(p).to_ascii_uppercase();
                ["M3", "M03", "M4", "M04"].iter().any(|m| has_word(&t, m))
            })
        });
    if !starts || cx.sections().any(|s| cx.prints(s, &[Quantity::SpindleSpeed])) {
        return;
    }
    let at = [Section::SpindleOn, Section::ToolChange, Section::Header].into_iter().find_map(|s| cx.section_span(s));
    let mut d = Diagnostic::warning(
        RULE.code,
        "the post starts the spindle but never prints a spindle speed: every tool runs at the speed the spindle was left at",
    )
    .help("print [S] where the spindle starts (SPINDLE_ON or TOOLCHANGE); ignore this for a spindle whose speed is set by hand");
    if let Some(span) = at {
        d = d.at(span, "the spindle starts here, without [S]");
    }
    out.push(d);
}

/// Whether `word` stands alone in `text` (not followed by a digit).
pub(crate) fn has_word(text: &str, word: &str) -> bool {
    text.match_indices(word).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + word.len()..].chars().next();
        !before.is_some_and(|c| c.is_ascii_alphanumeric()) && !after.is_some_and(|c| c.is_ascii_digit())
    })
}
