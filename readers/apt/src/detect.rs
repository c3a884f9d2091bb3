//! Telling CL text from what is not: binary CL files, APT part programs,
//! and anything else, by looking at the head of a file.
//!
//! - **Binary**: a NUL byte in the head. Text CL never has one. The IBM
//!   APT360 CLFILE (and NCL's binary clfile) are records of 32-bit words: a
//!   record number, a word count, a record type (1000, 2000, 3000, 5000,
//!   ...) and a subtype; a head that starts like that is named as one. A
//!   UTF-16 byte-order mark is named too.
//! - **Part program**: APT source defines geometry by assignment
//!   (`PL1=PLANE/0,0,1,0`, `C1=CIRCLE/...`) and moves along it
//!   (`GO/TO,L1`, `TLLFT,GOLFT/L1,PAST,L2`, `GOTO/PT1`). CL data never has
//!   an `=` outside text and comments, and its motion records carry numbers.
//!   The head check looks for an assignment `NAME[(n)] = WORD/`; while
//!   reading, any assignment, `GO/...`, a drive word without CATIA's nested
//!   `(CIRCLE/...)`, or a GOTO/FROM naming a point is the same proof.
//! - **CL text**: the first record of the head (skipping blank lines and
//!   `$$` comments) starts with a CL or post-processor word.

use crate::words::{Major, classify, upper};

/// What the head of a file is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Content {
    /// APT CL text.
    ClText,
    /// A binary file; the text says what kind, when known.
    Binary(&'static str),
    /// An APT part program: byte range of the line that shows it.
    PartProgram(usize, usize),
    /// Neither.
    Other,
}

/// Whether a head of 32-bit words starts like an APT360 CLFILE record.
fn apt360_record(head: &[u8]) -> bool {
    let word = |i: usize, big: bool| -> Option<u32> {
        let b: [u8; 4] = head.get(i * 4..i * 4 + 4)?.try_into().ok()?;
        Some(if big { u32::from_be_bytes(b) } else { u32::from_le_bytes(b) })
    };
    [false, true].into_iter().any(|big| {
        word(0, big) == Some(1)
            && word(1, big).is_some_and(|n| (1..=1000).contains(&n))
            && word(2, big).is_some_and(|t| matches!(t, 1000 | 2000 | 3000 | 5000 | 6000 | 9000 | 14000))
    })
}

/// The head (up to 64 KiB) is binary: what kind.
pub(crate) fn binary_kind(head: &[u8]) -> Option<&'static str> {
    let head = &head[..head.len().min(1 << 16)];
    if head.starts_with(&[0xFF, 0xFE]) || head.starts_with(&[0xFE, 0xFF]) {
        return Some("UTF-16 text; postc reads CL files as ASCII or UTF-8");
    }
    if !head.contains(&0) {
        return None;
    }
    Some(if apt360_record(head) { "an APT360-style binary CLFILE of 32-bit records" } else { "it has NUL bytes" })
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic()
}

/// Whether a trimmed statement line is an APT definition: `NAME[(n)] = WORD/`.
fn is_definition(line: &[u8]) -> bool {
    let mut i = 0;
    if !line.first().copied().is_some_and(is_ident_start) {
        return false;
    }
    while i < line.len() && (line[i].is_ascii_alphanumeric() || line[i] == b'_') {
        i += 1;
    }
    if line.get(i) == Some(&b'(') {
        while i < line.len() && line[i] != b')' {
            i += 1;
        }
        i += 1;
    }
    while line.get(i) == Some(&b' ') {
        i += 1;
    }
    if line.get(i) != Some(&b'=') {
        return false;
    }
    i += 1;
    while line.get(i) == Some(&b' ') {
        i += 1;
    }
    let start = i;
    while i < line.len() && (line[i].is_ascii_alphanumeric() || line[i] == b'_') {
        i += 1;
    }
    while line.get(i) == Some(&b' ') {
        i += 1;
    }
    i > start && line.get(i) == Some(&b'/')
}

/// The head word of a statement line, upper case, in `buf`.
fn head_word<'b>(line: &[u8], buf: &'b mut [u8; 48]) -> Option<&'b str> {
    let end = line.iter().position(|&b| matches!(b, b'/' | b',' | b' ' | b'\t' | b'=' | b'(')).unwrap_or(line.len());
    upper(&line[..end], buf)
}

/// Looks at the head of a file.
pub fn sniff(head: &[u8]) -> Content {
    if let Some(kind) = binary_kind(head) {
        return Content::Binary(kind);
    }
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let mut first_word = None;
    let mut offset = 0;
    for (n, raw) in head.split(|&b| b == b'\n').enumerate() {
        let line_start = offset;
        offset += raw.len() + 1;
        if n >= 2000 {
            break;
        }
        let start = raw.iter().position(|b| !b.is_ascii_whitespace()).unwrap_or(raw.len());
        let line = raw[start..].trim_ascii_end();
        if line.is_empty() || line.starts_with(b"$$") {
            continue;
        }
        if is_definition(line) {
            return Content::PartProgram(line_start + start, line_start + start + line.len());
        }
        if first_word.is_none() {
            let mut buf = [0u8; 48];
            let word = head_word(line, &mut buf).unwrap_or_default();
            let text = ["PPRINT", "PARTNO", "INSERT", "REMARK", "OPFEATSTART", "OPFEATEND"].contains(&word);
            let second = if word == "TOOL" { Some("PATH") } else { None };
            let known = text || !matches!(classify(word, second), Major::Unknown | Major::SourceMotion);
            first_word = Some(known);
        }
    }
    match first_word {
        Some(true) => Content::ClText,
        _ => Content::Other,
    }
}
