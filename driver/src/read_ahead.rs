//! Reading a toolpath on a thread of its own while the post runs.
//!
//! Reading a toolpath (parsing each line's numbers) costs about as much as
//! a simple post spends on a move. [`ReadAhead`] moves it to a second
//! thread: the reader fills batches of events and hands them over a
//! bounded channel, so on a machine with two cores the whole job takes
//! about as long as the posting alone.
//!
//! What a consumer sees does not change: the same events, each with its
//! span, and each diagnostic of the reader delivered by the same
//! `next_event` call that would have delivered it reading in line (a batch
//! keeps diagnostics and events in the order the reader produced them).
//! Memory stays bounded (at most [`IN_FLIGHT`] batches in flight), emptied batches go back
//! to the reader so a move allocates nothing, a consumer that stops early
//! stops the reader (its next hand-over fails), and a reader that panics
//! panics the consumer at the point the stream would have ended, never a
//! stream that silently ends early. When no thread can be started, the
//! source is read in line.

use std::sync::mpsc::{Receiver, SyncSender, TryRecvError, sync_channel};
use std::thread::JoinHandle;

use postc_ir::{Diagnostic, Event, EventSource, Span};

/// Events handed over at a time.
#[doc(hidden)]
pub const BATCH: usize = 1024;
/// Batches read ahead of the consumer at most (65,536 events).
///
/// The reader is the slowest thread of a simple post's job, so the job
/// takes as long as it does. While `postc post` also verifies, three
/// threads share two cores and the scheduler takes the reader's core for
/// the posting or verify thread at times: a deep queue lets the reader
/// run on when it gets a core back instead of stopping as soon as the
/// post falls a few batches behind (docs/performance.md, "Verifying
/// while posting", measures the depths).
const IN_FLIGHT: usize = 64;

/// One thing the reader produced, in its order.
enum Item {
    Event(Event, Span),
    Diagnostic(Diagnostic),
}

/// A toolpath source read on its own thread (see the module's doc).
pub struct ReadAhead {
    /// Filled batches, each in reverse order (the next item is the last).
    filled: Option<Receiver<Vec<Item>>>,
    /// Emptied batches going back to the reader.
    emptied: SyncSender<Vec<Item>>,
    current: Vec<Item>,
    reader: Option<JoinHandle<()>>,
    ended: bool,
}

impl ReadAhead {
    /// `source` read on its own thread, or in line when no thread starts.
    pub fn start<S: EventSource + Send + 'static>(source: S) -> Box<dyn EventSource> {
        let (filled_tx, filled) = sync_channel::<Vec<Item>>(IN_FLIGHT);
        let (emptied, emptied_rx) = sync_channel::<Vec<Item>>(IN_FLIGHT + 2);
        // The source goes to the thread once it runs, so that it is still
        // here when the thread cannot be started.
        let (give, take) = sync_channel::<S>(1);
        let spawned = std::thread::Builder::new().name("postc-read".into()).spawn(move || {
            if let Ok(source) = take.recv() {
                read(source, &filled_tx, &emptied_rx);
            }
        });
        match spawned {
            Ok(reader) => match give.send(source) {
                Ok(()) => Box::new(ReadAhead {
                    filled: Some(filled),
                    emptied,
                    current: Vec::new(),
                    reader: Some(reader),
                    ended: false,
                }),
                // The thread is gone before it took the source: read in line.
                Err(returned) => Box::new(returned.0),
            },
            Err(_) => Box::new(source),
        }
    }

    /// The reader has stopped: wait for its thread, and panic as it did.
    fn finish(&mut self) {
        self.filled = None;
        if let Some(reader) = self.reader.take()
            && let Err(panic) = reader.join()
        {
            std::panic::resume_unwind(panic);
        }
    }
}

/// The reader's thread: batches of events until the source ends or the
/// consumer is gone.
fn read<S: EventSource>(mut source: S, filled: &SyncSender<Vec<Item>>, emptied: &Receiver<Vec<Item>>) {
    let mut diagnostics = Vec::new();
    loop {
        let mut batch = match emptied.try_recv() {
            Ok(b) => b,
            Err(TryRecvError::Empty | TryRecvError::Disconnected) => Vec::with_capacity(BATCH),
        };
        let mut ended = false;
        while batch.len() < BATCH {
            let next = source.next_event(&mut diagnostics);
            batch.extend(diagnostics.drain(..).map(Item::Diagnostic));
            match next {
                Some((event, span)) => batch.push(Item::Event(event, span)),
                None => {
                    ended = true;
                    break;
                }
            }
        }
        batch.reverse();
        if filled.send(batch).is_err() || ended {
            return;
        }
    }
}

impl EventSource for ReadAhead {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        loop {
            while let Some(item) = self.current.pop() {
                match item {
                    Item::Event(event, span) => return Some((event, span)),
                    Item::Diagnostic(d) => diagnostics.push(d),
                }
            }
            if self.ended {
                return None;
            }
            let next = self.filled.as_ref().map(Receiver::recv);
            match next {
                Some(Ok(batch)) => {
                    let emptied = std::mem::replace(&mut self.current, batch);
                    // A full return channel only costs the reader an allocation.
                    let _ = self.emptied.try_send(emptied);
                }
                _ => {
                    self.ended = true;
                    self.finish();
                }
            }
        }
    }
}

impl Drop for ReadAhead {
    fn drop(&mut self) {
        // Dropping the receiver first makes the reader's next hand-over
        // fail, so it stops rather than reading the rest of the file.
        self.filled = None;
        if let Some(reader) = self.reader.take() {
            let _ = reader.join();
        }
    }
}
