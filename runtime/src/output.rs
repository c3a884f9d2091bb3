//! Output sinks: where blocks go, whole or not at all.
//!
//! Handlers append bytes to [`Output::buf`]; every 64 KiB the buffer moves
//! to the destination. A file destination writes into temporary files beside
//! the target and renames them only when the program is complete, so a
//! failed run never leaves a half-written program; tape splitting opens one
//! temporary file per part and names them at the end. Standard output is
//! held back (up to 64 MiB) so that an error in the first part of a job
//! writes nothing at all.

use std::fs::File;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use postc_ir::post::TapeSplitting;

const FLUSH_AT: usize = 1 << 16;
const HOLD_STDOUT: usize = 64 << 20;

/// Where the program goes.
pub enum Destination {
    /// Parts kept in memory (tests, `convert`).
    Memory(Vec<Vec<u8>>),
    /// Standard output.
    Stdout { held: Vec<u8>, streaming: bool },
    /// Counted and dropped (benchmarks).
    Discard,
    /// A file, or several parts beside it under tape splitting.
    Files(FileParts),
}

/// Temporary part files beside the target.
pub struct FileParts {
    target: PathBuf,
    parts: Vec<tempfile::NamedTempFile>,
}

/// The output of one run.
pub struct Output {
    /// Bytes of the current part not yet handed to the destination.
    pub buf: Vec<u8>,
    dest: Destination,
    blocks_in_part: u64,
    blocks: u64,
    bytes: u64,
    error: Option<io::Error>,
}

impl Output {
    pub fn new(dest: Destination) -> Output {
        Output { buf: Vec::with_capacity(FLUSH_AT * 2), dest, blocks_in_part: 0, blocks: 0, bytes: 0, error: None }
    }

    /// Parts in memory.
    pub fn memory() -> Output {
        Output::new(Destination::Memory(vec![Vec::new()]))
    }

    /// Standard output, held back until the run ends or 64 MiB accumulate.
    pub fn stdout() -> Output {
        Output::new(Destination::Stdout { held: Vec::new(), streaming: false })
    }

    /// Counts and drops everything.
    pub fn discard() -> Output {
        Output::new(Destination::Discard)
    }

    /// A file written through temporary files in its folder.
    pub fn file(target: &Path) -> io::Result<Output> {
        let mut parts = FileParts { target: target.to_path_buf(), parts: Vec::new() };
        parts.open_part()?;
        Ok(Output::new(Destination::Files(parts)))
    }

    /// Blocks written to the current part.
    pub fn blocks_in_part(&self) -> u64 {
        self.blocks_in_part
    }

    /// Blocks written in all.
    pub fn blocks(&self) -> u64 {
        self.blocks
    }

    /// Bytes written in all.
    pub fn bytes(&self) -> u64 {
        self.bytes + self.buf.len() as u64
    }

    /// Marks the end of a block (after its line ending).
    #[inline]
    pub fn end_block(&mut self) {
        self.blocks_in_part += 1;
        self.blocks += 1;
        if self.buf.len() >= FLUSH_AT {
            self.flush();
        }
    }

    /// Hands buffered bytes to the destination.
    pub fn flush(&mut self) {
        if self.buf.is_empty() {
            return;
        }
        self.bytes += self.buf.len() as u64;
        let result = match &mut self.dest {
            Destination::Memory(parts) => {
                if let Some(p) = parts.last_mut() {
                    p.extend_from_slice(&self.buf);
                }
                Ok(())
            }
            Destination::Stdout { held, streaming } => {
                if *streaming {
                    io::stdout().lock().write_all(&self.buf)
                } else {
                    held.extend_from_slice(&self.buf);
                    if held.len() >= HOLD_STDOUT {
                        *streaming = true;
                        let r = io::stdout().lock().write_all(held);
                        *held = Vec::new();
                        r
                    } else {
                        Ok(())
                    }
                }
            }
            Destination::Discard => Ok(()),
            Destination::Files(files) => files.current().write_all(&self.buf),
        };
        self.buf.clear();
        if let Err(e) = result {
            self.error.get_or_insert(e);
        }
    }

    /// Starts the next tape-split part.
    pub fn new_part(&mut self) {
        self.flush();
        self.blocks_in_part = 0;
        let result = match &mut self.dest {
            Destination::Memory(parts) => {
                parts.push(Vec::new());
                Ok(())
            }
            Destination::Files(files) => files.open_part(),
            Destination::Stdout { .. } | Destination::Discard => Ok(()),
        };
        if let Err(e) = result {
            self.error.get_or_insert(e);
        }
    }

