use postc_driver::ReadAhead;
use postc_driver::testing::read_ahead::BATCH;
use postc_ir::FileId;
use postc_ir::event::{Move, VecSource};
use postc_ir::{Diagnostic, Event, EventSource, Span};

/// A source that reports a diagnostic before every third event.
struct Noisy {
    inner: VecSource,
    n: usize,
}

impl EventSource for Noisy {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        self.n += 1;
        if self.n.is_multiple_of(3) {
            diagnostics.push(Diagnostic::error(postc_ir::codes::TP002, format!("before event {}", self.n)));
        }
        self.inner.next_event(diagnostics)
    }
}

fn events(n: usize) -> Vec<Event> {
    (0..n).map(|i| Event::Rapid(Move { x: i as f64, ..Default::default() })).collect()
}

/// Each event with the diagnostics delivered by the call that gave it.
fn drain(source: &mut dyn EventSource) -> Vec<(Option<Event>, Vec<String>)> {
    let mut all = Vec::new();
    loop {
        let mut diagnostics = Vec::new();
        let next = source.next_event(&mut diagnostics);
        let done = next.is_none();
        all.push((next.map(|(e, _)| e), diagnostics.into_iter().map(|d| d.message).collect()));
        if done {
            return all;
        }
    }
}

#[test]
fn read_ahead_gives_what_reading_in_line_gives() {
    for n in [0, 1, BATCH - 1, BATCH, BATCH + 1, 5 * BATCH + 7] {
        let in_line = drain(&mut Noisy { inner: VecSource::new(events(n), FileId(0)), n: 0 });
        let mut ahead = ReadAhead::start(Noisy { inner: VecSource::new(events(n), FileId(0)), n: 0 });
        assert_eq!(drain(&mut *ahead), in_line, "{n} events");
        // After the end, the end again.
        assert!(ahead.next_event(&mut Vec::new()).is_none());
    }
}

#[test]
fn a_consumer_that_stops_early_stops_the_reader() {
    let mut ahead = ReadAhead::start(VecSource::new(events(50 * BATCH), FileId(0)));
    assert!(ahead.next_event(&mut Vec::new()).is_some());
    drop(ahead); // joins the reader: it must not wait forever
}

struct Panics;

impl EventSource for Panics {
    fn next_event(&mut self, _: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        panic!("the reader failed");
    }
}

#[test]
fn a_reader_that_panics_is_not_an_early_end() {
    let mut ahead = ReadAhead::start(Panics);
    let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| ahead.next_event(&mut Vec::new())));
    assert!(caught.is_err(), "the stream must not just end");
}
