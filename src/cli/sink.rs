//! Where the command line writes programs: the [`Sink`]s over the file
//! system and the terminal. The runtime has only memory and discard sinks;
//! these are the ones that touch the world.
//!
//! - [`FileSink`]: a program written to temporary files beside its target
//!   ([`Temp`]), one per tape-split part, handed to the command's
//!   [`Batch`] when the run completes, named from the post's format; the
//!   command renames them with its other outputs when it succeeds, and a
//!   failed run leaves nothing behind (docs/outputs.md);
//! - [`StdoutSink`]: standard output, held back (up to 64 MiB) so that an
//!   error in the first part of a job writes nothing at all.

use std::io::{self, Write};
use std::path::{Path, PathBuf};

use postc_ir::post::TapeSplitting;
use postc_runtime::Output;
use postc_runtime::output::{Finished, Sink, part_names};

use super::outputs::{Batch, Temp};

/// Standard output held back at most.
pub const HOLD_STDOUT: usize = 64 << 20;

/// A program to be written to `target` (several parts beside it under
/// tape splitting): its temporary files join `batch` when the run completes.
pub fn file(target: &Path, batch: &Batch) -> io::Result<Output> {
    Ok(Output::new(Box::new(FileSink::new(target, batch)?)))
}

/// A program written to standard output.
pub fn stdout() -> Output {
    Output::new(Box::new(StdoutSink::default()))
}

/// Temporary part files beside the target.
pub struct FileSink {
    target: PathBuf,
    parts: Vec<Temp>,
    batch: Batch,
}

impl FileSink {
    pub fn new(target: &Path, batch: &Batch) -> io::Result<FileSink> {
        let mut sink = FileSink { target: target.to_path_buf(), parts: Vec::new(), batch: batch.clone() };
        sink.open_part()?;
        Ok(sink)
    }

    fn open_part(&mut self) -> io::Result<()> {
        self.parts.push(Temp::beside(&self.target)?);
        Ok(())
    }

    fn current(&mut self) -> io::Result<&Temp> {
        self.parts.last().ok_or_else(|| io::Error::other("no part file is open"))
    }
}

impl Sink for FileSink {
    fn write(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.current()?.file()?.write_all(bytes)
    }

    fn new_part(&mut self) -> io::Result<()> {
        self.open_part()
    }

    fn finish(self: Box<Self>, tape: Option<&TapeSplitting>) -> io::Result<Finished> {
        let names = part_names(&self.target, self.parts.len(), tape);
        for (part, name) in self.parts.into_iter().zip(&names) {
            self.batch.stage(part, name.clone());
        }
        Ok(Finished::Files(names))
    }

    fn settle(&self) -> io::Result<()> {
        self.parts.iter().try_for_each(|part| part.file()?.sync_all())
    }

    fn written(&self, limit: usize) -> Option<Vec<u8>> {
        let mut all = Vec::new();
        for part in &self.parts {
            let path = part.path().ok()?;
            if all.len() as u64 + std::fs::metadata(path).ok()?.len() > limit as u64 {
                return None;
            }
            all.extend(std::fs::read(path).ok()?);
        }
        (all.len() <= limit).then_some(all)
    }
}

/// Standard output, held back until the run ends or 64 MiB accumulate.
#[derive(Default)]
pub struct StdoutSink {
    held: Vec<u8>,
    streaming: bool,
}

impl Sink for StdoutSink {
    fn write(&mut self, bytes: &[u8]) -> io::Result<()> {
        if self.streaming {
            return io::stdout().lock().write_all(bytes);
        }
        self.held.extend_from_slice(bytes);
        if self.held.len() >= HOLD_STDOUT {
            self.streaming = true;
            let r = io::stdout().lock().write_all(&self.held);
            self.held = Vec::new();
            return r;
        }
        Ok(())
    }

    fn new_part(&mut self) -> io::Result<()> {
        Ok(())
    }

    fn finish(self: Box<Self>, _tape: Option<&TapeSplitting>) -> io::Result<Finished> {
        let mut out = io::stdout().lock();
        out.write_all(&self.held)?;
        out.flush()?;
        Ok(Finished::Streamed)
    }

    fn written(&self, limit: usize) -> Option<Vec<u8>> {
        (!self.streaming && self.held.len() <= limit).then(|| self.held.clone())
    }
}
