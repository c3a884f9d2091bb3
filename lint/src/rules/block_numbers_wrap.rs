//! LN012: the post prints block numbers (`[N]`) and `LINE_NUMBER_MAXIMUM`
//! is reached after fewer blocks than a long program has: numbering then
//! starts again, so block numbers repeat, which controllers that search
//! for a block number (`GOTO`, restart at a block) get wrong, and postc
//! verify reports (VF040).

use postc_ir::codes;
use postc_ir::{Diagnostic, Quantity};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN012.code, name: "block-numbers-wrap", check };

/// Blocks a long program has: a 3D finish of a few hours.
const LONG_PROGRAM: f64 = 100_000.0;

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if !cx.sections().any(|s| cx.prints(s, &[Quantity::BlockNumber])) {
        return;
    }
    let b = cx.post.options.block_numbers;
    if b.increment.is_nan() || b.increment <= 0.0 {
        return;
    }
    let blocks = ((b.maximum - b.start) / b.increment).floor() + 1.0;
    if blocks >= LONG_PROGRAM || cx.post.options.tape_splitting.as_ref().is_some_and(|t| (t.max_lines as f64) < blocks)
    {
        return;
    }
    let mut d = Diagnostic::warning(
        RULE.code,
        format!(
            "block numbers run from {} to {} in steps of {}: after {blocks} blocks they start again and repeat",
            b.start, b.maximum, b.increment
        ),
    )
    .help("raise LINE_NUMBER_MAXIMUM (99999 or more), or drop [N] if the controller does not need block numbers");
    // The sections that print `[N]`, else the post as a whole.
    let span = cx
        .post
        .handlers
        .iter()
        .filter(|h| matches!(h.key, postc_ir::HandlerKey::Section(s) if cx.prints(s, &[Quantity::BlockNumber])))
        .find_map(|h| h.span)
        .or(cx.post.info.span);
    if let Some(span) = span {
        d = d.at(span, "block numbers printed here");
    }
    out.push(d);
}
