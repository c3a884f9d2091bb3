//! LN017: the post states its units and writes the other system's units
//! word: `UNITS = "INCHES"` and a header that says `G21`. Every length the
//! controller reads is then 25.4 times off. A post that states no units
//! writes the system of the one units word it holds (docs/units.md), so
//! only a post that states them can contradict itself.

use postc_ir::codes;
use postc_ir::units::WrittenUnits;
use postc_ir::{Diagnostic, Piece, Stmt, Units};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN017.code, name: "units-word-contradicts-units", check };

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    let post = cx.post;
    let Some(stated) = post.info.units else { return };
    let words = post.written_units();
    let Some(written) = words.only().filter(|w| *w != stated) else { return };
    let word = words.word(written);
    let (said, wrote) = match stated {
        Units::Inch => ("inches", "millimetres"),
        Units::Mm => ("millimetres", "inches"),
    };
    let mut d = Diagnostic::warning(
        RULE.code,
        format!("the post writes {said}, but its text says {word} ({wrote}): the controller would read every length 25.4 times off"),
    )
    .help("make the units statement and the units word agree");
    // The first output line that writes the word, else the post's name.
    let line = post.handlers.iter().flat_map(|h| &h.body).find_map(|s| match s {
        Stmt::Line { pieces, span: Some(span) } => pieces
            .iter()
            .any(|p| {
                let Piece::Text(t) = p else { return false };
                let mut w = WrittenUnits::default();
                w.scan(t);
                w.only() == Some(written)
            })
            .then_some(*span),
        _ => None,
    });
    if let Some(span) = line.or(post.info.span) {
        d = d.at(span, format!("{word} here"));
    }
    out.push(d);
}
