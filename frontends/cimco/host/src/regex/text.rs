//! `replace`, `split` and `search` with a regular expression, as
//! JavaScript does them: `$&`, `$1`..`$99` and `$$` in replacements; every
//! match under the `g` flag, else the first; an empty match moves on by one
//! character; `split` keeps the groups; `search` counts UTF-16 units.

use super::Regex;

/// The first match at or after `from`, moving past empty matches as
/// JavaScript's `lastIndex` does.
fn next_after(text: &str, at: usize) -> usize {
    text[at..].chars().next().map_or(text.len() + 1, |c| at + c.len_utf8())
}

/// `text.replace(re, replacement)`.
pub fn replace(re: &Regex, text: &str, replacement: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut last = 0;
    let mut pos = 0;
    while pos <= text.len() {
        let Some(caps) = re.captures_at(text, pos) else { break };
        let whole = caps.get(0).expect("group 0 is the match");
        out.push_str(&text[last..whole.start()]);
        expand(replacement, &caps, &mut out);
        last = whole.end();
        pos = if whole.is_empty() { next_after(text, whole.end()) } else { whole.end() };
        if !re.global {
            break;
        }
    }
    out.push_str(&text[last.min(text.len())..]);
    out
}

fn expand(replacement: &str, caps: &regex::Captures<'_>, out: &mut String) {
    let r = replacement.as_bytes();
    let mut i = 0;
    let mut literal_from = 0;
    while i < r.len() {
        if r[i] != b'$' || i + 1 >= r.len() {
            i += 1;
            continue;
        }
        let (taken, consumed): (Option<&str>, usize) = match r[i + 1] {
            b'$' => (Some("$"), 2),
            b'&' => (caps.get(0).map(|m| m.as_str()), 2),
            d @ b'1'..=b'9' => {
                // Two digits when that group exists, as JavaScript reads `$10`.
                let two =
                    r.get(i + 2).filter(|c| c.is_ascii_digit()).map(|c| (d - b'0') as usize * 10 + (c - b'0') as usize);
                match two.filter(|&n| n < caps.len()) {
                    Some(n) => (Some(caps.get(n).map_or("", |m| m.as_str())), 3),
                    None if ((d - b'0') as usize) < caps.len() => {
                        (Some(caps.get((d - b'0') as usize).map_or("", |m| m.as_str())), 2)
                    }
                    None => (None, 0),
                }
            }
            _ => (None, 0),
        };
        if consumed == 0 {
            i += 1;
            continue;
        }
        out.push_str(&replacement[literal_from..i]);
        out.push_str(taken.unwrap_or(""));
        i += consumed;
        literal_from = i;
    }
    out.push_str(&replacement[literal_from..]);
}

/// `text.split(re)`: the parts between matches, and each match's groups.
pub fn split(re: &Regex, text: &str) -> Vec<String> {
    if text.is_empty() {
        // JavaScript: an empty text splits into nothing when the pattern
        // matches it, else into one empty part.
        return if re.is_match(text) { Vec::new() } else { vec![String::new()] };
    }
    let mut parts = Vec::new();
    let mut last = 0;
    let mut pos = 0;
    while pos < text.len() {
        let Some(caps) = re.captures_at(text, pos) else { break };
        let whole = caps.get(0).expect("group 0 is the match");
        if whole.end() >= text.len() && whole.is_empty() {
            break;
        }
        if whole.end() == last || (whole.is_empty() && whole.start() == last) {
            pos = next_after(text, pos.max(whole.start()));
            continue;
        }
        parts.push(text[last..whole.start()].to_string());
        for group in caps.iter().skip(1) {
            parts.push(group.map_or(String::new(), |m| m.as_str().to_string()));
        }
        last = whole.end();
        pos = if whole.is_empty() { next_after(text, last) } else { last };
    }
    parts.push(text[last..].to_string());
    parts
}

/// `text.search(re)`: the UTF-16 index of the first match, or -1.
pub fn search(re: &Regex, text: &str) -> i64 {
    re.captures_at(text, 0).and_then(|c| c.get(0)).map_or(-1, |m| text[..m.start()].encode_utf16().count() as i64)
}
