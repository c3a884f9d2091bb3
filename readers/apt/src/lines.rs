//! Physical lines of a CL file: reads one line at a time into a buffer the
//! caller reuses, strips LF / CRLF, keeps the byte offset of each line, and
//! refuses to hold a line longer than [`MAX_LINE`] in memory (the rest of
//! such a line is skipped, so a file without line breaks cannot exhaust
//! memory).

use std::io::{self, BufRead};

/// The longest physical line kept; longer lines are reported and skipped.
pub(crate) const MAX_LINE: usize = 1 << 20;

/// Position of the first `\n`.
#[doc(hidden)]
pub fn find_newline(hay: &[u8]) -> Option<usize> {
    find_byte(hay, b'\n')
}

/// Position of the first `needle`, eight bytes at a time.
pub(crate) fn find_byte(hay: &[u8], needle: u8) -> Option<usize> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGH: u64 = 0x8080_8080_8080_8080;
    let pattern: u64 = ONES * u64::from(needle);
    let mut chunks = hay.chunks_exact(8);
    let mut at = 0;
    for chunk in &mut chunks {
        let mut word = [0u8; 8];
        word.copy_from_slice(chunk);
        let x = u64::from_le_bytes(word) ^ pattern;
        let found = x.wrapping_sub(ONES) & !x & HIGH;
        if found != 0 {
            return Some(at + (found.trailing_zeros() / 8) as usize);
        }
        at += 8;
    }
    chunks.remainder().iter().position(|&b| b == needle).map(|i| at + i)
}

/// Where a physical line sits in the file.
#[derive(Clone, Copy, Debug, Default)]
#[doc(hidden)]
pub struct LineInfo {
    /// Byte offset of the line's first byte.
    pub start: usize,
    /// The line was longer than [`MAX_LINE`]; the buffer holds its start only.
    pub too_long: bool,
}

/// Reads physical lines from a buffered reader.
#[doc(hidden)]
pub struct Lines<R> {
    inner: R,
    offset: usize,
    eof: bool,
}

impl<R: BufRead> Lines<R> {
    pub fn new(inner: R) -> Lines<R> {
        Lines { inner, offset: 0, eof: false }
    }

    /// The underlying reader, to look at the head of the file before reading.
    pub fn inner_mut(&mut self) -> &mut R {
        &mut self.inner
    }

    /// Bytes read so far: at the end, the length of the file.
    pub fn offset(&self) -> usize {
        self.offset
    }

    /// Skips `n` bytes at the start (a UTF-8 byte-order mark).
    pub fn skip_start(&mut self, n: usize) {
        self.inner.consume(n);
        self.offset += n;
    }

    /// Reads the next line into `buf` (cleared first), without its line end.
    /// `None` at the end of the file.
    pub fn read(&mut self, buf: &mut Vec<u8>) -> io::Result<Option<LineInfo>> {
        buf.clear();
        if self.eof {
            return Ok(None);
        }
        let start = self.offset;
        let mut too_long = false;
        let mut newline = false;
        loop {
            let chunk = match self.inner.fill_buf() {
                Ok(chunk) => chunk,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            };
            if chunk.is_empty() {
                break;
            }
            let (used, found) = match find_newline(chunk) {
                Some(i) => (i + 1, true),
                None => (chunk.len(), false),
            };
            let keep = used - usize::from(found);
            let room = MAX_LINE.saturating_sub(buf.len());
            if keep > room {
                too_long = true;
            }
            buf.extend_from_slice(&chunk[..keep.min(room)]);
            self.inner.consume(used);
            self.offset += used;
            if found {
                newline = true;
                break;
            }
        }
        if self.offset == start {
            self.eof = true;
            return Ok(None);
        }
        if newline && buf.last() == Some(&b'\r') {
            buf.pop();
        }
        Ok(Some(LineInfo { start, too_long }))
    }
}
