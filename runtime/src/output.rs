//! Output: where blocks go, whole or not at all.
//!
//! Handlers append bytes to [`Output::buf`]; every 64 KiB the buffer moves
//! to the output's [`Sink`]. The runtime never opens a file: it has two
//! sinks, [`MemorySink`] (tests, `convert`) and [`Discard`] (benchmarks),
//! and the caller brings the others (the command line's file sink writes
//! temporary files renamed only when the program is complete, one per
//! tape-split part, and its standard-output sink holds the program back so
//! that an error in the first part of a job writes nothing at all). A run
//! that fails drops its sink without [`Sink::finish`]; a sink must then
//! leave nothing behind.

use std::io;
use std::path::{Path, PathBuf};

use postc_ir::post::TapeSplitting;

const FLUSH_AT: usize = 1 << 16;

/// Where the bytes of a program go.
pub trait Sink {
    /// The next bytes of the current part.
    fn write(&mut self, bytes: &[u8]) -> io::Result<()>;

    /// Starts the next tape-split part.
    fn new_part(&mut self) -> io::Result<()>;

    /// The run completed: make the program visible (name the files, write
    /// what is held) and say what was produced. `tape` is the post's tape
    /// splitting, which names the parts.
    fn finish(self: Box<Self>, tape: Option<&TapeSplitting>) -> io::Result<Finished>;

    /// Puts what was written so far on stable storage, where the sink has
    /// any (the program's temporary files), without making it visible: a
    /// caller waiting for something else meanwhile (verification of the
    /// program) does the disk's work then, and the sync of the commit
    /// finds nothing left to write.
    fn settle(&self) -> io::Result<()> {
        Ok(())
    }

    /// The program written so far, its parts joined, when it is at most
    /// `limit` bytes long and the sink can read it back (verification's
    /// findings show their lines from it).
    fn written(&self, limit: usize) -> Option<Vec<u8>> {
        let _ = limit;
        None
    }
}

/// Parts kept in memory.
#[derive(Debug)]
pub struct MemorySink {
    parts: Vec<Vec<u8>>,
}

impl Default for MemorySink {
    fn default() -> MemorySink {
        MemorySink { parts: vec![Vec::new()] }
    }
}

impl Sink for MemorySink {
    fn write(&mut self, bytes: &[u8]) -> io::Result<()> {
        if let Some(p) = self.parts.last_mut() {
            p.extend_from_slice(bytes);
        }
        Ok(())
    }

    fn new_part(&mut self) -> io::Result<()> {
        self.parts.push(Vec::new());
        Ok(())
    }

    fn finish(self: Box<Self>, _tape: Option<&TapeSplitting>) -> io::Result<Finished> {
        Ok(Finished::Memory(self.parts))
    }

    fn written(&self, limit: usize) -> Option<Vec<u8>> {
        (self.parts.iter().map(Vec::len).sum::<usize>() <= limit).then(|| self.parts.concat())
    }
}

/// Counts (in [`Output`]) and drops everything.
#[derive(Clone, Copy, Debug, Default)]
pub struct Discard;

impl Sink for Discard {
    fn write(&mut self, _bytes: &[u8]) -> io::Result<()> {
        Ok(())
    }

    fn new_part(&mut self) -> io::Result<()> {
        Ok(())
    }

    fn finish(self: Box<Self>, _tape: Option<&TapeSplitting>) -> io::Result<Finished> {
        Ok(Finished::Streamed)
    }
}

/// The output of one run.
pub struct Output {
    /// Bytes of the current part not yet handed to the sink.
    pub buf: Vec<u8>,
    sink: Box<dyn Sink>,
    blocks_in_part: u64,
    blocks: u64,
    bytes: u64,
    error: Option<io::Error>,
    /// Text is written as Windows-1252 ([`Output::write_windows_1252`]).
    windows_1252: bool,
}

impl Output {
    pub fn new(sink: Box<dyn Sink>) -> Output {
        Output {
            buf: Vec::with_capacity(FLUSH_AT * 2),
            sink,
            blocks_in_part: 0,
            blocks: 0,
            bytes: 0,
            error: None,
            windows_1252: false,
        }
    }

    /// Parts in memory.
    pub fn memory() -> Output {
        Output::new(Box::new(MemorySink::default()))
    }

    /// Counts and drops everything.
    pub fn discard() -> Output {
        Output::new(Box::new(Discard))
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

    /// Writes the text of the lines, UTF-8 as a post's JavaScript makes
    /// it, as Windows-1252 from now on: a Fusion post's
    /// `setCodePage("ansi")` (docs/fusion.md, choice 38). A character
    /// Windows-1252 does not have is written `?`.
    pub fn write_windows_1252(&mut self) {
        self.windows_1252 = true;
    }

    /// Hands buffered bytes to the sink.
    pub fn flush(&mut self) {
        if self.buf.is_empty() {
            return;
        }
        // Whole lines only reach here, so no character is cut in two.
        if self.windows_1252 && !self.buf.is_ascii() {
            let text = String::from_utf8_lossy(&self.buf).into_owned();
            self.buf.clear();
            let mut one = [0u8; 4];
            for c in text.chars() {
                match encoding_rs::WINDOWS_1252.encode(c.encode_utf8(&mut one)) {
                    (b, _, false) if b.len() == 1 => self.buf.push(b[0]),
                    _ => self.buf.push(b'?'),
                }
            }
        }
        self.bytes += self.buf.len() as u64;
        let result = self.sink.write(&self.buf);
        self.buf.clear();
        if let Err(e) = result {
            self.error.get_or_insert(e);
        }
    }

    /// Starts the next tape-split part.
    pub fn new_part(&mut self) {
        self.flush();
        self.blocks_in_part = 0;
        if let Err(e) = self.sink.new_part() {
            self.error.get_or_insert(e);
        }
    }

    /// Completes the run: the sink writes what it holds and gives the files
    /// their names. Returns what the sink produced (the paths written, the
    /// memory parts).
    pub fn finish(mut self, tape: Option<&TapeSplitting>) -> io::Result<Finished> {
        self.flush();
        if let Some(e) = self.error.take() {
            return Err(e);
        }
        self.sink.finish(tape)
    }
}

/// What a finished run produced.
pub enum Finished {
    Memory(Vec<Vec<u8>>),
    Files(Vec<PathBuf>),
    Streamed,
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
#[doc(hidden)]
pub fn c_format(format: &str, name: &str, index: u64) -> String {
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
