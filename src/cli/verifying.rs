//! `postc post` verifying the program while it writes it (docs/verify.md,
//! "While posting").
//!
//! Two tees on the posting thread feed one verify thread over one bounded
//! channel: [`TeeSink`] hands it each chunk of program bytes the runtime
//! writes (64 KiB at a time), [`TeeSource`] the toolpath events the post
//! reads, as the few fields verify reads of them ([`Record`]), in batches. The verify thread reads the bytes as a
//! `BufRead` and the records as a `RecordSource` and runs
//! [`postc_verify::verify_records`] over them, so the toolpath is read once and the
//! program never goes back to disk.
//!
//! One channel carries both, in the order they were produced (the events
//! read so far go before each chunk of bytes), so the posting thread never
//! waits for a verify thread that waits for it: when verify needs bytes and
//! events come first, or the reverse, it keeps what it received and reads
//! on. What it keeps is bounded by what a post writes between two chunks;
//! memory stays flat whatever the job's length.
//!
//! The program sink's own `finish` is held back ([`Verification::finish`]
//! hands the sink over): the caller names and commits the files, or writes
//! standard output, only once verification has passed. The verify thread
//! keeps none of the program: when verify finds something, the caller reads
//! the lines to show back from the sink ([`Sink::written`]), so a verified
//! run takes no more memory, and no more fresh pages, than one that is not.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::io::{self, BufRead, Read};
use std::rc::Rc;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};
use std::thread::JoinHandle;

use postc_ir::post::TapeSplitting;
use postc_ir::{Diagnostic, Event, EventSource, FileId, Span};
use postc_runtime::output::{Finished, Sink};
use postc_verify::expect::{Record, RecordSource};
use postc_verify::{Report, Settings};

/// Events sent at a time.
const BATCH: usize = 1024;
/// Messages in flight at most.
const IN_FLIGHT: usize = 32;
/// Programs up to this size are read back to show their lines with findings.
pub const HOLD: usize = 16 << 20;
/// Batches of events kept at most while the verify thread waits for
/// program bytes: past them the post has written nothing for this many
/// events, and verification stops ([`Outcome::Stalled`]) rather than keep
/// the toolpath in memory.
const STALL: usize = 64;

enum Message {
    Bytes(Vec<u8>),
    Events(Vec<(Record, Span)>),
}

/// Toolpath records sent at a time.
type Batch = Vec<(Record, Span)>;

/// The two kinds of buffer going back from the verify thread to the
/// posting thread once read: either end of the two channels.
struct Spare<B, E> {
    bytes: B,
    events: E,
}

/// What the verify thread found.
pub enum Outcome {
    /// The program is of a family verify does not read, told by its first
    /// bytes (HPGL, ShopBot, Heidenhain conversational), or binary data:
    /// which.
    Foreign(&'static str),
    /// The post wrote nothing while the toolpath went on for
    /// [`STALL`] batches of events, after this many bytes of program:
    /// verification stopped there.
    Stalled { bytes: u64, events: usize },
    /// The verification's report.
    Verified { report: Report },
}

/// The posting thread's end of the channel, shared by the two tees.
struct Tee {
    tx: Option<SyncSender<Message>>,
    /// Buffers the verify thread has read, coming back to be filled again,
    /// so that a long program does not take fresh memory (and its page
    /// faults) for every chunk and batch.
    spare: Spare<Receiver<Vec<u8>>, Receiver<Batch>>,
    events: Vec<(Record, Span)>,
    /// Set by the verify thread when it reads no further (a foreign program).
    stop: Arc<AtomicBool>,
    /// The inner sink once the run finished.
    parked: Option<Box<dyn Sink>>,
    bytes: u64,
    /// Lines are counted (for a tape-split program whose trace is kept).
    count_lines: bool,
    lines: u64,
    /// The lines of the program before each tape-split part after the first.
    part_lines: Vec<u64>,
}

impl Tee {
    fn send(&mut self, message: Message) {
        if self.stop.load(Ordering::Relaxed) {
            self.tx = None;
        }
        if let Some(tx) = &self.tx
            && tx.send(message).is_err()
        {
            // The verify thread is gone (it panicked): `finish` says so.
            self.tx = None;
        }
    }

