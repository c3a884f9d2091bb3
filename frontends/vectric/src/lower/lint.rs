//! Lints over the compiled post.
//!
//! The project's dialect decisions (docs/vectric.md): arc words ([I] [J] [IA] [JA] [Radius]) come from the
//! unrounded geometry, so a post that prints them more coarsely than its
//! positions makes arcs whose radius at the start and at the end differ by
//! more than a controller with a tight radius check accepts. The lint
//! compares the smallest step each word can print (one unit of its last
//! decimal, divided by its multiplier) with the finest position step.

use std::collections::BTreeSet;

use postc_ir::post::VarId;
use postc_ir::{Diagnostic, Piece, Post, Quantity, Stmt, ValueSource};

use crate::diagnostics::Code;
use crate::lower::emit::Variables;

const ARC_WORDS: &[Quantity] = &[Quantity::I, Quantity::J, Quantity::IA, Quantity::JA, Quantity::Radius];

/// The variables the handlers print.
fn used_variables(post: &Post) -> BTreeSet<VarId> {
    let mut used = BTreeSet::new();
    for handler in &post.handlers {
        for stmt in &handler.body {
            if let Stmt::Line { pieces, .. } = stmt {
                used.extend(pieces.iter().filter_map(|p| match p {
                    Piece::Var(id) => Some(*id),
                    _ => None,
                }));
            }
        }
    }
    used
}

/// The quantity, decimals and printed step of a variable.
fn step(post: &Post, id: VarId) -> Option<(Quantity, u8, f64)> {
    let var = post.variables.get(usize::from(id))?;
    let ValueSource::Quantity(q) = var.source else {
        return None;
    };
    let format = post.formats.get(usize::from(var.format))?;
    let m = format.multiplier.abs();
    (m > 0.0).then(|| (q, format.decimals, 10f64.powi(-i32::from(format.decimals)) / m))
}

/// Warns about arc words printed more coarsely than positions.
pub fn coarse_arc_words(post: &Post, vars: &Variables, diags: &mut Vec<Diagnostic>) {
    let used = used_variables(post);
    let steps: Vec<(VarId, Quantity, u8, f64)> =
        used.iter().filter_map(|&id| step(post, id).map(|(q, d, s)| (id, q, d, s))).collect();
    let finest =
        steps.iter().filter(|(_, q, _, _)| matches!(q, Quantity::X | Quantity::Y)).min_by(|a, b| a.3.total_cmp(&b.3));
    let Some(&(_, _, pos_decimals, pos_step)) = finest else {
        return;
    };
    for &(id, q, decimals, arc_step) in &steps {
        if !ARC_WORDS.contains(&q) || arc_step <= pos_step * (1.0 + 1e-9) {
            continue;
        }
        let Some(at) = vars.declared_at.get(&id).or_else(|| vars.first_use.get(&id)) else {
            continue;
        };
        let declared = vars.declared_at.contains_key(&id);
        diags.push(
            Code::CoarseArcWords
                .diag(format!(
                    "[{}] prints {decimals} decimals but positions print {pos_decimals}: a controller with a tight radius check may reject arcs",
                    q.label()
                ))
                .at(*at, if declared { "arc word declared here" } else { "arc word with the default format (3 decimals)" })
                .note("arc words come from the exact geometry while positions are rounded, so the radius at the start and at the end of an arc may differ")
                .help(
                    "print arc words with at least as many decimals as positions, or post with --exact-arcs to compute them from the printed points",
                ),
        );
    }
}
