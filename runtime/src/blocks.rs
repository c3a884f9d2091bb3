//! Text written straight into the output by the fast path (`Stmt::Emit`)
//! becoming blocks, with the rules of `Stmt::Write`: each line (ended by
//! `\n`, a `\r` before it dropped) that is not empty is one block, ended
//! by the post's line ending. When the text already has that shape, which
//! is the usual case, only the blocks are counted.

use crate::engine::Engine;

impl Engine<'_> {
    /// Turns the output written since `start` into blocks.
    pub(crate) fn blocks_since(&mut self, start: usize) {
        let start = start.min(self.out.buf.len());
        let ending: &[u8] = &self.post.options.line_ending;
        let region = &self.out.buf[start..];
        let mut lines = 0usize;
        let mut clean = !ending.is_empty() && ending.last() == Some(&b'\n');
        let mut pos = 0;
        while clean && pos < region.len() {
            match region[pos..].iter().position(|&b| b == b'\n') {
                Some(i) => {
                    let end = pos + i + 1;
                    let line = &region[pos..end];
                    let content = line.len() - if line.ends_with(b"\r\n") { 2 } else { 1 };
                    clean = content > 0 && line.ends_with(ending) && line.len() - ending.len() == content;
                    lines += 1;
                    pos = end;
                }
                None => clean = false,
            }
        }
        if !clean {
            let text = self.out.buf.split_off(start);
            lines = 0;
            for line in text.split(|&b| b == b'\n') {
                let line = line.strip_suffix(b"\r").unwrap_or(line);
                if line.is_empty() {
                    continue;
                }
                self.out.buf.extend_from_slice(line);
                self.out.buf.extend_from_slice(&self.post.options.line_ending);
                lines += 1;
            }
        }
        for _ in 0..lines {
            self.out.end_block();
            self.advance_block_number();
        }
    }
}
