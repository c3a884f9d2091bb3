//! `replace` and `split` with a regular expression, as JavaScript does
//! them: `$&`, `$1`..`$9` and `$$` in replacements; every match under the
//! `g` flag, else the first.

use super::{Captures, Regex};

/// `text.replace(re, replacement)`.
pub fn replace(re: &Regex, text: &str, replacement: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut pos = 0;
    let mut last = 0;
    while pos <= chars.len() {
        let Some(caps) = re.find_at(&chars, pos) else { break };
        let Some((s, e)) = caps[0] else { break };
        out.extend(&chars[last..s]);
        expand(replacement, &chars, &caps, &mut out);
        last = e;
        pos = if e == s { e + 1 } else { e };
        if e == s && s < chars.len() {
            out.push(chars[s]);
            last = s + 1;
        }
        if !re.global {
            break;
        }
    }
    if last <= chars.len() {
        out.extend(&chars[last..]);
    }
    out
}

fn expand(replacement: &str, text: &[char], caps: &Captures, out: &mut String) {
    let r: Vec<char> = replacement.chars().collect();
    let mut i = 0;
    while i < r.len() {
        if r[i] == '$' && i + 1 < r.len() {
            let n = r[i + 1];
            if n == '$' {
                out.push('$');
                i += 2;
                continue;
            }
            if n == '&' {
                if let Some((s, e)) = caps[0] {
                    out.extend(&text[s..e]);
                }
                i += 2;
                continue;
            }
            if let Some(d) = n.to_digit(10).filter(|d| *d >= 1 && (*d as usize) < caps.len()) {
                if let Some((s, e)) = caps[d as usize] {
                    out.extend(&text[s..e]);
                }
                i += 2;
                continue;
            }
        }
        out.push(r[i]);
        i += 1;
    }
}

/// `text.split(re)`.
pub fn split(re: &Regex, text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut parts = Vec::new();
    let mut last = 0;
    let mut pos = 0;
    while pos < chars.len() {
        let Some(caps) = re.find_at(&chars, pos) else { break };
        let Some((s, e)) = caps[0] else { break };
        if e == s {
            if s >= chars.len() {
                break;
            }
            if s == last {
                pos = s + 1;
                continue;
            }
        }
        parts.push(chars[last..s].iter().collect());
        last = e;
        pos = if e == s { e + 1 } else { e };
    }
    parts.push(chars[last..].iter().collect());
    parts
}

