//! LN010: arc words (I J K, absolute centres, R) print so few decimals
//! that the radius at the start and at the end of an arc can differ by
//! more than a controller accepts: grbl refuses more than 0.005 mm
//! (`gcode.c`), LinuxCNC more than 0.0283 mm (`interp_internal.hh`); the
//! limits and their sources are in docs/verify.md. Rounding a centre word
//! to a step `s` moves the centre by up to `s/2` in each of two axes, so
//! the radius by up to `s/√2`.

use postc_ir::codes;
use postc_ir::{Diagnostic, Piece, Quantity, Stmt, Units};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN010.code, name: "arc-words-too-coarse", check };

const ARC_WORDS: &[Quantity] =
    &[Quantity::I, Quantity::J, Quantity::K, Quantity::IA, Quantity::JA, Quantity::KA, Quantity::Radius];
const GRBL_MM: f64 = 0.005;
const LINUXCNC_MM: f64 = 0.0283;

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    // Controllers' radius checks are G-code's; HPGL and others have none.
    if !cx.writes_gcode() {
        return;
    }
    let mm_per_unit = match cx.post.output_units() {
        Some(Units::Mm) => 1.0,
        Some(Units::Inch) => 25.4,
        None => return,
    };
    let mut seen = std::collections::BTreeSet::new();
    for h in &cx.post.handlers {
        for stmt in &h.body {
            let Stmt::Line { pieces, span } = stmt else { continue };
            for piece in pieces {
                let Piece::Var(v) = piece else { continue };
                let Some(q) = cx.quantity(piece).filter(|q| ARC_WORDS.contains(q)) else { continue };
                if !seen.insert(v.index()) {
                    continue;
                }
                let var = cx.post.variable(*v);
                let format = cx.post.format(var.format);
                let m = format.multiplier.abs();
                if m == 0.0 {
                    continue;
                }
                let step_mm = 10f64.powi(-i32::from(format.decimals)) / m * mm_per_unit;
                let error = step_mm / std::f64::consts::SQRT_2;
                if error <= GRBL_MM {
                    continue;
                }
                let who = if error > LINUXCNC_MM { "grbl and LinuxCNC refuse" } else { "grbl refuses" };
                let mut d = Diagnostic::warning(
                    RULE.code,
                    format!(
                        "[{}] prints {} decimals: rounding alone can make an arc's radius differ by {error:.4} mm at its ends, and {who} that",
                        q.label(),
                        format.decimals
                    ),
                )
                .help("print arc words with more decimals (3 in mm, 4 in inches), or post with --exact-arcs");
                if let Some(at) = var.span.or(*span) {
                    d = d.at(at, "this arc word");
                }
                out.push(d);
            }
        }
    }
}