    /// Completes the run: writes what is held and gives the files their
    /// names. Returns the paths written (empty for other destinations) or
    /// the memory parts.
    pub fn finish(mut self, tape: Option<&TapeSplitting>) -> io::Result<Finished> {
        self.flush();
        if let Some(e) = self.error.take() {
            return Err(e);
        }
        match self.dest {
            Destination::Memory(parts) => Ok(Finished::Memory(parts)),
            Destination::Stdout { held, .. } => {
                let mut out = io::stdout().lock();
                out.write_all(&held)?;
                out.flush()?;
                Ok(Finished::Streamed)
            }
            Destination::Discard => Ok(Finished::Streamed),
            Destination::Files(files) => files.persist(tape).map(Finished::Files),
        }
    }
}

/// What a finished run produced.
pub enum Finished {
    Memory(Vec<Vec<u8>>),
    Files(Vec<PathBuf>),
    Streamed,
}

impl FileParts {
    fn open_part(&mut self) -> io::Result<()> {
        let dir = match self.target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        self.parts.push(tempfile::Builder::new().prefix(".postc-").suffix(".part").tempfile_in(dir)?);
        Ok(())
    }

    fn current(&mut self) -> &mut File {
        self.parts.last_mut().expect("a part is always open").as_file_mut()
    }

    fn persist(self, tape: Option<&TapeSplitting>) -> io::Result<Vec<PathBuf>> {
        let names = part_names(&self.target, self.parts.len(), tape);
        let mut written = Vec::new();
        for (part, name) in self.parts.into_iter().zip(names) {
            part.as_file().sync_all()?;
            part.persist(&name).map_err(|e| e.error)?;
            written.push(name);
        }
        Ok(written)
    }
}

/// File names of the parts of a program: the target itself when there is
/// one part, else names from the tape-splitting format.
pub fn part_names(target: &Path, parts: usize, tape: Option<&TapeSplitting>) -> Vec<PathBuf> {
    let Some(tape) = tape.filter(|_| parts > 1) else {
        return vec![target.to_path_buf()];
    };
    let dir = target.parent().unwrap_or(Path::new(""));
    let stem = target.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    (0..parts)
        .map(|i| {
            if i == 0 && !tape.index_on_first_file {
                return target.to_path_buf();
            }
            let index = tape.start_index + i as u64 - u64::from(!tape.index_on_first_file);
            dir.join(c_format(&tape.name_format, &stem, index))
        })
        .collect()
}

/// Fills a printf-style name format: `%s` is the name, `%d` (or `%03d`) the index.
fn c_format(format: &str, name: &str, index: u64) -> String {
    let mut out = String::new();
    let mut chars = format.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '%' {
            out.push(c);
            continue;
        }
        let mut width = String::new();
        while let Some(&d) = chars.peek().filter(|d| d.is_ascii_digit()) {
            width.push(d);
            chars.next();
        }
        match chars.next() {
            Some('s') => out.push_str(name),
            Some('d') | Some('i') | Some('u') => {
                let w: usize = width.parse().unwrap_or(0);
                if width.starts_with('0') {
                    out.push_str(&format!("{index:0w$}"));
                } else {
                    out.push_str(&format!("{index:w$}"));
                }
            }
            Some('%') => out.push('%'),
            Some(other) => {
                out.push('%');
                out.push_str(&width);
                out.push(other);
            }
            None => out.push('%'),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tape(first: bool) -> TapeSplitting {
        TapeSplitting {
            max_lines: 1000,
            tolerance: 100,
            name_format: "%s_%d.tap".into(),
            start_index: 1,
            index_on_first_file: first,
        }
    }

    #[test]
    fn names_follow_the_format() {
        let t = tape(true);
        let names = part_names(Path::new("out/toolpath.tap"), 3, Some(&t));
        assert_eq!(names, ["out/toolpath_1.tap", "out/toolpath_2.tap", "out/toolpath_3.tap"].map(PathBuf::from));
        let t = tape(false);
        let names = part_names(Path::new("toolpath.tap"), 2, Some(&t));
        assert_eq!(names, ["toolpath.tap", "toolpath_1.tap"].map(PathBuf::from));
        assert_eq!(part_names(Path::new("a.tap"), 1, Some(&t)), [PathBuf::from("a.tap")]);
        assert_eq!(c_format("P%03d_%s.nc", "x", 7), "P007_x.nc");
    }

    #[test]
    fn files_appear_only_when_finished() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("o.nc");
        let mut out = Output::file(&target).unwrap();
        out.buf.extend_from_slice(b"G0X1\n");
        out.end_block();
        out.flush();
        assert!(!target.exists());
        let files = out.finish(None).unwrap();
        assert!(matches!(files, Finished::Files(ref f) if f == std::slice::from_ref(&target)));
        assert_eq!(std::fs::read(&target).unwrap(), b"G0X1\n");
        // A dropped (failed) run leaves nothing behind.
        let other = dir.path().join("p.nc");
        let mut out = Output::file(&other).unwrap();
        out.buf.extend_from_slice(b"G0X1\n");
        out.flush();
        drop(out);
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }
}
