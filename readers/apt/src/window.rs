//! The window: events held back since the last flush, so that the stream
//! comes out in the order the event contract asks for even though CL files
//! describe things in another order.
//!
//! - The `Job` comes first, and its units come from a `UNITS` record or the
//!   first feed unit, which may follow the first (rapid) moves: until the
//!   units are known (or [`LIMIT`] events are held, or the file ends) every
//!   event is held.
//! - A `Tool` comes before the `ToolpathStart` of the toolpath that uses it,
//!   although NX writes `LOAD/TOOL` after `TOOL PATH`; its diameter comes
//!   from `CUTTER`/`TLDATA` records before or after the load, its speed from
//!   the first `SPINDL` of the window.
//! - A file with moves outside any `TOOL PATH` (SolidWorks, Creo, NCL) gets
//!   a synthesized `ToolpathStart` right after the tool change (or after the
//!   last `ToolpathEnd`) before those moves.
//!
//! After the header, a window holds only the few records between two moves,
//! and moves go straight out when it is empty.

use std::collections::VecDeque;

use postc_ir::diagnostic::Span;
use postc_ir::event::Event;

/// The most events held before a flush is forced.
pub(crate) const LIMIT: usize = 4096;

/// Events held back, with the positions that matter for reordering.
#[derive(Default)]
pub(crate) struct Window {
    pub events: Vec<(Event, Span)>,
    /// Index of a move before which a synthesized `ToolpathStart` goes.
    pub synth_before: Option<usize>,
    /// Held events that only record what the file said (`FeedRate`); they
    /// do not count toward [`LIMIT`].
    pub notes: usize,
}

fn is_motion(event: &Event) -> bool {
    matches!(event, Event::Rapid(_) | Event::Feed(_) | Event::Arc(_) | Event::DrillCycle(_) | Event::DrillPoint(_))
}

impl Window {
    pub fn is_empty(&self) -> bool {
        self.events.is_empty()
    }

    pub fn len(&self) -> usize {
        self.events.len()
    }

    pub fn push(&mut self, event: Event, span: Span) {
        self.events.push((event, span));
    }

    /// Inserts before index `at`, keeping the recorded positions right.
    pub fn insert(&mut self, at: usize, event: Event, span: Span) {
        let at = at.min(self.events.len());
        if let Some(s) = self.synth_before.as_mut().filter(|s| **s >= at) {
            *s += 1;
        }
        self.events.insert(at, (event, span));
    }

    /// Where a tool loaded at index `at` goes: before the `ToolpathStart`
    /// that opens the toolpath it was loaded in, when that start is in the
    /// window with no move between them.
    pub fn tool_position(&self, at: usize) -> usize {
        let at = at.min(self.events.len());
        for j in (0..at).rev() {
            match &self.events[j].0 {
                Event::ToolpathStart(_) => return j,
                e if is_motion(e) || matches!(e, Event::ToolpathEnd | Event::Tool(_)) => break,
                _ => {}
            }
        }
        at
    }

    /// Inserts the pending synthesized `ToolpathStart`: right after the last
    /// `Tool` before the move, else right after the last `ToolpathEnd`, else
    /// at the start of the window.
    pub fn place_synth(&mut self, start: Event, span: Span) {
        let Some(before) = self.synth_before.take() else { return };
        let before = before.min(self.events.len());
        let mut at = 0;
        for (j, (e, _)) in self.events[..before].iter().enumerate() {
            match e {
                Event::ToolpathEnd | Event::Tool(_) => at = j + 1,
                e if is_motion(e) => at = j + 1,
                _ => {}
            }
        }
        self.insert(at, start, span);
    }

    /// Moves every held event to `out`.
    pub fn drain_into(&mut self, out: &mut VecDeque<(Event, Span)>) {
        out.extend(self.events.drain(..));
        self.synth_before = None;
        self.notes = 0;
    }
}
