//! LN001: the post cuts but no section prints a feed rate, so the machine
//! cuts at whatever feed was set before the program ran.

use postc_ir::codes;
use postc_ir::{Diagnostic, Quantity, Section};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN001.code, name: "feed-never-printed", check };

const FEEDS: &[Quantity] = &[Quantity::Feed, Quantity::CutFeed, Quantity::PlungeFeed, Quantity::InverseTimeFeed];

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    // G-code posts only: other families (HPGL, ShopBot) set speeds by
    // commands of their own.
    if !cx.straight_lines() || !cx.writes_gcode() {
        return;
    }
    let feed_sections = [Section::FeedMove, Section::FirstFeedMove, Section::PlungeMove, Section::FirstPlungeMove];
    let Some(&first) = feed_sections.iter().find(|s| cx.has(**s)) else { return };
    if cx.sections().any(|s| cx.prints(s, FEEDS)) {
        return;
    }
    let mut d = Diagnostic::warning(
        RULE.code,
        "no section prints a feed rate: the machine cuts at whatever feed was set before",
    )
    .help("print [F] in FEED_RATE_CHANGE or in the first feed move section (FIRST_FEED_MOVE)");
    if let Some(span) = cx.section_span(first) {
        d = d.at(span, "feed moves print here, without [F]");
    }
    out.push(d);
}
