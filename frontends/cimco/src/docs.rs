//! Comments a CIMCO post keeps (`postc_ir::Comment`): the file's head and
//! the `//` lines directly above a top-level statement (a function, a
//! `createVariable`), so that a converted post says what its source said.
//!
//! A comment line belongs to a statement when it and every line after it
//! up to the statement are whole-line `//` comments with no blank line
//! between. The head is the first such run at the top of the file, when a
//! blank line follows it. The notes a backend writes first (the
//! conversion note, and a section post's note) are left out.

/// The note a CIMCO section post starts with, after the conversion note;
/// the frontend does not read it back as a comment.
pub const SECTION_POST_NOTE: &str =
    " A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.";

/// The text of a whole-line `//` comment, after the `//`.
fn comment_text(line: &str) -> Option<&str> {
    line.trim_start().strip_prefix("//")
}

/// Whether a comment line is a note a backend wrote, not the source's.
fn is_note(line: &str) -> bool {
    postc_ir::post::is_conversion_note(line) || line == SECTION_POST_NOTE
}

/// The `//` lines directly above byte `start` (the start of a statement),
/// in order, each the text after `//`; `floor` is where the search stops.
pub fn before(text: &str, start: usize, floor: usize) -> Vec<String> {
    let Some(above) = text.get(floor.min(start)..start) else { return Vec::new() };
    // The statement's own line may start with blanks: step back to its start.
    let above = above.trim_end_matches([' ', '\t']);
    let mut lines: Vec<String> = Vec::new();
    let mut rest = match above.strip_suffix('\n') {
        Some(r) => r.strip_suffix('\r').unwrap_or(r),
        None => return Vec::new(),
    };
    loop {
        let (before_line, line) = match rest.rfind('\n') {
            Some(i) => (Some(&rest[..i]), &rest[i + 1..]),
            None => (None, rest),
        };
        let line = line.strip_suffix('\r').unwrap_or(line);
        match comment_text(line) {
            Some(t) if !is_note(t) => lines.push(t.to_string()),
            Some(_) => {}
            None => break,
        }
        match before_line {
            Some(b) => rest = b.strip_suffix('\r').unwrap_or(b),
            None => break,
        }
    }
    lines.reverse();
    lines
}

/// Where the text starts after the conversion notes on its first lines
/// (a converted post's), 0 when it has none.
pub fn after_notes(text: &str) -> usize {
    let mut skip = 0;
    for line in text.split_inclusive('\n') {
        match comment_text(line.trim_end_matches(['\n', '\r']).trim_start_matches('\u{feff}')) {
            Some(t) if postc_ir::post::is_conversion_note(t) => skip += line.len(),
            _ => break,
        }
    }
    skip
}

/// The file's head: the first run of `//` lines at the top of the file,
/// or a `/* ... */` block there (each line without the ` * ` that
/// decorates it), when a blank line follows it; and the byte where it
/// ends (0 when there is none).
pub fn head(text: &str) -> (Vec<String>, usize) {
    // A converted post's note line stands before the head it kept as written.
    let skip = after_notes(text);
    if skip > 0 {
        let (lines, end) = head(&text[skip..]);
        return (lines, if end > 0 { skip + end } else { 0 });
    }
    let body = text.trim_start_matches('\u{feff}');
    let bom = text.len() - body.len();
    if let Some(inner) = body.strip_prefix("/*")
        && let Some(close) = inner.find("*/")
    {
        let end = bom + 2 + close + 2;
        let after = &text[end..];
        let next_line = after.find('\n').map_or(after.len(), |i| i + 1);
        let blank_follows = after[..next_line].trim().is_empty()
            && after[next_line..].split('\n').next().is_some_and(|l| l.trim().is_empty());
        if !blank_follows {
            return (Vec::new(), 0);
        }
        let mut lines: Vec<String> = inner[..close]
            .lines()
            .map(|l| {
                let t = l.trim_start();
                match t.strip_prefix('*') {
                    Some(rest) if !rest.starts_with('/') => rest.to_string(),
                    _ => l.to_string(),
                }
            })
            .map(|l| l.trim_end().to_string())
            .collect();
        while lines.first().is_some_and(|l| l.trim().is_empty()) {
            lines.remove(0);
        }
        while lines.last().is_some_and(|l| l.trim().is_empty()) {
            lines.pop();
        }
        return (lines, end + next_line);
    }
    let mut lines = Vec::new();
    let mut end = 0;
    let mut pos = 0;
    for line in text.split_inclusive('\n') {
        let bare = line.trim_end_matches(['\n', '\r']);
        match comment_text(bare.trim_start_matches('\u{feff}')) {
            Some(t) => {
                if !is_note(t) {
                    lines.push(t.to_string());
                }
                end = pos + line.len();
            }
            None if bare.trim().is_empty() && end > 0 => return (lines, end),
            None => return (Vec::new(), 0),
        }
        pos += line.len();
    }
    (Vec::new(), 0)
}