    fn send_events(&mut self) {
        if !self.events.is_empty() {
            let empty = match self.spare.events.try_recv() {
                Ok(mut e) => {
                    e.clear();
                    e
                }
                Err(_) => Vec::with_capacity(BATCH),
            };
            let batch = std::mem::replace(&mut self.events, empty);
            self.send(Message::Events(batch));
        }
    }

    fn send_bytes(&mut self, bytes: &[u8]) {
        let mut chunk = match self.spare.bytes.try_recv() {
            Ok(mut b) => {
                b.clear();
                b
            }
            Err(_) => Vec::with_capacity(bytes.len()),
        };
        chunk.extend_from_slice(bytes);
        self.send(Message::Bytes(chunk));
    }
}

/// What a verification running beside a run gives when the run is over.
pub struct Finish {
    pub outcome: Outcome,
    /// The program sink, whose `finish` the caller calls once the program
    /// may be written.
    pub program: Option<Box<dyn Sink>>,
    /// The program's length in bytes.
    pub bytes: u64,
    /// The lines of the joined program before each tape-split part after
    /// the first (counted when [`Verification::start`] was asked to).
    pub part_lines: Vec<u64>,
}

/// A verification running beside a run of the post.
pub struct Verification {
    tee: Rc<RefCell<Tee>>,
    thread: Option<JoinHandle<Outcome>>,
}

impl Verification {
    /// Starts the verify thread for a program whose spans are in `file`;
    /// `count_lines` counts the program's lines where its parts start.
    pub fn start(file: FileId, settings: Settings, count_lines: bool) -> io::Result<Verification> {
        let (tx, rx) = sync_channel(IN_FLIGHT);
        let (bytes_back, bytes) = sync_channel(IN_FLIGHT + 2);
        let (events_back, events) = sync_channel(IN_FLIGHT + 2);
        let (give_back, spare) = (Spare { bytes: bytes_back, events: events_back }, Spare { bytes, events });
        let stop = Arc::new(AtomicBool::new(false));
        let flag = Arc::clone(&stop);
        let thread = std::thread::Builder::new()
            .name("postc-verify".into())
            .spawn(move || verify_thread(rx, give_back, file, &settings, &flag))?;
        let tee = Tee {
            tx: Some(tx),
            spare,
            events: Vec::with_capacity(BATCH),
            stop,
            parked: None,
            bytes: 0,
            count_lines,
            lines: 0,
            part_lines: Vec::new(),
        };
        Ok(Verification { tee: Rc::new(RefCell::new(tee)), thread: Some(thread) })
    }

    /// The program sink, teed to the verify thread.
    pub fn sink(&self, inner: Box<dyn Sink>) -> Box<dyn Sink> {
        Box::new(TeeSink { inner: Some(inner), tee: Rc::clone(&self.tee) })
    }

    /// The toolpath's events, teed to the verify thread.
    pub fn source<'a>(&self, inner: &'a mut dyn EventSource) -> TeeSource<'a> {
        TeeSource { inner, tee: Rc::clone(&self.tee) }
    }

    /// The run has finished: waits for the verify thread.
    pub fn finish(mut self) -> Finish {
        let (program, bytes, part_lines) = {
            let mut tee = self.tee.borrow_mut();
            tee.send_events();
            tee.tx = None;
            (tee.parked.take(), tee.bytes, std::mem::take(&mut tee.part_lines))
        };
        // While the verify thread reads what is left in the channel, the
        // program's file goes to disk; a failure to sync shows at the
        // commit, which syncs again.
        if let Some(program) = &program {
            let _ = program.settle();
        }
        let outcome = match self.thread.take().map(JoinHandle::join) {
            Some(Ok(outcome)) => outcome,
            Some(Err(panic)) => std::panic::resume_unwind(panic),
            None => unreachable!("the thread is joined once"),
        };
        Finish { outcome, program, bytes, part_lines }
    }
}

