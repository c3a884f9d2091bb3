//! Tape splitting under the section rules: a part ends with the footer
//! at a retract that reaches safe Z once it has `max - tolerance` blocks (or
//! at any move once it has `max`), and the next part starts like a program
//! at its first block.

use postc_ir::{Diagnostic, Section};

use super::{Result, SectionDispatch};
use crate::engine::Engine;

impl SectionDispatch {
    /// Ends the current tape-split part with the footer when a split is
    /// due; the next part starts (with the header) at its first block.
    #[inline]
    pub(super) fn split_if_pending(&mut self, eng: &mut Engine) -> Result<()> {
        if !self.split_pending {
            return Ok(());
        }
        self.split_now(eng)
    }

    /// [`Self::split_if_pending`] when a split is due (rare: kept out of
    /// the per-move path).
    #[cold]
    fn split_now(&mut self, eng: &mut Engine) -> Result<()> {
        self.split_pending = false;
        eng.run_section(Section::Footer)?;
        eng.out.new_part();
        eng.trace_new_part();
        self.started = false;
        Ok(())
    }

    /// Tape splitting after a move.
    pub(super) fn after_move(&mut self, eng: &mut Engine, retract: bool) -> Result<()> {
        let Some(tape) = &eng.post.options.tape_splitting else { return Ok(()) };
        let blocks = eng.out.blocks_in_part();
        // A retract that stops below safe Z (a peck back to the R plane, a
        // feed retract before the rapid up) is no place to end a part: the
        // next part would start from the header's position with a move
        // down into the cut.
        let clear = eng.machine.job.safe_z.is_none_or(|z| eng.machine.pos[2] >= z - 1e-9 * z.abs().max(1.0));
        let soft = retract && clear && blocks + tape.tolerance >= tape.max_lines;
        let hard = blocks >= tape.max_lines;
        if !(soft || hard) {
            return Ok(());
        }
        if self.split_pending {
            return Ok(());
        }
        if hard && !soft {
            eng.warn_once(
                Diagnostic::warning(
                    "RT014",
                    format!(
                        "a part reached {} lines with no retract in its last {}; it was split inside a cut",
                        tape.max_lines, tape.tolerance
                    ),
                )
                .help("raise the TAPE_SPLITTING tolerance so that a retract falls inside it"),
            );
        }
        self.split_pending = true;
        Ok(())
    }
}
