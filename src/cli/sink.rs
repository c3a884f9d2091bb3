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
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_appear_only_when_finished() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("o.nc");
        let batch = Batch::default();
        let mut out = file(&target, &batch).unwrap();
        out.buf.extend_from_slice(b"G0X1\n");
        out.end_block();
        out.flush();
        assert!(!target.exists());
        let files = out.finish(None).unwrap();
        assert!(matches!(files, Finished::Files(ref f) if f == std::slice::from_ref(&target)));
        assert!(!target.exists());
        batch.commit(&[], None).unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), b"G0X1\n");
        // A dropped (failed) run leaves nothing behind.
        let other = dir.path().join("p.nc");
        let mut out = file(&other, &batch).unwrap();
        out.buf.extend_from_slice(b"G0X1\n");
        out.flush();
        drop(out);
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn tape_split_parts_are_named_at_the_end() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("t.tap");
        let tape = TapeSplitting {
            max_lines: 1,
            tolerance: 0,
            name_format: "%s_%d.tap".into(),
            start_index: 1,
            index_on_first_file: true,
        };
        let batch = Batch::default();
        let mut out = file(&target, &batch).unwrap();
        out.buf.extend_from_slice(b"A\n");
        out.end_block();
        out.new_part();
        out.buf.extend_from_slice(b"B\n");
        out.end_block();
        assert_eq!(
            std::fs::read_dir(dir.path())
                .unwrap()
                .filter_map(Result::ok)
                .filter(|e| !e.file_name().to_string_lossy().starts_with(".postc-"))
                .count(),
            0
        );
        let Finished::Files(files) = out.finish(Some(&tape)).unwrap() else { panic!("files") };
        assert_eq!(files, [dir.path().join("t_1.tap"), dir.path().join("t_2.tap")]);
        batch.commit(&[], None).unwrap();
        assert_eq!(std::fs::read(&files[1]).unwrap(), b"B\n");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
    }
}