impl Drop for Verification {
    fn drop(&mut self) {
        // A failed run: the channel closes, the thread ends at once.
        self.tee.borrow_mut().tx = None;
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The program sink, whose bytes also go to the verify thread.
struct TeeSink {
    inner: Option<Box<dyn Sink>>,
    tee: Rc<RefCell<Tee>>,
}

impl Sink for TeeSink {
    fn write(&mut self, bytes: &[u8]) -> io::Result<()> {
        if let Some(inner) = self.inner.as_mut() {
            inner.write(bytes)?;
        }
        let mut tee = self.tee.borrow_mut();
        tee.bytes += bytes.len() as u64;
        if tee.count_lines {
            tee.lines += bytes.iter().filter(|&&b| b == b'\n').count() as u64;
        }
        if tee.tx.is_some() {
            tee.send_events();
            tee.send_bytes(bytes);
        }
        Ok(())
    }

    fn new_part(&mut self) -> io::Result<()> {
        // The parts are verified as one program, as if joined.
        let mut tee = self.tee.borrow_mut();
        let lines = tee.lines;
        tee.part_lines.push(lines);
        self.inner.as_mut().map_or(Ok(()), |s| s.new_part())
    }

    /// Parks the inner sink for [`Verification::finish`]; the program is
    /// not written yet.
    fn finish(mut self: Box<Self>, _tape: Option<&TapeSplitting>) -> io::Result<Finished> {
        let mut tee = self.tee.borrow_mut();
        tee.send_events();
        tee.tx = None;
        tee.parked = self.inner.take();
        Ok(Finished::Streamed)
    }

    fn written(&self, limit: usize) -> Option<Vec<u8>> {
        self.inner.as_ref()?.written(limit)
    }
}

/// The toolpath's events, each also sent to the verify thread as its
/// [`Record`] (events verify does not read are not sent).
pub struct TeeSource<'a> {
    inner: &'a mut dyn EventSource,
    tee: Rc<RefCell<Tee>>,
}

impl EventSource for TeeSource<'_> {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        let next = self.inner.next_event(diagnostics);
        let mut tee = self.tee.borrow_mut();
        if tee.tx.is_some() {
            match &next {
                Some((event, span)) => {
                    if let Some(record) = Record::of(event) {
                        tee.events.push((record, *span));
                        if tee.events.len() >= BATCH {
                            tee.send_events();
                        }
                    }
                }
                None => tee.send_events(),
            }
        }
        next
    }

    fn outline(&mut self) -> Option<postc_ir::outline::JobOutline> {
        self.inner.outline()
    }
}

/// What the verify thread has received and not yet read.
struct Demux {
    rx: Receiver<Message>,
    /// Read buffers back to the posting thread (when it has room for them).
    give_back: Spare<SyncSender<Vec<u8>>, SyncSender<Batch>>,
    bytes: VecDeque<Vec<u8>>,
    events: VecDeque<Vec<(Record, Span)>>,
    ended: bool,
    /// The post stopped writing while events went on ([`STALL`]): bytes
    /// are no longer kept.
    stalled: bool,
}

impl Demux {
    /// Receives one message; false at the end of the run.
    fn receive(&mut self) -> bool {
        if self.ended {
            return false;
        }
        match self.rx.recv() {
            Ok(Message::Bytes(_)) if self.stalled => {}
            Ok(Message::Bytes(b)) => self.bytes.push_back(b),
            Ok(Message::Events(e)) => self.events.push_back(e),
            Err(_) => self.ended = true,
        }
        !self.ended
    }
}

/// The program's bytes as the verify thread reads them.
struct Program {
    demux: Rc<RefCell<Demux>>,
    chunk: Vec<u8>,
    at: usize,
    /// Bytes received so far.
    read: u64,
}

