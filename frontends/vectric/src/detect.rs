//! Dialect detection: whether a file's bytes look like a Vectric post when
//! its extension says nothing.
//!
//! A Vectric post has `begin SECTION` lines naming known sections, and at
//! least one more sign: a `POST_NAME =` statement, a `VAR NAME = [` line or
//! a quoted output line. Only the first 64 KiB are looked at.

use postc_ir::Section;

use crate::decode::decode;

const LOOK_AT: usize = 64 * 1024;

/// Whether the bytes look like a Vectric post.
pub fn looks_like_vectric(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(LOOK_AT)];
    let (text, _) = decode(head);
    let (mut sections, mut others) = (0usize, 0usize);
    for line in text.lines() {
        let line = line.trim_start_matches(['\u{feff}', ' ', '\t']);
        let mut words = line.split_whitespace();
        let first = words.next().unwrap_or("");
        if first.eq_ignore_ascii_case("begin") {
            if words.next().is_some_and(|name| Section::from_name(name).is_some()) {
                sections += 1;
            }
        } else if first.eq_ignore_ascii_case("var") {
            let rest: String = line.chars().skip(3).filter(|c| !c.is_whitespace()).collect();
            if rest.contains("=[") {
                others += 1;
            }
        } else if line.get(..9).is_some_and(|head| head.eq_ignore_ascii_case("POST_NAME")) {
            if line.get(9..).is_some_and(|rest| rest.trim_start().starts_with('=')) {
                others += 1;
            }
        } else if line.starts_with('"') && line.trim_end().ends_with('"') {
            others += 1;
        }
    }
    sections > 0 && others > 0
}
