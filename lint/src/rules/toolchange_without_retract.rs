//! LN004: the tool change section changes the tool (M6) before anything
//! moves Z up or home: on a machine that does not retract by itself, the
//! tool is pulled sideways out of the work.

use postc_ir::codes;
use postc_ir::{Diagnostic, Quantity, Section};

use super::spindle_never_printed::has_word;
use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN004.code, name: "toolchange-without-retract", check };

/// Words that send the machine up or home before a tool change.
const RETRACTS: &[&str] = &["G28", "G30", "G53", "Z"];

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if !cx.straight_lines() {
        return;
    }
    for (pieces, span) in cx.lines(Section::ToolChange) {
        let text = crate::literal_text(pieces).to_ascii_uppercase();
        let moves_z = pieces
            .iter()
            .any(|p| cx.quantity(p).is_some_and(|q| matches!(q, Quantity::Z | Quantity::SafeZ | Quantity::HomeZ)))
            || RETRACTS.iter().any(|w| text.contains(w));
        if moves_z {
            return;
        }
        if has_word(&text, "M6") || has_word(&text, "M06") {
            let mut d = Diagnostic::warning(RULE.code, "the tool changes (M6) before any line raises Z")
                .help("retract first, e.g. a line \"G0 Z[SAFEZ]\" or \"G53 G0 Z0\" before the M6, unless the controller's tool change macro retracts");
            if let Some(span) = span {
                d = d.at(span, "the tool change");
            }
            out.push(d);
            return;
        }
    }
}