impl Program {
    /// The next chunk the posting thread sent; `None` at the end of the
    /// program (or once the post stalled, [`STALL`]).
    fn next_chunk(&mut self) -> Option<Vec<u8>> {
        let chunk = {
            let mut demux = self.demux.borrow_mut();
            loop {
                if let Some(b) = demux.bytes.pop_front() {
                    break b;
                }
                if demux.events.len() > STALL {
                    demux.stalled = true;
                }
                if demux.stalled || !demux.receive() {
                    return None;
                }
            }
        };
        self.read += chunk.len() as u64;
        Some(chunk)
    }

    /// The next `n` bytes of the program (fewer at its end), not consumed.
    fn peek(&mut self, n: usize) -> &[u8] {
        while self.chunk.len() - self.at < n {
            let Some(next) = self.next_chunk() else { break };
            self.chunk.extend_from_slice(&next);
        }
        let end = self.chunk.len().min(self.at + n);
        &self.chunk[self.at..end]
    }
}

impl Read for Program {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let available = self.fill_buf()?;
        let n = available.len().min(buf.len());
        buf[..n].copy_from_slice(&available[..n]);
        self.consume(n);
        Ok(n)
    }
}

impl BufRead for Program {
    fn fill_buf(&mut self) -> io::Result<&[u8]> {
        while self.at >= self.chunk.len() {
            let Some(chunk) = self.next_chunk() else { return Ok(&[]) };
            let read = std::mem::replace(&mut self.chunk, chunk);
            let _ = self.demux.borrow().give_back.bytes.try_send(read);
            self.at = 0;
        }
        Ok(&self.chunk[self.at..])
    }

    fn consume(&mut self, amount: usize) {
        self.at = (self.at + amount).min(self.chunk.len());
    }
}

/// The toolpath's records as the verify thread reads them.
struct Events {
    demux: Rc<RefCell<Demux>>,
}

impl RecordSource for Events {
    fn next_batch(&mut self, batch: &mut Vec<(Record, Span)>, _diagnostics: &mut Vec<Diagnostic>) -> bool {
        let mut demux = self.demux.borrow_mut();
        loop {
            match demux.events.pop_front() {
                Some(next) if next.is_empty() => {}
                Some(next) => {
                    let read = std::mem::replace(batch, next);
                    let _ = demux.give_back.events.try_send(read);
                    return true;
                }
                None if !demux.receive() => return false,
                None => {}
            }
        }
    }
}

fn verify_thread(
    rx: Receiver<Message>,
    give_back: Spare<SyncSender<Vec<u8>>, SyncSender<Batch>>,
    file: FileId,
    settings: &Settings,
    stop: &AtomicBool,
) -> Outcome {
    let demux = Rc::new(RefCell::new(Demux {
        rx,
        give_back,
        bytes: VecDeque::new(),
        events: VecDeque::new(),
        ended: false,
        stalled: false,
    }));
    let mut program = Program { demux: Rc::clone(&demux), chunk: Vec::new(), at: 0, read: 0 };
    let head = program.peek(4096);
    let family = match postc_verify::looks_binary(head) {
        true => Some("binary data"),
        false => postc_verify::foreign_family(head),
    };
    if let Some(family) = family {
        stop.store(true, Ordering::Relaxed);
        let mut demux = demux.borrow_mut();
        while demux.receive() {
            demux.bytes.clear();
            demux.events.clear();
        }
        return Outcome::Foreign(family);
    }
    let mut events = Events { demux: Rc::clone(&demux) };
    let report = postc_verify::verify_records(&mut program, file, &mut events, settings);
    // Whatever verify left unread (nothing, as it reads both to their end).
    while demux.borrow_mut().receive() {}
    if demux.borrow().stalled {
        return Outcome::Stalled { bytes: program.read, events: STALL * BATCH };
    }
    Outcome::Verified { report }
}
