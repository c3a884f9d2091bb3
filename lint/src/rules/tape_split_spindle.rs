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

#[cfg(test)]
mod tests {
    use crate::tests::lint_vectric;

    const SPLIT: &str = "TAPE_SPLITTING = 1000 100 \"%s_%d.tap\" 1 \"NO\"\n";

    #[test]
    fn fires_when_only_the_tool_change_starts_it() {
        let found = lint_vectric(&format!("{SPLIT}begin HEADER\n\"G21\"\nbegin TOOLCHANGE\n\"T[T] M6\"\n\"[S] M3\"\n"));
        assert!(found.iter().any(|d| d.code == "LN011"), "{found:?}");
    }

    #[test]
    fn quiet_with_spindle_on_or_without_splitting() {
        let found = lint_vectric(&format!("{SPLIT}begin HEADER\n\"G21\"\nbegin SPINDLE_ON\n\"[S] M3\"\n"));
        assert!(!found.iter().any(|d| d.code == "LN011"), "{found:?}");
        let found = lint_vectric("begin HEADER\n\"G21\"\nbegin TOOLCHANGE\n\"T[T] M6\"\n\"[S] M3\"\n");
        assert!(!found.iter().any(|d| d.code == "LN011"), "{found:?}");
    }
}
