//! Comments a post keeps: the file's head and the comment lines directly
//! before each `Sub` and `Function`, so that a converted post says what
//! its source said (`postc_ir::Comment`).
//!
//! A comment line belongs to a Sub when it and every line after it up to
//! the Sub's header are whole-line comments with no blank line between.
//! The head is the first such run of lines at the top of the file, when a
//! blank line or a statement follows it. Keyword comments (`' #Cycle ...`)
//! are the Subs' signatures, not their documentation, and a converted
//! post's header note ([`postc_ir::post::CONVERSION_NOTE`]) is left out.

use crate::ast::{Item, Program};
use crate::lexer::Comment;

/// Fills [`Program::doc`] and each procedure's `doc` from the comments.
pub fn attach(program: &mut Program, comments: &[Comment], text: &str) {
    let file = program.file;
    let plain: Vec<&Comment> =
        comments.iter().filter(|c| c.whole_line && crate::keywords::read(c, file).is_none()).collect();
    let blank_between = |from: usize, to: usize| text.get(from..to).is_some_and(|t| t.matches('\n').count() > 1);
    // The run of comments that ends right before `at` (nothing but one line
    // break between each and the next), after `floor`.
    let run_before = |at: usize, floor: usize| -> Vec<String> {
        let mut lines = Vec::new();
        let mut next = at;
        for c in plain.iter().rev().filter(|c| c.span.end <= at && c.span.start >= floor) {
            if c.span.end > next || blank_between(c.span.end, next) || has_code(text, c.span.end, next) {
                break;
            }
            lines.push(c.text.clone());
            next = c.span.start;
        }
        lines.reverse();
        lines
    };
    let mut floor = 0;
    let mut first = true;
    for item in &mut program.items {
        let (start, end) = match item {
            Item::Stmt(s) => (s.span.start, s.span.end),
            Item::Proc(p) => (p.header.start, p.end.map_or(p.header.end, |e| e.end)),
        };
        if first {
            first = false;
            // The head: the first run of comments, unless it is a Sub's.
            let head_end =
                plain.iter().take_while(|c| c.span.end <= start).fold(None, |run: Option<usize>, c| match run {
                    None => Some(c.span.end),
                    Some(e) if !blank_between(e, c.span.start) => Some(c.span.end),
                    Some(e) => Some(e),
                });
            if let Some(e) = head_end
                && (blank_between(e, start) || matches!(item, Item::Stmt(_)))
            {
                program.doc = run_before(e, 0).into_iter().filter(|l| !postc_ir::post::is_conversion_note(l)).collect();
                floor = e;
            }
        }
        if let Item::Proc(p) = item {
            p.doc = run_before(start, floor);
        }
        floor = end;
    }
}

/// Whether anything but blanks, line breaks and comments stands between
/// two offsets (a comment's text is skipped with its line).
fn has_code(text: &str, from: usize, to: usize) -> bool {
    text.get(from..to).is_some_and(|t| t.lines().any(|l| !l.trim().is_empty()))
}
