//! String literal escapes: decoding the text between the quotes, and the
//! problems a lexer reports about it.

use std::ops::Range;

/// A problem with one escape sequence, as a byte range of the literal's
/// body and a message.
#[derive(Clone, Debug, PartialEq, Eq)]
#[doc(hidden)]
pub struct EscapeProblem {
    pub range: Range<usize>,
    pub message: &'static str,
}

/// Decodes the body of a string literal (the text between the quotes).
/// Bad escapes decode to the character after the backslash and are
/// reported.
#[doc(hidden)]
pub fn decode(body: &str) -> (String, Vec<EscapeProblem>) {
    decode_as(body, false)
}

/// Decodes the raw text of a piece of a template literal: escapes as in a
/// string, and a line break written in it (CR LF, CR or LF) is LF.
#[doc(hidden)]
pub fn decode_template(raw: &str) -> (String, Vec<EscapeProblem>) {
    decode_as(raw, true)
}

fn decode_as(body: &str, template: bool) -> (String, Vec<EscapeProblem>) {
    let mut out = String::with_capacity(body.len());
    let mut problems = Vec::new();
    let mut chars = body.char_indices().peekable();
    let mut pending_high: Option<u32> = None;
    while let Some((at, c)) = chars.next() {
        if c != '\\' {
            flush_surrogate(&mut out, &mut pending_high);
            if template && c == '\r' {
                if chars.peek().is_some_and(|(_, d)| *d == '\n') {
                    chars.next();
                }
                out.push('\n');
            } else {
                out.push(c);
            }
            continue;
        }
        let Some((_, e)) = chars.next() else {
            problems
                .push(EscapeProblem { range: at..at + 1, message: "a `\\` at the end of the text escapes nothing" });
            break;
        };
        if e != 'u' {
            flush_surrogate(&mut out, &mut pending_high);
        }
        let mut unit: Option<u32> = None;
        match e {
            'n' => out.push('\n'),
            't' => out.push('\t'),
            'r' => out.push('\r'),
            'b' => out.push('\u{8}'),
            'f' => out.push('\u{c}'),
            'v' => out.push('\u{b}'),
            '0' if !chars.peek().is_some_and(|(_, d)| d.is_ascii_digit()) => out.push('\0'),
            '0'..='9' => problems.push(EscapeProblem {
                range: at..at + 2,
                message: "octal escapes (`\\1`) are not allowed; write `\\x01` or `\\u0001`",
            }),
            '\n' | '\u{2028}' | '\u{2029}' => {}
            '\r' => {
                if chars.peek().is_some_and(|(_, d)| *d == '\n') {
                    chars.next();
                }
            }
            'x' => match hex_digits(&mut chars, 2) {
                Some(v) => unit = Some(v),
                None => problems.push(EscapeProblem {
                    range: at..at + 2,
                    message: "`\\x` must be followed by two hex digits, as in `\\x41`",
                }),
            },
            'u' => {
                if chars.peek().is_some_and(|(_, d)| *d == '{') {
                    problems.push(EscapeProblem {
                        range: at..at + 3,
                        message: "`\\u{...}` escapes are newer than the JavaScript posts use; write `\\u0041`",
                    });
                } else {
                    match hex_digits(&mut chars, 4) {
                        Some(v) => unit = Some(v),
                        None => problems.push(EscapeProblem {
                            range: at..at + 2,
                            message: "`\\u` must be followed by four hex digits, as in `\\u00B0`",
                        }),
                    }
                }
            }
            other => out.push(other),
        }
        if let Some(u) = unit {
            push_unit(&mut out, &mut pending_high, u);
        }
    }
    flush_surrogate(&mut out, &mut pending_high);
    (out, problems)
}

/// Reads exactly `n` hex digits.
fn hex_digits(chars: &mut std::iter::Peekable<std::str::CharIndices<'_>>, n: usize) -> Option<u32> {
    let mut value = 0u32;
    for _ in 0..n {
        let d = chars.peek().and_then(|(_, c)| c.to_digit(16))?;
        chars.next();
        value = value * 16 + d;
    }
    Some(value)
}

/// Appends a UTF-16 code unit, pairing surrogates.
fn push_unit(out: &mut String, pending_high: &mut Option<u32>, unit: u32) {
    if (0xD800..0xDC00).contains(&unit) {
        flush_surrogate(out, pending_high);
        *pending_high = Some(unit);
        return;
    }
    if (0xDC00..0xE000).contains(&unit) {
        if let Some(high) = pending_high.take() {
            let c = 0x10000 + ((high - 0xD800) << 10) + (unit - 0xDC00);
            out.push(char::from_u32(c).unwrap_or('\u{FFFD}'));
        } else {
            out.push('\u{FFFD}');
        }
        return;
    }
    flush_surrogate(out, pending_high);
    out.push(char::from_u32(unit).unwrap_or('\u{FFFD}'));
}

/// A lone high surrogate becomes U+FFFD.
fn flush_surrogate(out: &mut String, pending_high: &mut Option<u32>) {
    if pending_high.take().is_some() {
        out.push('\u{FFFD}');
    }
}

/// Writes a string as a double-quoted JavaScript literal.
#[doc(hidden)]
pub fn quote(value: &str) -> String {
    let mut out = String::with_capacity(value.len() + 2);
    out.push('"');
    for c in value.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{8}' => out.push_str("\\b"),
            '\u{c}' => out.push_str("\\f"),
            '\u{b}' => out.push_str("\\v"),
            '\0' => out.push_str("\\x00"),
            c if (c as u32) < 0x20 || c == '\u{2028}' || c == '\u{2029}' || c == '\u{7f}' => {
                out.push_str(&format!("\\u{:04X}", c as u32));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
