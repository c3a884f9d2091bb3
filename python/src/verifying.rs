//! `postc.post` verifying the program it posted, as `postc post` does by
//! default (docs/verify.md, "While posting"): the records verify reads of
//! the toolpath's events (`postc_verify::expect::Record`) are kept as the
//! post reads the events, and once the program is posted (to memory, which
//! `postc.post` holds whole anyway) `postc_verify::verify_records` replays
//! it against them with the post's settings, the generic controller and
//! 0.01 mm, the command's defaults. What it cannot read is said as VF044,
//! as the command says it; the refusals are `postc_verify::refusal`'s.

use postc_ir::{Diagnostic, Event, EventSource, Post, SourceMap, Span};
use postc_verify::expect::{Record, RecordSource};
use postc_verify::{Controller, Settings};

/// An event source that keeps the record of each event the post reads.
pub struct Recording<'a> {
    pub inner: &'a mut dyn EventSource,
    pub records: Vec<(Record, Span)>,
}

impl EventSource for Recording<'_> {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        let next = self.inner.next_event(diagnostics);
        if let Some((event, span)) = &next
            && let Some(record) = Record::of(event)
        {
            self.records.push((record, *span));
        }
        next
    }

    fn outline(&mut self) -> Option<postc_ir::outline::JobOutline> {
        self.inner.outline()
    }
}

/// The kept records, given to verify a batch at a time.
struct Kept(std::vec::IntoIter<(Record, Span)>);

impl RecordSource for Kept {
    fn next_batch(&mut self, batch: &mut Vec<(Record, Span)>, _: &mut Vec<Diagnostic>) -> bool {
        batch.clear();
        batch.extend(self.0.by_ref().take(1024));
        !batch.is_empty()
    }
}

/// What verifying a posted program found.
pub enum Verdict {
    /// Verify does not read this program: why, as a VF044 note.
    Unverified(Diagnostic),
    /// The findings (errors refuse the program).
    Findings(Vec<Diagnostic>),
}

/// Verifies `program` (named `name`, extension `ext`) against the records
/// of the events `post` read.
pub fn verify(
    post: &Post,
    program: &[u8],
    name: &str,
    ext: &str,
    records: Vec<(Record, Span)>,
    sources: &mut SourceMap,
) -> Verdict {
    let unverified = |why: String| Verdict::Unverified(postc_verify::unverified(name, &why));
    if let Some(refused) = postc_verify::refusal(name, Some(post), ext, &program[..program.len().min(4096)]) {
        return unverified(refused.message);
    }
    let file = sources.add(name.to_string(), String::from_utf8_lossy(program).into_owned());
    let settings = Settings::from_post(post, Controller::Generic, 0.01);
    let report = postc_verify::verify_records(&mut &program[..], file, &mut Kept(records.into_iter()), &settings);
    if let Some(why) = postc_verify::not_gcode(&report) {
        return unverified(why);
    }
    Verdict::Findings(report.findings)
}
