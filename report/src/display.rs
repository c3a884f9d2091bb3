//! Source lines as a diagnostic shows them (docs/diagnostics.md, "How
//! diagnostics are shown"): a line longer than [`MAX_LINE_CHARS`] is cut
//! around the places the labels point at, with `…` where text was left
//! out, and control characters are escaped, so that a file of any bytes
//! renders as a few readable lines and never writes raw escape sequences
//! to the terminal.
//!
//! Escapes: C0 control characters (but tab and the line ending) and DEL
//! are shown as their Unicode control pictures (`␛` for ESC, `␇` for BEL,
//! `␀` for NUL: one column each, so carets stay under the right character);
//! C1 controls and the bidirectional-override and isolate characters, as
//! `\u{..}`.

use std::borrow::Cow;
use std::ops::Range;

/// The longest source line shown whole, in characters.
pub const MAX_LINE_CHARS: usize = 160;

/// Characters kept on each side of a place a label points at, in a line cut.
pub const CONTEXT_CHARS: usize = 40;

/// Lines around a label's first and last line that codespan-reporting may
/// show (its context lines and a single line between two labels).
const NEAR_LINES: usize = 5;

/// How a character is shown, when not as itself.
fn escape(c: char) -> Option<Cow<'static, str>> {
    match c {
        '\t' | '\n' => None,
        '\u{0}'..='\u{1f}' => char::from_u32(0x2400 + c as u32).map(|p| Cow::Owned(p.to_string())),
        '\u{7f}' => Some(Cow::Borrowed("\u{2421}")),
        '\u{80}'..='\u{9f}' | '\u{200e}' | '\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' => {
            Some(Cow::Owned(format!("\\u{{{:x}}}", c as u32)))
        }
        _ => None,
    }
}

/// Text (a message, a note) with its control characters escaped as in
/// source lines; tabs and line breaks kept.
pub fn escape_text(text: &str) -> Cow<'_, str> {
    if !text.chars().any(|c| escape(c).is_some()) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        match escape(c) {
            Some(e) => out.push_str(&e),
            None => out.push(c),
        }
    }
    Cow::Owned(out)
}

/// A stretch of the source and the display text that stands for it.
#[derive(Clone, Debug)]
struct Piece {
    orig: Range<usize>,
    shown: Range<usize>,
    /// The shown text is the source text, byte for byte.
    verbatim: bool,
}

/// Lines `first..` of a file as shown for one diagnostic.
#[derive(Debug)]
pub struct Shown {
    /// The 0-based line of the file the text starts at.
    pub first: usize,
    pub text: String,
    /// Byte offsets in `text` of its lines' starts.
    pub line_starts: Vec<usize>,
    pieces: Vec<Piece>,
}

/// Which way an offset that falls in text left out or escaped goes.
#[derive(Clone, Copy)]
pub enum Side {
    Start,
    End,
}

impl Shown {
    /// The shown offset of a source offset.
    pub fn to_shown(&self, offset: usize, side: Side) -> usize {
        let i = self.pieces.partition_point(|p| p.orig.end <= offset);
        let Some(p) = self.pieces.get(i) else { return self.text.len() };
        if offset < p.orig.start {
            return p.shown.start;
        }
        match (p.verbatim, side) {
            (true, _) => p.shown.start + (offset - p.orig.start),
            (false, Side::Start) => p.shown.start,
            (false, Side::End) if offset == p.orig.start => p.shown.start,
            (false, Side::End) => p.shown.end,
        }
    }

    /// The source offset of a shown offset.
    pub fn to_source(&self, shown: usize) -> usize {
        let i = self.pieces.partition_point(|p| p.shown.end <= shown);
        match self.pieces.get(i) {
            Some(p) if p.verbatim => p.orig.start + (shown - p.shown.start).min(p.orig.len()),
            Some(p) => p.orig.start,
            None => self.pieces.last().map_or(0, |p| p.orig.end),
        }
    }

    /// The 0-based line of the file a shown offset is on.
    pub fn line_index(&self, shown: usize) -> usize {
        self.first + self.line_starts.partition_point(|&s| s <= shown).saturating_sub(1)
    }

    /// The shown range of a 0-based line of the file, with its line end;
    /// empty for lines outside the shown ones.
    pub fn line_range(&self, line: usize) -> Range<usize> {
        let Some(i) = line.checked_sub(self.first) else { return 0..0 };
        match self.line_starts.get(i) {
            Some(&start) => start..self.line_starts.get(i + 1).copied().unwrap_or(self.text.len()),
            None => self.text.len()..self.text.len(),
        }
    }
}

/// The lines of a file, as `(start, end)` byte ranges with their line end.
pub trait Lines {
    fn line_of(&self, offset: usize) -> usize;
    fn range_of(&self, line: usize) -> Option<Range<usize>>;
}

