//! Finding an item of a post written as RON in its text, so that a
//! validation problem (`postc_ir::validate`) points at the handler,
//! variable or format that holds it: `formats[3]` is the fourth element of
//! the list after `formats:` in the outermost struct (`options` is found
//! the same way, without an index).
//!
//! The scan knows just enough RON to stay in step: strings (with escapes),
//! characters, `//` and `/* */` comments, and the nesting of `( [ {`.

/// The byte range of `field` (or of its `index`-th element) in `text`.
pub fn item(text: &str, field: &str, index: Option<usize>) -> Option<(usize, usize)> {
    let b = text.as_bytes();
    let mut i = 0;
    let mut depth = 0usize;
    // Where the field's value starts, once found.
    let mut value: Option<usize> = None;
    while i < b.len() {
        match b[i] {
            b'"' => i = skip_string(b, i),
            b'\'' => i = skip_char(b, i),
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                i += 2;
                while i + 1 < b.len() && !(b[i] == b'*' && b[i + 1] == b'/') {
                    i += 1;
                }
                i += 2;
            }
            b'(' | b'[' | b'{' => {
                depth += 1;
                i += 1;
            }
            b')' | b']' | b'}' => {
                depth = depth.saturating_sub(1);
                i += 1;
            }
            c if depth == 1 && (c.is_ascii_alphabetic() || c == b'_') => {
                let start = i;
                while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                    i += 1;
                }
                let mut j = i;
                while j < b.len() && b[j].is_ascii_whitespace() {
                    j += 1;
                }
                if &text[start..i] == field && b.get(j) == Some(&b':') {
                    value = Some(j + 1);
                    break;
                }
            }
            _ => i += 1,
        }
    }
    let mut at = skip_blank(b, value?);
    let Some(index) = index else {
        let end = text[..line_end(b, at)].trim_end().trim_end_matches(',').len();
        return Some((at, end.max(at)));
    };
    if b.get(at) != Some(&b'[') {
        return None;
    }
    at += 1;
    let mut n = 0;
    let mut depth = 0usize;
    let mut start = skip_blank(b, at);
    let mut i = at;
    while i < b.len() {
        match b[i] {
            b'"' => {
                i = skip_string(b, i);
                continue;
            }
            b'\'' => {
                i = skip_char(b, i);
                continue;
            }
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b'}' => depth = depth.saturating_sub(1),
            b']' if depth == 0 => {
                // The last element, with no comma after it.
                let end = text[..i].trim_end().len();
                return (n == index && end > start).then(|| (start, line_end(b, start).min(end)));
            }
            b']' => depth -= 1,
            b',' if depth == 0 => {
                if n == index {
                    return Some((start, line_end(b, start).min(i)));
                }
                n += 1;
                start = skip_blank(b, i + 1);
            }
            _ => {}
        }
        i += 1;
    }
    None
}

fn skip_string(b: &[u8], mut i: usize) -> usize {
    i += 1;
    while i < b.len() && b[i] != b'"' {
        i += if b[i] == b'\\' { 2 } else { 1 };
    }
    i + 1
}

fn skip_char(b: &[u8], mut i: usize) -> usize {
    i += 1;
    while i < b.len() && b[i] != b'\'' {
        i += if b[i] == b'\\' { 2 } else { 1 };
    }
    i + 1
}

fn skip_blank(b: &[u8], mut i: usize) -> usize {
    loop {
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        if b.get(i) == Some(&b'/') && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else {
            return i.min(b.len());
        }
    }
}

fn line_end(b: &[u8], i: usize) -> usize {
    b[i..].iter().position(|&c| c == b'\n').map_or(b.len(), |p| i + p)
}