/// How lines `first..=last` of `text` show for labels at `points` (source
/// offsets), or `None` when every line a label may show is short and has
/// nothing to escape (the text then shows as it is).
pub fn shown(text: &str, lines: &dyn Lines, points: &[usize]) -> Option<Shown> {
    let mut wanted: Vec<usize> = points.iter().map(|&p| lines.line_of(p.min(text.len()))).collect();
    wanted.sort_unstable();
    wanted.dedup();
    let near = |line: usize| wanted.iter().any(|&w| line + NEAR_LINES >= w && line <= w + NEAR_LINES);
    let first = wanted.first()?.saturating_sub(NEAR_LINES);
    let last = wanted.last()? + NEAR_LINES;
    let plain = |range: &Range<usize>| {
        let line = &text[range.clone()];
        line.len() <= MAX_LINE_CHARS && !content(line).chars().any(|c| escape(c).is_some())
    };
    let all_plain = (first..=last).filter(|&l| near(l)).filter_map(|l| lines.range_of(l)).all(|range| plain(&range));
    if all_plain {
        return None;
    }
    let mut shown = Shown { first, text: String::new(), line_starts: Vec::new(), pieces: Vec::new() };
    let mut skipped: Option<(usize, usize)> = None;
    for line in first..=last {
        let Some(range) = lines.range_of(line) else { break };
        if !near(line) {
            // Never shown: an empty line stands for it.
            skipped.get_or_insert((range.start, shown.text.len()));
            shown.line_starts.push(shown.text.len());
            shown.text.push('\n');
            continue;
        }
        if let Some((start, at)) = skipped.take() {
            shown.pieces.push(Piece { orig: start..range.start, shown: at..shown.text.len(), verbatim: false });
        }
        shown.line_starts.push(shown.text.len());
        let line_text = &text[range.clone()];
        let body = content(line_text);
        let body_range = range.start..range.start + body.len();
        let at: Vec<usize> =
            points.iter().copied().filter(|p| body_range.contains(p) || *p == body_range.end).collect();
        shown.push_line(text, body_range.clone(), &at);
        shown.push_verbatim(text, body_range.end..range.end);
    }
    if let Some((start, at)) = skipped.take() {
        let end = lines.range_of(last).map_or(text.len(), |r| r.end);
        shown.pieces.push(Piece { orig: start..end, shown: at..shown.text.len(), verbatim: false });
    }
    Some(shown)
}

/// A line without its line end (`\n` or `\r\n`).
fn content(line: &str) -> &str {
    let line = line.strip_suffix('\n').unwrap_or(line);
    line.strip_suffix('\r').unwrap_or(line)
}

impl Shown {
    fn push_verbatim(&mut self, text: &str, orig: Range<usize>) {
        if orig.is_empty() {
            return;
        }
        let start = self.text.len();
        self.text.push_str(&text[orig.clone()]);
        match self.pieces.last_mut() {
            Some(p) if p.verbatim && p.orig.end == orig.start && p.shown.end == start => {
                p.orig.end = orig.end;
                p.shown.end = self.text.len();
            }
            _ => self.pieces.push(Piece { orig, shown: start..self.text.len(), verbatim: true }),
        }
    }

    fn push_stand_in(&mut self, orig: Range<usize>, stand_in: &str) {
        let start = self.text.len();
        self.text.push_str(stand_in);
        self.pieces.push(Piece { orig, shown: start..self.text.len(), verbatim: false });
    }

    /// One line's text (`orig`, without its end): whole when short, else
    /// the parts around `points`, each character escaped as needed. Works
    /// in byte offsets, walking only the characters it keeps, so a line of
    /// 50 MB costs no more than a short one.
    fn push_line(&mut self, text: &str, orig: Range<usize>, points: &[usize]) {
        let line = &text[orig.clone()];
        let keep: Vec<Range<usize>> = if line.chars().nth(MAX_LINE_CHARS).is_none() {
            vec![orig.clone()]
        } else {
            let floor = |mut p: usize| {
                p = p.clamp(orig.start, orig.end);
                while !text.is_char_boundary(p) {
                    p -= 1;
                }
                p
            };
            let back = |p: usize, n: usize| {
                text[orig.start..p].char_indices().rev().nth(n - 1).map_or(orig.start, |(i, _)| orig.start + i)
            };
            let forward = |p: usize, n: usize| text[p..orig.end].char_indices().nth(n).map_or(orig.end, |(i, _)| p + i);
            let mut windows: Vec<Range<usize>> = points
                .iter()
                .map(|&p| {
                    let p = floor(p);
                    back(p, CONTEXT_CHARS)..forward(p, CONTEXT_CHARS)
                })
                .collect();
            if windows.is_empty() {
                windows.push(orig.start..forward(orig.start, 2 * CONTEXT_CHARS));
            }
            windows.sort_by_key(|w| w.start);
            let mut merged: Vec<Range<usize>> = Vec::new();
            for w in windows {
                match merged.last_mut() {
                    Some(m) if w.start <= m.end => m.end = m.end.max(w.end),
                    _ => merged.push(w),
                }
            }
            merged
        };
        let mut at = orig.start;
        for w in keep {
            if w.start > at {
                self.push_stand_in(at..w.start, "…");
            }
            for (i, c) in text[w.clone()].char_indices() {
                let o = w.start + i;
                let end = o + c.len_utf8();
                match escape(c) {
                    Some(e) => self.push_stand_in(o..end, &e),
                    None => self.push_verbatim(text, o..end),
                }
            }
            at = w.end;
        }
        if at < orig.end {
            self.push_stand_in(at..orig.end, "…");
        }
    }
}
